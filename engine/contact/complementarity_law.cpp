/// Primal-dual active set (semi-smooth Newton) with exact conditions, mortar's
/// ALGO_CONT='LAGRANGIEN' (facts: the project's research notes on mortar, Hueber and
/// Wohlmuth 2005, Popp et al. 2009): an active condition holds g = 0 exactly, an inactive one
/// has no pressure. Statuses follow the complementarity function C = p - max(0, p - c g),
/// with p = -lambda >= 0 the pressure in compression and c = COEF_CONT E / h (relative
/// coefficient): a condition is active where p - c g > 0, that is lambda + c g < 0. They are
/// updated inside Newton (the shared part calls update_statuses at its iterations).
///
/// The law holds its conditions by elimination (exact_by_elimination): on dual rows each
/// active condition removes one unknown of its slave node, so the system stays SPD and has no
/// multiplier unknown; the pressure is recovered from the node's equilibrium.
#include <algorithm>
#include <cmath>

#include "engine/contact/contact_law.hpp"

namespace lunaster::engine::contact {

namespace {

class ComplementarityLaw final : public ContactLaw {
 public:
  const char* name() const override { return "primal-dual active set"; }
  bool has_multipliers() const override { return false; }
  bool exact_by_elimination() const override { return true; }
  double coefficient(const ContactZone& zone) const override { return zone.coef_cont; }
  bool relative_coefficient() const override { return true; }
  bool status(double lambda, double g, double rho) const override { return lambda + rho * g < 0.0; }
  PointCoefficients point_coefficients(bool active, double w, double /*rho*/) const override {
    if (!active) return {};
    return {w, 0.0, w, 0.0};
  }
  double pressure(const ContactPoint&, double lambda, double, double) const override { return lambda; }

  /// C changes sign only beyond round-off: a pressure or a gap at the level of the solve's
  /// accuracy (1e-9 of the largest active pressure, 1e-9 of c h) keeps the status. An
  /// inactive point's pressure counts as zero.
  int update_statuses(std::vector<ContactPoint>& points, const StatusInputs& in,
                      const std::vector<double>& rho_of_zone) const override {
    double lambda_max = 0.0;
    for (size_t i = 0; i < points.size(); ++i)
      if (points[i].active) lambda_max = std::max(lambda_max, std::abs(in.lambda[i]));
    int changed = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      ContactPoint& p = points[i];
      if (inactive_if_unpaired(p, changed)) continue;
      const double c = rho_of_zone[p.zone], h = in.min_edge[p.zone];
      const double pressure = p.active ? -in.lambda[i] : 0.0;
      const double tol = p.active ? 1e-9 * lambda_max + 1e-9 * c * h : 1e-9 * c * h;
      const double value = pressure - c * in.gap[i];
      const bool active = p.active ? value > -tol : value > tol;
      changed += active != p.active;
      p.active = active;
    }
    return changed;
  }
};

}  // namespace

std::unique_ptr<ContactLaw> make_complementarity_law() { return std::make_unique<ComplementarityLaw>(); }

}  // namespace lunaster::engine::contact
