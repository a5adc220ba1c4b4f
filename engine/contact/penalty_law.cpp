/// Penalty law, code_aster's ALGO_CONT='PENALISATION': active iff g < 0, the force is
/// the coefficient times the penetration. On integration points the coefficient is a
/// pressure per gap (COEF_PENA_CONT, Pa/m) and LAGS_C reports rho g (its rows hold
/// lambda = rho g in the L2 sense); on nodes it is a spring per slave node (E_N, N/m)
/// and there is no LAGS_C. The multipliers never enter the displacement equations, so
/// the solved system is SPD and LAGS_C is recovered after each solve.
#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

namespace {

class PenaltyLaw final : public ContactLaw {
 public:
  explicit PenaltyLaw(bool spring_per_node) : spring_(spring_per_node) {}
  const char* name() const override { return "penalty"; }
  bool has_multipliers() const override { return !spring_; }
  double coefficient(const ContactZone& zone) const override { return zone.coef_pena; }
  bool initial_status(ContactInit init, double g, double tolerance) const override {
    // Discrete penalty: the springs act where the bodies overlap, and everywhere with
    // CONTACT_INIT='OUI' (a body held only by contact is held from the first iteration).
    if (spring_) return init == ContactInit::Yes || (init != ContactInit::No && g < 0.0);
    return ContactLaw::initial_status(init, g, tolerance);
  }
  bool status(double, double g, double) const override { return g < 0.0; }
  PointCoefficients coefficients(const ContactPoint& p, double rho) const override {
    const double w = p.wjac;
    if (spring_) return {0.0, p.active ? rho : 0.0, 0.0, 0.0};
    if (!p.active) return {0.0, 0.0, 0.0, w / rho};
    return {0.0, w * rho, w, w / rho};
  }
  double pressure(const ContactPoint& p, double, double g, double rho) const override {
    if (!spring_) return rho * g;
    return p.wjac > 0.0 ? rho * g / p.wjac : 0.0;
  }

 private:
  bool spring_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_penalty_law(bool spring_per_node) {
  return std::make_unique<PenaltyLaw>(spring_per_node);
}

}  // namespace lunaster::engine::contact
