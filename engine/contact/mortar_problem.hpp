#pragma once
/// The shared part of mortar contact (DEFI_CONT, APPARIEMENT='MORTAR'): the rows of the
/// segment-to-segment discretisation (mortar_segments.hpp: one weighted gap g~_j per slave
/// node, dual multipliers, D diagonal) times a law (contact_law.hpp). Here, once for every
/// law: pairing and re-pairing in the geometry loop, initial statuses (CONTACT_INIT), statuses
/// inside Newton, the terms of the rows, and CONT_NOEU. The law decides statuses and how an
/// active row acts:
///
/// - A law that holds its rows exactly (`exact_by_elimination`, the primal-dual active set of
///   ALGO_CONT='LAGRANGIEN'): an active row holds g~_j = 0. The driver eliminates one
///   displacement component of each active slave node by that relation (the component along
///   which n_j is largest), so the system it factorises is Q^T K Q: symmetric positive
///   definite, solved by CHOLMOD; no multiplier is an unknown. The pressure lambda_j (Pa,
///   >= 0 in compression; LAGS_C = -lambda_j) is recovered from the slave node's own
///   equilibrium, lambda_j = -n_j . r~_j / D_j with r~ the (transformed) residual K u - f at
///   the node. Statuses are updated at every Newton iteration but the first of each instant
///   (semi-smooth Newton); the law's coefficient is relative: c = COEF_CONT E / h.
/// - A penalty law ('PENALISATION', the law's beta = D_j rho on an active row): lambda_j =
///   COEF_CONT max(0, -g_j) (Pa, COEF_CONT in Pa/m); tangent COEF_CONT / D_j grad g~_j
///   grad g~_j^T on active rows; SPD, CHOLMOD. The pressure of the patch test is then
///   E / (2 COEF_CONT) low (two blocks of unit height). A row closes whenever it penetrates
///   and opens from the second iteration of an instant on.
///
/// The law sees each row as a nodal contact point (contact_point.hpp) of weight D_j, with the
/// nodal gap g_j = g~_j / D_j and LAGS_C's sign (negative in compression).
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/contact_definition.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/contact/contact_law.hpp"
#include "engine/contact/mortar_segments.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::contact {

class MortarProblem final : public ContactHook {
 public:
  MortarProblem(const ContactDefinition& definition, const Mesh& mesh, int dim, std::unique_ptr<ContactLaw> law);
  /// With the law of `definition.method` (make_contact_law).
  MortarProblem(const ContactDefinition& definition, const Mesh& mesh, int dim);

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override;
  void set_related(const std::vector<std::pair<int, int>>& node_components) override;
  void add_dofs(DofMap& dofs) override;
  void share_among_ranks(const std::vector<char>& owned_nodes) override;
  void begin_step(const Vector& u, const Log& log) override;
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override;
  const std::vector<Elimination>& eliminations() const override { return eliminations_; }
  bool newton_converged() const override;
  bool settle(const Vector& u, const Log& log) override;
  MatrixKind matrix_kind() const override {
    return law_->symmetric() ? MatrixKind::SymmetricPositiveDefinite : MatrixKind::General;
  }
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
  /// The law (its `symmetric()` decides whether the system needs an unsymmetric factorisation).
  const ContactLaw& law() const { return *law_; }

 private:
  void pair(const Vector& u, const Log* log);
  /// Makes `rows` the current pairing (statuses kept node by node) and checks them.
  void adopt(const Vector& u, MortarPairingRows pairing, const Log* log);
  /// Row i as the law sees it: a paired nodal point of weight D_j with the row's status.
  ContactPoint as_point(size_t i) const;
  /// True when every node of the contact surfaces moved by one vector since the last pairing
  /// (to round-off): the rows of a new pairing would be the same.
  bool moved_as_one(const Vector& u) const;
  /// Pressures of the exact rows from the slave nodes' equilibrium (the residual at u).
  void update_pressures(const Vector& residual);
  /// The law's statuses of the exact rows at u; returns how many changed.
  int update_statuses(const Vector& u);
  void build_eliminations(const Vector& u);

  const ContactDefinition def_;
  const Mesh& mesh_;
  const int dim_;
  MortarSegments segments_;
  std::unique_ptr<ContactLaw> law_;
  const bool exact_;                       ///< the law holds its rows by elimination
  std::vector<double> rho_;                ///< per zone, the law's coefficient (E / h applied)
  std::vector<double> h_;                  ///< per zone, smallest slave edge (m)
  DofMap dofs_;
  std::set<std::pair<int, int>> imposed_;
  std::set<std::pair<int, int>> related_;  ///< (node, component) that linear relations tie to others
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
