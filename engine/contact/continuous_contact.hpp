#pragma once
#include <algorithm>
/// Continuous (mixed, augmented Lagrangian) contact after code_aster's
/// FORMULATION='CONTINUE' (R5.03.52), frictionless.
///
/// Unknowns: LAGS_C on every slave node (mid-side nodes included),
/// interpolated with the slave shape functions. Contact points: the
/// integration points of the slave cells (integration_rules.hpp), projected
/// orthogonally on the master surface; normal n = outward master normal.
///
/// Conventions: gap g > 0 open (see linear_gap.hpp); lambda = LAGS_C is the
/// normal traction on the slave, **negative in compression** (code_aster's
/// user-visible sign: the SSNP121 answer is LAGS_C = -1e5 Pa).
/// Per point (weight w, slave Jacobian J, rho = COEF_CONT):
///  - status: active iff lambda + rho g < 0 (code_aster's lambda - rho d with d = -g);
///  - active:   r_u += w J (lambda + rho g) dg/du,  r_lambda_a += w J phi_a g,
///              K_uu += w J rho dg/du (x) dg/du,  K_u lambda_a = K_lambda_a u = w J phi_a dg/du;
///  - inactive: r_lambda_a += -(w J / rho) phi_a lambda,  K_lambda_a lambda_b += -(w J / rho) phi_a phi_b.
/// The system is symmetric indefinite. ALGO_CONT='PENALISATION'
/// (ContactMethod::ContinuousPenalty, rho = COEF_PENA_CONT): active iff g < 0,
/// r_u += w J rho g dg/du, and LAGS_C is slaved to rho g by
/// r_lambda_a += w J phi_a (g - lambda / rho) (non-symmetric system).
#include <memory>
#include <vector>

#include "engine/contact/contact_hook_base.hpp"
#include "engine/contact/linear_gap.hpp"
#include "engine/contact/master_search.hpp"

namespace lunaster::engine::contact {

/// One contact point (integration point of a slave cell) and its pairing.
struct ContinuousPoint {
  int zone = 0;
  int slave_cell = -1;
  double xi[2] = {0.0, 0.0};
  double weight = 0.0;     ///< reference weight
  int n_slave = 0;
  int slave_nodes[8] = {};
  double phi[8] = {};      ///< slave shape functions at xi (also LAGS_C interpolation)
  bool paired = false;
  int master_cell = -1;
  double xi_master[2] = {0.0, 0.0};
  double normal[3] = {0.0, 0.0, 0.0};
  double wjac = 0.0;       ///< weight * slave Jacobian (m or m^2)
  LinearGap gap;           ///< frozen-pairing gap
  bool active = false;
};

class ContinuousContact : public ContactHookBase {
 public:
  ContinuousContact(const ContactDefinition& definition, const Mesh& mesh, int dim);

  void add_dofs(DofMap& dofs) override;
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override;
  MatrixKind matrix_kind() const override;
  int n_active() const override {
    return static_cast<int>(std::count_if(points_.begin(), points_.end(), [](const auto& p) { return p.active; }));
  }
  void write_fields(const Vector& u, ResultStep& step) const override;

  const std::vector<ContinuousPoint>& points() const { return points_; }
  /// Slave nodes carrying LAGS_C (sorted).
  const std::vector<int>& slave_nodes() const { return slave_nodes_; }
  /// LAGS_C interpolated at a point.
  double multiplier(const Vector& u, const ContinuousPoint& p) const;
  /// Forces the statuses (tests).
  void set_all_active(bool active);

 protected:
  void pair(const Vector& u) override;
  void init_statuses(const Vector& u, const Log& log) override;
  int update_statuses(const Vector& u, const Log& log) override;
  void first_pairing_report(const Log& log) override;
  const std::vector<int>& geometry_nodes() const override { return geometry_nodes_; }
  bool statuses_in_newton() const override { return def_.status_loop == FixedPointOrNewton::Newton; }

 private:
  bool penalty() const { return def_.method == ContactMethod::ContinuousPenalty; }
  double rho(int zone) const;
  bool status_of(const Vector& u, const ContinuousPoint& p) const;
  void add_point(const Vector& u, const ContinuousPoint& p, LocalTangent& tangent, Vector& residual) const;

  std::vector<std::unique_ptr<MasterSurface>> masters_;  ///< one per zone
  std::vector<ContinuousPoint> points_;
  std::vector<int> slave_nodes_;
  std::vector<int> geometry_nodes_;
  std::vector<double> min_edge_;  ///< per zone, smallest slave edge (m)
};

}  // namespace lunaster::engine::contact
