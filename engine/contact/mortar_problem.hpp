#pragma once
/// Mortar contact (DEFI_CONT, APPARIEMENT='MORTAR'): one weighted-gap condition per slave
/// node with dual (biorthogonal) multipliers, enforced by a primal-dual active set inside
/// Newton (ALGO_CONT='LAGRANGIEN') or by a penalty on the weighted gaps ('PENALISATION').
/// Facts and sources: mortar_integration.hpp and the project's research notes.
/// AXIS models (ContactDefinition::axisymmetric): every overlap weight is multiplied by the
/// radius of its slave point, so D_j, M_jl and the dual basis are those of the measure r dl
/// (per radian, as the AXIS elements), and LAGS_C stays a pressure.
///
/// Rows. For slave node j, with Phi_j its dual function, N~ the slave shape functions
/// (transformed on TRIA6/QUAD8 slave cells, mortar_integration.hpp), n_j the nodal normal
/// (outward from the slave body, the average of the adjacent slave cells' normals):
///   D_j  = sum over slave cells of the integral of N~_j over the covered part,
///   M_jl = sum over slave/master overlaps of the integral of Phi_j N_l,
///   g~_j(u) = n_j . (sum_l M_jl x_l - D_j x~_j),  x = X + u, x~_j the transformed slave position,
/// frozen between two pairings, so g~_j is linear in u (g~ > 0 open). The nodal gap is
/// g_j = g~_j / D_j (m) and the nodal pressure lambda_j (Pa, >= 0 in compression; LAGS_C =
/// -lambda_j) acts on the slave as -lambda_j grad g~_j.
///
/// Lagrange ('LAGRANGIEN'): an active row holds g~_j = 0. The driver eliminates one
/// displacement component of each active slave node by that relation (the component along
/// which n_j is largest), so the system it factorises is Q^T K Q: symmetric positive definite,
/// solved by CHOLMOD; no multiplier is an unknown. lambda_j is recovered from the slave node's
/// own equilibrium, lambda_j = -n_j . r~_j / D_j with r~ the (transformed) residual K u - f
/// at the node. Statuses follow the complementarity function C_j = lambda_j - max(0,
/// lambda_j - c g_j), updated at every Newton iteration but the first of each instant
/// (semi-smooth Newton); c = COEF_CONT E / h (E the largest Young's modulus, h the
/// smallest slave edge), so that the default works in any unit system.
///
/// Penalty ('PENALISATION'): lambda_j = COEF_CONT max(0, -g_j) (Pa, COEF_CONT in Pa/m);
/// tangent COEF_CONT / D_j grad g~_j grad g~_j^T on active rows; SPD, CHOLMOD. The pressure
/// of the patch test is then E / (2 COEF_CONT) low (two blocks of unit height).
#include <memory>
#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/contact_definition.hpp"
#include "engine/mesh/mesh.hpp"
#include "engine/nonlinear/contact_hook.hpp"

namespace lunaster::engine::contact {

/// A surface cell of a zone with its nodes in the order whose normal points out of its body.
struct OrientedCell {
  int cell = -1;
  CellType type = CellType::Seg2;
  int n = 0;
  int nodes[8] = {};
};

/// One weighted-gap condition (a slave node of one zone).
struct MortarRow {
  int zone = 0;
  int node = -1;                 ///< slave node
  double d = 0.0;                ///< D_j (m in 2D, m^2 in 3D)
  double normal[3] = {0, 0, 0};  ///< n_j, outward from the slave body
  std::vector<int> eq;           ///< displacement equations of g~_j
  std::vector<double> coef;      ///< d g~_j / d u_eq (m or m^2 per m)
  double g0 = 0.0;               ///< g~_j at u = 0
  bool active = false;
  int eliminated = -1;           ///< equation eliminated by an active Lagrange row

  double weighted_gap(const Vector& u) const {
    double g = g0;
    for (size_t k = 0; k < eq.size(); ++k) g += coef[k] * u[eq[k]];
    return g;
  }
};

class MortarProblem final : public ContactHook {
 public:
  MortarProblem(const ContactDefinition& definition, const Mesh& mesh, int dim);

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override;
  void add_dofs(DofMap& dofs) override;
  void share_among_ranks(const std::vector<char>& owned_nodes) override;
  void begin_step(const Vector& u, const Log& log) override;
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override;
  const std::vector<Elimination>& eliminations() const override { return eliminations_; }
  bool newton_converged() const override;
  bool settle(const Vector& u, const Log& log) override;
  MatrixKind matrix_kind() const override { return MatrixKind::SymmetricPositiveDefinite; }
  long pattern_version() const override { return pattern_version_; }
  unsigned long long status_key() const override;
  int n_active() const override;
  void write_fields(const Vector& u, ResultStep& step) const override;
  void write_initial_fields(ResultStep& step) const override;
  ContactSnapshot snapshot() const override;
  void restore(const ContactSnapshot& state) override;

  // ---- inspection (tests, reports) ----
  const std::vector<MortarRow>& rows() const { return rows_; }
  /// Nodal pressure of each row at the last add_to_system (Pa, >= 0 in compression).
  const std::vector<double>& pressures() const { return lambda_; }
  /// Master-side coefficient M_jl of every row (node, value), from the last pairing (tests).
  const std::vector<std::vector<std::pair<int, double>>>& master_terms() const { return master_terms_; }
  int n_pairings() const { return n_pairings_; }
  /// Times the rows were integrated (a pairing, or a re-pairing checked against the last).
  int n_row_builds() const { return n_row_builds_; }
  int n_status_changes() const { return n_status_changes_; }

 private:
  bool lagrange() const { return def_.method == ContactMethod::MortarLagrange; }
  /// Builds the rows from the configuration u (statuses kept for nodes still paired).
  std::vector<MortarRow> build_rows(const Vector& u, std::vector<std::vector<std::pair<int, double>>>& masters,
                                    int& n_whole_cell) const;
  /// A shared model: D, M and the count of whole-cell dual bases of a zone, each rank having
  /// integrated its own slave cells, made whole on every rank (collective).
  static void share_overlaps(std::vector<double>& d, std::vector<std::vector<std::pair<int, double>>>& m,
                             int& n_whole_cell);
  void pair(const Vector& u, const Log* log);
  /// Makes `rows` the current pairing (statuses kept node by node) and checks them.
  void adopt(const Vector& u, std::vector<MortarRow> rows, std::vector<std::vector<std::pair<int, double>>> masters,
             int n_whole_cell, const Log* log);
  /// True when every node of the contact surfaces moved by one vector since the last pairing
  /// (to round-off): the rows of a new pairing would be the same.
  bool moved_as_one(const Vector& u) const;
  void update_pressures(const Vector& residual);
  int update_statuses(const Vector& u);
  void build_eliminations(const Vector& u);
  double complementarity(int zone) const;

  const ContactDefinition def_;
  const Mesh& mesh_;
  const int dim_;
  DofMap dofs_;
  std::set<std::pair<int, int>> imposed_;
  std::vector<double> h_;                  ///< per zone, smallest slave edge (m)
  std::vector<std::vector<OrientedCell>> slave_cells_, master_cells_;  ///< per zone, oriented outwards
  /// Mid-edge slave nodes of transformed cells: (mid node, vertex 1, vertex 2).
  std::vector<std::array<int, 3>> mid_edges_;
  std::vector<int> geometry_nodes_;        ///< nodes of the slave and master cells
  Vector u_at_pairing_;
  std::vector<MortarRow> rows_;
  std::vector<std::vector<std::pair<int, double>>> master_terms_;
  std::vector<int> row_of_node_;           ///< per mesh node, its row or -1
  std::vector<double> lambda_;             ///< per row, Pa, >= 0 in compression
  std::vector<Elimination> eliminations_;
  bool shared_ = false;                    ///< a model shared among MPI ranks (share_among_ranks)
  bool first_iteration_ = true;            ///< the next add_to_system is the first of an instant
  bool first_step_ = true;
  bool changed_in_newton_ = false;
  long pattern_version_ = 0;
  int n_pairings_ = 0, n_status_changes_ = 0, n_geom_iter_ = 0, n_row_builds_ = 0;
};

}  // namespace lunaster::engine::contact
