/// Penalty law with a pressure per gap, code_aster's ALGO_CONT='PENALISATION' on integration
/// points and DEFI_CONT's mortar 'PENALISATION': active iff g < 0, the pressure is the
/// coefficient (COEF_PENA_CONT, Pa/m) times the penetration, and LAGS_C reports rho g (its
/// rows hold lambda = rho g in the L2 sense). The multipliers never enter the displacement
/// equations, so the solved system is SPD and LAGS_C is recovered after each solve.
/// The spring law (spring_law.cpp) is its nodal sibling without LAGS_C.
#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

namespace {

class PenaltyLaw final : public ContactLaw {
 public:
  const char* name() const override { return "penalty"; }
  bool has_multipliers() const override { return true; }
  double coefficient(const ContactZone& zone) const override { return zone.coef_pena; }
  bool status(double, double g, double) const override { return g < 0.0; }
  PointCoefficients point_coefficients(bool active, double w, double rho) const override {
    if (!active) return {0.0, 0.0, 0.0, w / rho};
    return {0.0, w * rho, w, w / rho};
  }
  double pressure(const ContactPoint&, double, double g, double rho) const override { return rho * g; }
};

}  // namespace

std::unique_ptr<ContactLaw> make_penalty_law() { return std::make_unique<PenaltyLaw>(); }

}  // namespace lunaster::engine::contact
