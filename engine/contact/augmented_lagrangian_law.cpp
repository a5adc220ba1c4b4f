/// Augmented Lagrangian law, code_aster's FORMULATION='CONTINUE', ALGO_CONT='STANDARD'
/// (R5.03.52), frictionless: a point is active iff lambda + rho g < 0 (code_aster's
/// lambda - rho d with d = -g); rho = COEF_CONT. Symmetric indefinite system.
#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

namespace {

class AugmentedLagrangianLaw final : public ContactLaw {
 public:
  const char* name() const override { return "augmented Lagrangian"; }
  bool has_multipliers() const override { return true; }
  double coefficient(const ContactZone& zone) const override { return zone.coef_cont; }
  bool status(double lambda, double g, double rho) const override { return lambda + rho * g < 0.0; }
  PointCoefficients point_coefficients(bool active, double w, double rho) const override {
    if (!active) return {0.0, 0.0, 0.0, w / rho};
    return {w, w * rho, w, 0.0};
  }
  double pressure(const ContactPoint&, double lambda, double g, double rho) const override {
    return lambda + rho * g;
  }
};

}  // namespace

std::unique_ptr<ContactLaw> make_augmented_lagrangian_law() { return std::make_unique<AugmentedLagrangianLaw>(); }

}  // namespace lunaster::engine::contact
