#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

bool ContactLaw::initial_status(ContactInit init, double g, double tolerance) const {
  switch (init) {
    case ContactInit::Yes: return true;
    case ContactInit::No: return false;
    case ContactInit::Interpenetrated: return g <= tolerance;
  }
  return false;
}

int ContactLaw::update_statuses(std::vector<ContactPoint>& points, const StatusInputs& in,
                                const std::vector<double>& rho_of_zone) const {
  int changed = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    ContactPoint& p = points[i];
    const bool s = p.paired && status(in.lambda[i], in.gap[i], rho_of_zone[p.zone]);
    changed += s != p.active;
    p.active = s;
  }
  return changed;
}

std::unique_ptr<ContactLaw> make_contact_law(ContactMethod method) {
  switch (method) {
    case ContactMethod::Continuous: return make_augmented_lagrangian_law();
    case ContactMethod::ContinuousPenalty: return make_penalty_law(false);
    case ContactMethod::DiscreteLagrange: return make_active_set_law();
    case ContactMethod::DiscretePenalty: return make_penalty_law(true);
    case ContactMethod::MortarLagrange: return make_complementarity_law();
    case ContactMethod::MortarPenalty: return make_penalty_law(false);
  }
  return nullptr;
}

}  // namespace lunaster::engine::contact
