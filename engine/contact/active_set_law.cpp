/// Active-set law with exact multipliers, code_aster's discrete ALGO_CONT='CONTRAINTE'
/// (R5.03.50, algoco): an active point holds g = 0 exactly with its multiplier; an
/// inactive one has lambda = 0, its row scaled by w / c (c = COEF_CONT, conditioning
/// only). After each converged Newton every violated inactive point is added; when none
/// is, the active point with the most tensile multiplier is removed.
#include <algorithm>
#include <cmath>

#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

namespace {

class ActiveSetLaw final : public ContactLaw {
 public:
  const char* name() const override { return "active set"; }
  bool has_multipliers() const override { return true; }
  double coefficient(const ContactZone& zone) const override { return zone.coef_cont; }
  bool status(double lambda, double g, double /*rho*/) const override { return g < 0.0 || lambda < 0.0; }
  bool statuses_in_newton_allowed() const override { return false; }
  PointCoefficients point_coefficients(bool active, double w, double rho) const override {
    if (!active) return {0.0, 0.0, 0.0, w / rho};
    return {w, 0.0, w, 0.0};
  }
  double pressure(const ContactPoint&, double lambda, double, double) const override { return lambda; }

  int update_statuses(std::vector<ContactPoint>& points, const StatusInputs& in,
                      const std::vector<double>& /*rho_of_zone*/) const override {
    double lambda_max = 0.0;
    for (double l : in.lambda) lambda_max = std::max(lambda_max, std::abs(l));
    const double lambda_tol = 1e-10 * lambda_max;
    int changed = 0;
    ContactPoint* worst = nullptr;
    double worst_lambda = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
      ContactPoint& p = points[i];
      if (inactive_if_unpaired(p, changed)) continue;
      if (!p.active && in.gap[i] < -1e-8 * in.min_edge[p.zone]) p.active = true, ++changed;
      if (p.active && in.lambda[i] > lambda_tol && (!worst || in.lambda[i] > worst_lambda))
        worst = &p, worst_lambda = in.lambda[i];
    }
    if (changed == 0 && worst) worst->active = false, changed = 1;
    return changed;
  }
};

}  // namespace

std::unique_ptr<ContactLaw> make_active_set_law() { return std::make_unique<ActiveSetLaw>(); }

}  // namespace lunaster::engine::contact
