/// Spring law, code_aster's discrete ALGO_CONT='PENALISATION': a spring of stiffness E_N
/// (N/m, the zone's coefficient) on each slave node, active iff g < 0; no multiplier unknown
/// and no LAGS_C. The pressure reported is the spring force over the node's tributary
/// length/area. The penalty law (penalty_law.cpp) is its sibling with a pressure per gap.
#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

namespace {

class SpringLaw final : public ContactLaw {
 public:
  const char* name() const override { return "penalty"; }
  bool has_multipliers() const override { return false; }
  double coefficient(const ContactZone& zone) const override { return zone.coef_pena; }
  /// The springs act where the bodies overlap, and everywhere with CONTACT_INIT='OUI' (a
  /// body held only by contact is held from the first iteration).
  bool initial_status(ContactInit init, double g, double /*tolerance*/) const override {
    return init == ContactInit::Yes || (init != ContactInit::No && g < 0.0);
  }
  bool status(double, double g, double) const override { return g < 0.0; }
  PointCoefficients point_coefficients(bool active, double /*w*/, double rho) const override {
    return {0.0, active ? rho : 0.0, 0.0, 0.0};
  }
  double pressure(const ContactPoint& p, double, double g, double rho) const override {
    return p.wjac > 0.0 ? rho * g / p.wjac : 0.0;
  }
};

}  // namespace

std::unique_ptr<ContactLaw> make_spring_law() { return std::make_unique<SpringLaw>(); }

}  // namespace lunaster::engine::contact
