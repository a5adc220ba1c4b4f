#include "engine/contact/contact_law.hpp"

#include "engine/assembly/dof_map.hpp"

namespace lunaster::engine::contact {

std::vector<int> ContactLaw::multipliers(int /*dim*/) const {
  if (has_multipliers()) return {LAGS_C};
  return {};
}

PointResponse ContactLaw::evaluate(const PointKinematics& in, const PointState& /*start*/, PointState& state) const {
  const PointCoefficients c = point_coefficients(state.status != PointStatus::Open, in.weight, in.coefficient);
  PointResponse r;
  r.n_q = 1;
  r.n_z = has_multipliers() ? 1 : 0;
  const double lambda = r.n_z ? in.z[0] : 0.0, g = in.q[0];
  r.r_q[0] = c.alpha * lambda + c.beta * g;
  r.k_qq[0][0] = c.beta;
  if (r.n_z) {
    r.k_qz[0][0] = c.alpha;
    r.r_z[0] = c.sigma * g - c.kappa * lambda;
    r.k_zq[0][0] = c.sigma;
    r.k_zz[0][0] = -c.kappa;
  }
  r.status = state.status;
  return r;
}

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

std::unique_ptr<ContactLaw> make_contact_law(ContactEnforcement how) {
  switch (how) {
    case ContactEnforcement::AugmentedLagrangian: return make_augmented_lagrangian_law();
    case ContactEnforcement::ActiveSet: return make_active_set_law();
    case ContactEnforcement::Complementarity: return make_complementarity_law();
    case ContactEnforcement::Penalty: return make_penalty_law();
    case ContactEnforcement::Springs: return make_spring_law();
  }
  return nullptr;
}

}  // namespace lunaster::engine::contact
