#pragma once
#include <algorithm>
/// Discrete node-to-segment (2D) / node-to-facet (3D) contact after code_aster's
/// FORMULATION='DISCRETE' (R5.03.50), frictionless:
///  - ContactMethod::DiscreteLagrange (ALGO_CONT='CONTRAINTE'): one multiplier
///    per slave node, active set;
///  - ContactMethod::DiscretePenalty (ALGO_CONT='PENALISATION'): a spring of
///    stiffness E_N (N/m, per slave node, not weighted by area) on the violated gap.
///
/// Each slave vertex is projected on the master surface (master normal, g > 0
/// open, see linear_gap.hpp). Quadratic cells are linearised: only vertices are
/// slave nodes and masters are their vertex-only linear cells. On QUAD8 faces
/// (slave and master) each mid-side node is tied to the mean of its edge's two
/// vertices, u_m = (u_a + u_b) / 2 in every displacement component, as code_aster's
/// discrete formulation does (message CONTACT_8): a QUAD8 face then moves as the
/// QUAD4 the contact sees, and the patch test on matching HEXA20 meshes is exact.
/// Each relation is dualised by a multiplier LAGR_DX.. on the mid-side node,
/// scaled by the squared edge length; one whose three components are all imposed
/// by DDL_IMPO is left out (it would hold anyway and leave a singular system).
/// Mid-side nodes of SEG3 / TRIA6 faces stay free (a warning says so).
///
/// Lagrange multipliers are stored as LAGS_C DOFs on the slave vertices and
/// scaled as a pressure: the constraint of node i is weighted by its
/// tributary area a_i = integral of its linear shape function over the slave
/// cells, so LAGS_C reads like the continuous one (Pa, negative in compression)
/// and the node force is a_i LAGS_C. Residual/tangent per node:
///  - active:   r_u += a_i lambda_i dg_i/du, r_lambda_i += a_i g_i (exact equality);
///  - inactive: r_lambda_i += -(a_i / c) lambda_i, c = COEF_CONT of the zone (scaling only).
/// Active set (algoco, settle): inactive nodes with g < -tol are all added;
/// otherwise the active node with the most tensile multiplier is removed.
/// Penalty: active iff g < 0, r_u += E_N g dg/du, K += E_N dg/du (x) dg/du.
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "engine/contact/contact_hook_base.hpp"
#include "engine/contact/linear_gap.hpp"
#include "engine/contact/master_search.hpp"

namespace lunaster::engine::contact {

/// A mid-side node of a QUAD8 contact face tied to its edge's vertices.
struct MidSideTie {
  int mid = -1, a = -1, b = -1;  ///< nodes: mid-side, edge ends
  double scale = 0.0;            ///< squared edge length, m^2 (conditioning only)
  int lagr[3] = {-1, -1, -1};    ///< multiplier equation per component, -1 if left out
};

/// One slave node of a discrete zone and its pairing.
struct DiscreteNode {
  int zone = 0;
  int node = -1;
  double area = 0.0;      ///< tributary length/area a_i, m or m^2
  bool paired = false;
  int master_cell = -1;
  double normal[3] = {0.0, 0.0, 0.0};
  LinearGap gap;
  bool active = false;
};

class DiscreteContact : public ContactHookBase {
 public:
  DiscreteContact(const ContactDefinition& definition, const Mesh& mesh, int dim);

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override;
  void add_dofs(DofMap& dofs) override;
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override;
  MatrixKind matrix_kind() const override;
  int n_active() const override {
    return static_cast<int>(std::count_if(nodes_.begin(), nodes_.end(), [](const auto& n) { return n.active; }));
  }
  void write_fields(const Vector& u, ResultStep& step) const override;

  const std::vector<DiscreteNode>& nodes() const { return nodes_; }
  const std::vector<MidSideTie>& ties() const { return ties_; }
  /// Forces the statuses (tests).
  void set_all_active(bool active);

 protected:
  void pair(const Vector& u) override;
  void init_statuses(const Vector& u, const Log& log) override;
  int update_statuses(const Vector& u, const Log& log) override;
  void first_pairing_report(const Log& log) override;
  const std::vector<int>& geometry_nodes() const override { return geometry_nodes_; }

 private:
  bool lagrange() const { return def_.method == ContactMethod::DiscreteLagrange; }
  double multiplier(const Vector& u, const DiscreteNode& n) const;
  /// Nodal pressure (Pa, negative in compression): LAGS_C, or E_N g / a_i.
  double pressure(const Vector& u, const DiscreteNode& n) const;

  std::vector<std::unique_ptr<MasterSurface>> masters_;
  std::vector<DiscreteNode> nodes_;
  std::vector<MidSideTie> ties_;
  bool free_mid_side_ = false;  ///< a SEG3/TRIA6 contact face: mid-side nodes neither slave nor tied
  std::set<std::pair<int, int>> fixed_;  ///< (node, component) imposed by DDL_IMPO
  std::vector<int> geometry_nodes_;
  std::vector<double> min_edge_;
};

}  // namespace lunaster::engine::contact
