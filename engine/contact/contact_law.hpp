#pragma once
/// How contact conditions are enforced: a law decides the status of each contact
/// point and the coefficients of its terms; it does not know where the points come
/// from (discretisation.hpp). With lambda = sum_a phi_a LAGS_C_a the pressure at a
/// point and g its gap (g > 0 open), every law is a choice, per point, of four
/// coefficients (PointCoefficients) in
///
///   r_u      += (alpha lambda + beta g) dg/du          K_uu      += beta dg/du (x) dg/du
///                                                      K_u,lambda_b += alpha phi_b dg/du
///   r_lambda_a += phi_a (sigma g - kappa lambda)       K_lambda_a,u += sigma phi_a dg/du
///                                                      K_lambda_a,lambda_b += -kappa phi_a phi_b
///
/// | law (file)                                   | active point                      | inactive point       |
/// |----------------------------------------------|-----------------------------------|----------------------|
/// | augmented Lagrangian (CONTINUE, ALGO_CONT='STANDARD') | alpha = sigma = w, beta = w rho | kappa = w / rho |
/// | active set (CONTRAINTE)                      | alpha = sigma = w, beta = 0        | kappa = w / c (scaling) |
/// | penalty (PENALISATION, penalty_law.cpp)      | beta = w rho; sigma = w, kappa = w / rho (LAGS_C reports rho g) | kappa = w / rho |
/// | springs (discrete PENALISATION, spring_law.cpp) | beta = E_N (a spring per slave node) | nothing       |
/// | primal-dual active set (mortar LAGRANGIEN)   | alpha = sigma = w: g = 0 exactly   | nothing              |
///
/// w is the point's weight (contact_point.hpp). When no point has alpha != 0 the
/// multipliers do not enter the displacement equations: the shared part then
/// condenses them out of the linear solve (the system is SPD) and recovers them from
/// their own rows, (sum kappa phi phi^T) LAGS_C = sum sigma g phi.
///
/// A law may hold its active conditions exactly without any multiplier unknown
/// (`exact_by_elimination`): on a dual discretisation (mortar_segments.hpp) each condition is
/// its slave node's own, so the shared part for such rows (mortar_problem.hpp) eliminates
/// one unknown of that node per active row and recovers the pressure from the node's
/// equilibrium afterwards. The penalty law works on those rows too (its beta terms).
#include <memory>
#include <vector>

#include "engine/contact/contact_definition.hpp"
#include "engine/contact/contact_point.hpp"
#include "engine/contact/point_law.hpp"

namespace lunaster::engine::contact {

struct PointCoefficients {
  double alpha = 0.0, beta = 0.0, sigma = 0.0, kappa = 0.0;
};

/// What a law reads when it updates statuses (one entry per point, or per zone).
struct StatusInputs {
  const std::vector<double>& lambda;    ///< pressure at each point (Pa)
  const std::vector<double>& gap;       ///< gap at each point (m)
  const std::vector<double>& min_edge;  ///< smallest slave edge of each zone (m)
};

/// A frictionless law (one condition per point, at most one multiplier, LAGS_C) as the shared
/// parts (contact_problem.hpp, mortar_problem.hpp) drive it: its statuses set by their loops
/// (`update_statuses`), its terms the four coefficients above. As a PointLaw (point_law.hpp) it
/// answers from the same coefficients, with the status held in the point's state: r_q = alpha
/// lambda + beta g, r_z = sigma g - kappa lambda; symmetric.
class ContactLaw : public PointLaw {
 public:
  /// True: the slave nodes carry LAGS_C unknowns.
  virtual bool has_multipliers() const = 0;
  /// LAGS_C, or none.
  std::vector<int> multipliers(int dim) const override;
  /// The point's coefficients with its status (Open: inactive), as above.
  PointResponse evaluate(const PointKinematics& in, const PointState& start, PointState& state) const override;
  /// True: an active condition holds g = 0 exactly by eliminating an unknown of its slave
  /// node (dual rows only, mortar_problem.hpp); no LAGS_C unknown.
  virtual bool exact_by_elimination() const { return false; }
  /// The zone's coefficient the law works with (penalty, augmentation or scaling); > 0.
  virtual double coefficient(const ContactZone& zone) const = 0;
  /// True: `coefficient` is dimensionless, to be multiplied by E / h (the model's largest
  /// Young's modulus over the zone's smallest slave edge), so that its default works in any
  /// unit system.
  virtual bool relative_coefficient() const { return false; }
  /// Status of the first pairing: CONTACT_INIT, given the gap at the start.
  virtual bool initial_status(ContactInit init, double g, double tolerance) const;
  /// Status of one paired point from its pressure and gap (fixed point, Newton statuses, CONT_NOEU).
  virtual bool status(double lambda, double g, double rho) const = 0;
  /// Updates the statuses of every point after a converged Newton; returns how many changed.
  /// Default: `status` point by point (unpaired points inactive).
  virtual int update_statuses(std::vector<ContactPoint>& points, const StatusInputs& in,
                              const std::vector<double>& rho_of_zone) const;
  /// True when statuses may be updated inside Newton (ALGO_RESO_CONT='NEWTON').
  virtual bool statuses_in_newton_allowed() const { return true; }
  /// Coefficients of a paired point with its current status.
  PointCoefficients coefficients(const ContactPoint& p, double rho) const {
    return point_coefficients(p.active, p.wjac, rho);
  }
  /// Coefficients of a paired point of weight w (wjac) with the status `active`.
  virtual PointCoefficients point_coefficients(bool active, double w, double rho) const = 0;
  /// Contact pressure of an active point (Pa, negative in compression).
  virtual double pressure(const ContactPoint& p, double lambda, double g, double rho) const = 0;

 protected:
  /// An unpaired point is inactive: sets it so, counting a change in `changed`; true when
  /// the point is unpaired (nothing more to decide).
  static bool inactive_if_unpaired(ContactPoint& p, int& changed) {
    if (p.paired) return false;
    changed += p.active;
    p.active = false;
    return true;
  }
};

std::unique_ptr<ContactLaw> make_augmented_lagrangian_law();
std::unique_ptr<ContactLaw> make_active_set_law();
/// Primal-dual active set inside Newton, with exact conditions held by elimination (mortar's
/// ALGO_CONT='LAGRANGIEN').
std::unique_ptr<ContactLaw> make_complementarity_law();
/// Penalty with a pressure per gap (COEF_PENA_CONT, Pa/m); LAGS_C reports rho g.
std::unique_ptr<ContactLaw> make_penalty_law();
/// Penalty with a spring per slave node (discrete E_N, N/m); no LAGS_C.
std::unique_ptr<ContactLaw> make_spring_law();

/// The law of an enforcement (the table of contact_factory.hpp).
std::unique_ptr<ContactLaw> make_contact_law(ContactEnforcement how);

}  // namespace lunaster::engine::contact
