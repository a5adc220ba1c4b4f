#pragma once
/// The shared part of every contact method: a discretisation (where the conditions
/// live, discretisation.hpp) times a law (how they are enforced, contact_law.hpp).
/// Here, once for all methods: LAGS_C and linear-relation unknowns, pairing with the
/// master surface, initial statuses (CONTACT_INIT), the status and geometry
/// fixed-point loops, assembly of the point terms, condensation of multipliers that
/// no active point couples to the displacements, the first-pairing report, and the
/// CONT_NOEU field.
///
/// Conventions: gap g > 0 open (linear_gap.hpp); LAGS_C is the normal traction on the
/// slave, negative in compression (code_aster's user-visible sign).
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "engine/assembly/linear_relations.hpp"
#include "engine/contact/contact_common.hpp"
#include "engine/contact/contact_definition.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/contact/contact_law.hpp"
#include "engine/contact/discretisation.hpp"
#include "engine/contact/master_search.hpp"

namespace lunaster::engine::contact {

class ContactProblem final : public ContactHook {
 public:
  ContactProblem(const ContactDefinition& definition, const Mesh& mesh, int dim,
                 std::unique_ptr<Discretisation> discretisation, std::unique_ptr<ContactLaw> law);

  void set_dirichlet(const std::vector<DirichletValue>& dirichlet) override;
  std::vector<LinearRelation> take_relations(const std::function<bool(const LinearRelation&)>& which = {}) override;
  void add_dofs(DofMap& dofs) override;
  void share_among_ranks(const std::vector<char>& owned_nodes) override;
  void begin_step(const Vector& u, const Log& log) override;
  void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) override;
  bool add_residual(const Vector& u, Vector& residual) override;
  const std::vector<int>& condensed_equations() const override;
  void recover(Vector& u) override;
  bool settle(const Vector& u, const Log& log) override;
  MatrixKind matrix_kind() const override;
  /// With friction and RESI_FROT: false while the friction bounds still move (bound_change()).
  bool newton_converged() const override;
  /// The largest change of a point's contact pressure between the last two iterates, over the
  /// largest pressure (with friction; 0 before two iterates).
  double bound_change() const { return bound_change_; }
  std::vector<int> surface_equations() const override;
  std::array<bool, 3> displacement_components() const override;
  long pattern_version() const override { return pattern_version_; }
  unsigned long long status_key() const override;
  int n_active() const override;
  void write_fields(const Vector& u, ResultStep& step) const override;
  ContactSnapshot snapshot() const override;
  void restore(const ContactSnapshot& state) override;
  void commit_step(const Vector& u) override;
  /// With friction: whether every closed point slips (the tangential load beyond what friction
  /// holds), and the points whose status changed three times or more in the step, with their
  /// sequence (at most five named).
  std::vector<std::string> failure_hints() const override;

  // ---- inspection (tests, reports) ----
  const std::vector<ContactPoint>& points() const { return points_; }
  /// Nodes carrying LAGS_C (sorted); empty for a law without multipliers.
  const std::vector<int>& multiplier_nodes() const { return multiplier_nodes_; }
  const LinearRelations& relations() const { return relations_; }
  /// The law (its `symmetric()` decides whether the system needs an unsymmetric factorisation).
  const ContactLaw& law() const { return *law_; }
  /// The frictional law on top of it (coulomb_law.hpp), or null without friction.
  const PointLaw* friction() const { return friction_.get(); }
  /// Every point's state (status open/stick/slip, the law's history): at the step's start and
  /// at the last evaluation. Kept with friction only.
  const PointStates& states() const { return states_; }
  /// What a law reads at point p (point_law.hpp), the pairing frozen: q = its normal gap and
  /// its tangential relative displacement along tangent_frame(normal) (x_slave - x_master),
  /// dq_step their change since `u_start` (the step's start), z its LAGS_C, its weight and
  /// the zone's coefficient. `n_tangents`: 0 (the normal gap only) or dim - 1.
  /// `slips_out` (dim - 1 of them), when given, receives the slip gaps it built (a paired point).
  PointKinematics kinematics(const ContactPoint& p, const Vector& u, const Vector& u_start, int n_tangents,
                             LinearGap* slips_out = nullptr) const;
  /// Pressure interpolated at a point from LAGS_C (0 without multipliers).
  double multiplier(const Vector& u, const ContactPoint& p) const;
  /// Forces the statuses of the paired points (tests).
  void set_all_active(bool active);
  /// With false, multipliers are never condensed out: the tangent holds every row (tests).
  void allow_condensation(bool allow) { allow_condensation_ = allow; }
  int n_status_iterations() const { return n_status_iter_; }
  int n_pairings() const { return n_pairings_; }
  /// Points whose last pairing kept the previous one (moved_as_one).
  int n_kept() const { return n_kept_; }

 private:
  double rho(int zone) const { return rho_[zone]; }
  /// True when an active point couples LAGS_C to the displacements (no condensation).
  bool coupled() const;
  void pair(const Vector& u);
  /// Pairs points_[i] for i in `which` at the coordinates xyz (two threads when many).
  void pair_points(const std::vector<double>& xyz, const std::vector<int>& which);
  /// A shared model: the pairing of every point from the rank that paired it, and which
  /// points touch this rank's columns.
  void share_pairing();
  /// The gap of a paired point from its master cell, xi_master and normal.
  void set_gap(ContactPoint& p) const;
  /// True when the point, its master cell and the master cells around it moved by one vector
  /// since the last pairing (to round-off): its pairing then stands.
  bool moved_as_one(const ContactPoint& p, const Vector& u);
  /// The nodes of a master cell (a mesh cell of `zone`) and of the master cells sharing a node with it.
  const std::vector<int>& neighbourhood(int zone, int master_cell);
  /// Smallest and largest motion, per component, of a master cell's neighbourhood since the
  /// last pairing (once per cell and pairing).
  struct CellMotion {
    double lo[3], hi[3];
  };
  const CellMotion& cell_motion(int zone, int master_cell, const Vector& u);
  void pair_and_record(const Vector& u);
  void init_statuses(const Vector& u, const Log& log);
  int update_statuses(const Vector& u);
  void first_pairing_report(const Log& log) const;
  bool statuses_in_newton() const;
  /// The statuses at iterate u, when they are updated inside Newton (else unchanged).
  void update_statuses_in_newton(const Vector& u);
  /// The law at point p with multiplier lambda and gap g, its status the point's.
  PointResponse respond(const ContactPoint& p, double lambda, double g) const;
  /// Point p's terms of the residual: its gap gradient and its multiplier rows.
  void add_point_residual(const ContactPoint& p, const PointResponse& r, Vector& residual) const;
  /// The slip gaps of a paired point: its relative displacement along tangent_frame(normal)
  /// (dim - 1 of them; x_slave - x_master).
  void slip_gaps(const ContactPoint& p, LinearGap* slips) const;
  /// A multiplier component (LAGS_C, LAGS_F1 ...) interpolated at point p.
  double interpolate(const Vector& u, const ContactPoint& p, int component) const;
  /// With friction: point i's response at u (its state at the present iterate updated), its
  /// residual, and with `local` its tangent (LAGS_C entries zero when `condensed`).
  void frictional_point(size_t i, const Vector& u, Vector& residual, LocalTangent* local, bool condensed);
  /// With friction, what CONT_NOEU reports of point i at u: its status, the tangential force on
  /// the slave (N, global axes) and the slip of the step along its tangents.
  struct PointFriction {
    int status = 0;
    double tangential[3] = {0.0, 0.0, 0.0};
    double slip[2] = {0.0, 0.0};
  };
  PointFriction friction_at(size_t i, const Vector& u) const;
  /// DEPL's LAGS_F1[, LAGS_F2] as code_aster reports them: the traction over mu p.
  void report_semi_multipliers(const Vector& u, ResultStep& step) const;
  /// With friction: every point's residual, and with `tangent` every point's tangent.
  void add_frictional_terms(const Vector& u, std::vector<Triplet>* tangent, Vector& residual);

  const ContactDefinition def_;
  const Mesh& mesh_;
  const int dim_;
  std::unique_ptr<Discretisation> disc_;
  std::unique_ptr<ContactLaw> law_;
  std::unique_ptr<PointLaw> friction_;     ///< Coulomb on law_, or null (coulomb_law.hpp)
  std::vector<int> friction_components_;   ///< the multipliers friction_ reads, in its order
  std::vector<double> mu_, coef_t_;        ///< per zone: COULOMB, the tangential coefficient
  PointStates states_;                     ///< per point, with friction
  Vector u_start_;                         ///< u at the step's start (the slips are measured from it)
  std::vector<PointState> reported_start_; ///< the last committed step's start states (its results)
  std::vector<std::string> status_trail_;  ///< per point, its friction statuses in this step ('O', 'S', 'G')
  std::vector<double> bounds_;             ///< per point, its pressure at the last iterate (friction)
  Vector u_of_bounds_;                     ///< that iterate
  double bound_change_ = 0.0;
  /// The pressures at iterate u, and how much they moved since the last iterate.
  void track_bounds(const Vector& u);
  Vector reported_u_start_;                ///< and its start u
  std::vector<std::unique_ptr<MasterSurface>> masters_;  ///< one per zone
  std::vector<ContactPoint> points_;
  std::vector<int> multiplier_nodes_;
  std::vector<int> multiplier_eqs_;  ///< LAGS_C equation per multiplier node
  std::vector<int> geometry_nodes_;
  std::vector<double> min_edge_;     ///< per zone, smallest slave edge (m)
  std::vector<double> rho_;          ///< per zone, the law's coefficient
  LinearRelations relations_;
  std::set<std::pair<int, int>> imposed_;  ///< (node, component) under Dirichlet conditions
  DofMap dofs_;

  // Condensed multipliers: (sum kappa phi phi^T) LAGS_C = sum sigma g phi, factorised once per pairing.
  struct Recovery;
  std::shared_ptr<Recovery> recovery_;

  // A model shared among MPI ranks (share_among_ranks): the rank pairing each point, and per
  // point whether one of its nodes is this rank's.
  bool shared_ = false;
  std::vector<int> point_rank_;
  std::vector<char> touches_mine_;
  std::vector<char> owned_;  ///< per mesh node: its equations are this rank's

  Vector u_at_pairing_;  ///< u at the last pairing of the geometry loop (its residual)
  Vector u_paired_;      ///< u at the last pairing, whichever loop asked for it
  int n_kept_ = 0;       ///< points of the last pairing that kept the previous one
  std::vector<std::vector<std::vector<int>>> neighbourhoods_;  ///< per zone, per master cell
  std::vector<std::vector<CellMotion>> motions_;               ///< per zone, per master cell
  std::vector<std::vector<char>> motion_known_;                ///< motions_ computed this pairing
  bool first_step_ = true;
  /// The iterate CONTACT_INIT set the statuses at, until Newton moves away from it: statuses
  /// updated inside Newton are judged on Newton's iterates, as code_aster does after each
  /// iteration, not on the start they were just set at (empty: none pending).
  Vector u_at_init_;
  bool allow_condensation_ = true;
  long pattern_version_ = 0;
  int n_status_iter_ = 0, n_geom_iter_ = 0, n_pairings_ = 0;
};

}  // namespace lunaster::engine::contact
