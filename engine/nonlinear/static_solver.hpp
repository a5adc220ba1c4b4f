#pragma once
/// Quasi-static incremental solver: Newton iterations per instant, with an
/// optional contact algorithm plugged in through `ContactHook`.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/global_dofs.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fields/fields.hpp"
#include "engine/nonlinear/constraints.hpp"
#include "engine/nonlinear/convergence_test.hpp"
#include "engine/nonlinear/interface_policy.hpp"
#include "engine/nonlinear/linear_solve.hpp"
#include "engine/nonlinear/solve_log.hpp"
#include "engine/nonlinear/loads.hpp"
#include "engine/nonlinear/newton_options.hpp"
#include "engine/nonlinear/numbering.hpp"
#include "engine/nonlinear/reduction.hpp"
#include "engine/nonlinear/step_results.hpp"
#include "engine/nonlinear/system_matrix.hpp"
#include "engine/nonlinear/tangent_source.hpp"
#include "engine/solver/interface_solver.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

/// Runs the instants in turn from u = 0; returns one ResultStep per instant
/// (nume_ordre 0 = initial state) with DEPL. Throws SolveError on divergence,
/// naming the instant, the loop and the last residuals; steps converged before
/// the failure are available through `converged_steps()`.
class StepResults;


class StaticSolver {
 public:
  StaticSolver(const FeModel& model, const MechanicalLoads& loads, NewtonOptions options, ContactHook* contact,
               const Log& log);
  std::vector<ResultStep> run(const std::vector<double>& instants);
  const std::vector<ResultStep>& converged_steps() const { return steps_; }
  const DofMap& dofs() const { return dofs_; }
  /// Cost of the last `run` (also filled when it throws).
  const SolverStats& stats() const { return stats_; }
  /// With a model shared among the ranks: per mesh cell, the rank whose volume cell it is
  /// (-1 for other cells), for post-processing where the cells live; empty otherwise.
  const std::vector<int>& cell_ranks() const { return layout_.cell_rank(); }
  /// Runs the next `run` on this rank's part of a mesh in parts (docs/distributed-model.md,
  /// step 3): the model and the loads are on `part->mesh`, every rank of `part` calls `run`
  /// (collective). Each rank assembles its own nodes' columns, the Dirichlet conditions of its
  /// ghosts are their owners', and the results are on the part's nodes, ghosts included (they
  /// hold their owners' values). MUMPS and PETSc solve in parts; METHODE='AUTO' and the backends
  /// of one process are refused (DeckError). nullptr: the whole model again. With a hook
  /// (contact, linear relations), `numbered` is `part` with the nodes the hook was built on: the
  /// contact surfaces whole (with_whole_surfaces, step 5) and the relations' nodes
  /// (add_ghost_nodes). Its nodes beyond the part's are ghosts of the system (their
  /// displacements come from their owners at each exchange); each rank builds every contact
  /// point's and every relation's terms and keeps those of its own columns. The hook's
  /// multipliers are numbered after each rank's owned unknowns; MUMPS solves such a system,
  /// PETSc is refused there (DeckError).
  /// The tangent (and internal forces) of the next runs: a behaviour's source, borrowed; null
  /// (the default): the model's linear elastic stiffness. A constant one keeps today's path
  /// (assembled once per Dirichlet set, factorisations kept); one that is not constant is
  /// assembled again at each Newton iteration that solves.
  void set_tangent(TangentSource* tangent) { given_tangent_ = tangent; }
  /// The behaviours of the model's cells for the next runs (borrowed; built on this solver's
  /// model), or null (the default): the model's linear elasticity. When every behaviour is
  /// linear nothing changes (the elastic tangent, assembled once per Dirichlet set); otherwise
  /// each run integrates them (make_behaviour_tangent), commits their states when a step
  /// converges, restores them when it is subdivided, and its results carry them. A nonlinear
  /// behaviour on a shared model or a mesh in parts is refused (DeckError, SharedBehaviour).
  void set_behaviours(const CellBehaviours* behaviours) { behaviours_ = behaviours; }
  void set_part(const MeshPart* part, const MeshPart* numbered = nullptr) {
    part_ = part;
    hook_part_ = numbered;
  }

 private:
  /// Newton for one instant: what its iterations and contact passes share.
  struct Instant {
    double t = 0.0;
    Constraints cons;      ///< the Dirichlet conditions at t
    Vector f_ext;          ///< external forces at t
    int owned_free = 0;    ///< free unknowns this rank answers for in norms
    int total_newton = 0;  ///< Newton iterations over the contact passes
    double last_converged_maxi = -1.0;  ///< absolute residual the previous pass converged with
    ResidualNorms norms;   ///< the last iteration's
    /// The residual after a solve, when the previous iteration could give it (apply_increment).
    Vector carried_residual;
  };
  /// The terms of one iteration's system beyond K_ff: the contact triplets, the hook's
  /// condensed equations and eliminations, and the equations eliminated.
  struct SystemTerms {
    const std::vector<Triplet>* contact = nullptr;
    const std::vector<int>* condensed = nullptr;
    const std::vector<Elimination>* eliminated = nullptr;
    std::vector<int> eliminated_eqs;
  };
  /// The run's numbering: the DOF map (and in parts the hook's nodes and multipliers); refuses
  /// what a mesh in parts does not do (DeckError with a typed Failure). `node_halo`: in parts,
  /// the part's node exchanges.
  void number_unknowns(std::optional<NodeHalo>& node_halo);
  /// The instants in turn from u = 0, subdivided on failure (TimeStepper); the steps' results.
  std::vector<ResultStep> step_through(const std::vector<double>& instants);
  /// Newton (+ contact loops) at instant t starting from u; throws on failure.
  void solve_instant(double t, Vector& u);
  /// One Newton loop of a contact pass; throws ConvergenceError when it does not converge.
  void newton_loop(Instant& in, Vector& u, int fixed_point);
  /// The residual at u and the convergence test of iteration `iter`: true when converged.
  bool converged_at(Instant& in, const Vector& u, int iter, Vector& residual, Vector& r_free,
                    std::vector<Triplet>& k_contact, bool& tangent_pending);
  /// One Newton step: the system, its solve, u updated.
  void newton_step(Instant& in, Vector& u, int iter, Vector& residual, Vector& r_free,
                   std::vector<Triplet>& k_contact);
  /// With no contact point active, the check (once per run) that something holds every body.
  void check_bodies_held(const Instant& in, const SystemTerms& terms, SolverKind backend);
  /// The linear solve of this iteration's system (linear_), worded in the log.
  Vector solve_system(const Instant& in, int iter, MatrixKind kind, SolverKind backend, const SystemTerms& terms,
                      const Vector& r_free, RefinedSolve& accuracy);
  /// A x for the system a (collective when shared or in parts).
  MatrixProduct system_product(const SparseMatrix& a, bool a_is_k_ff) const;
  /// u += du (and the eliminated and condensed unknowns), the next residual carried when it can be.
  void apply_increment(Instant& in, Vector& du, const RefinedSolve& accuracy, const SystemTerms& terms,
                       Vector& residual, Vector& u);
  /// The backend for this kind of system (linear_), its choice said once in the log.
  SolverKind choose_backend(MatrixKind kind);
  /// The backend that holds K_ff (handed over, no copy kept here), or null.
  const LinearSolver* k_ff_holder() const { return linear_ ? linear_->holder() : nullptr; }
  /// The system of this iteration in matrix_: K_ff with the contact terms, condensed and
  /// eliminated equations (or the interface solver's terms). A shared model: collective, and its
  /// pattern counter and values key are the whole system's, the same on every rank (a rank
  /// whose own columns kept their terms must still factorise when another's changed: MUMPS and
  /// PETSc factorise on all of them).
  void update_system(const Constraints& cons, const std::vector<Triplet>& contact, const std::vector<int>& condensed,
                     const std::vector<int>& eliminated);
  /// The node blocks of the system's equations (condensed and eliminated equations left
  /// out): what algebraic multigrid aggregates, with the coordinates of its rigid-body modes.
  SystemLayout system_layout(const Constraints& cons, const std::vector<int>& condensed,
                             const std::vector<int>& eliminated) const;
  /// Whether this run shares the model among the ranks of an MPI run (see distributed_).
  bool shares_model() const;
  /// The internal forces at u: K u for a constant tangent (stiffness_times), else the tangent
  /// source's, completed over the ranks, with the tangent at u from the same integration.
  /// Throws ConvergenceError (BehaviourIntegration) when a behaviour's integration failed at u
  /// (t: the instant, for the message).
  Vector internal_forces(const Vector& u, double t);
  /// The tangent of the run: the given one, the behaviours' (refused on a shared model or a
  /// mesh in parts), or the elastic stiffness.
  void choose_tangent();
  /// K u over the whole numbering (summed over the ranks when the model is shared).
  Vector stiffness_times(const Vector& u) const;
  /// A solve failure explained by the elastic stiffness (FailureDiagnosis); K_ff restored first.
  SolveError diagnose(const Constraints& cons, const SolveError& err, double t);

  /// The stiffness K split by the Dirichlet conditions of the run (one set for every instant,
  /// only the imposed values follow the load functions) and each iteration's system in its
  /// storage (system_matrix.hpp). Lives for the run.
  SystemMatrix matrix_;
  /// Where K comes from: the tangent given (set_tangent), or the linear elastic one of the run.
  TangentSource* given_tangent_ = nullptr;
  std::unique_ptr<TangentSource> elastic_tangent_;
  const CellBehaviours* behaviours_ = nullptr;  ///< set_behaviours
  std::unique_ptr<TangentSource> behaviour_tangent_;  ///< of the run, when a behaviour is nonlinear
  TangentSource* tangent_ = nullptr;
  /// The model shared among the ranks of an MPI run (several ranks, a backend named by the
  /// deck that takes a distributed system: MUMPS unless told not to share, or PETSc). The
  /// volume cells are partitioned (Scotch); each rank assembles the complete columns of the nodes it owns
  /// (RankLayout::owned_nodes), so K and the system hold only those, and products with them are
  /// summed over the ranks. The contact hook shares its pairing among the ranks and builds
  /// the terms of the points touching this rank's columns (share_among_ranks); each rank
  /// keeps the terms of its own columns. Pressures and nodal forces are computed by the rank
  /// of their node and summed. Everything else (mesh, vectors, results) is whole on every rank.
  bool distributed_ = false;
  /// A mesh in parts (set_part), and in_parts_ while a run is on it: distributed_ too, but the
  /// vectors are the part's (owned unknowns first, then the ghosts'); what the shared model sums
  /// over the ranks goes to the owners and back to the ghosts through equation_halo_, the norms
  /// are over the owned entries and then over the ranks, and the system's equations (its free
  /// unknowns, the same order) are numbered across the ranks by the layout's free
  /// numbers and exchanged through its free halo.
  const MeshPart* part_ = nullptr;
  const MeshPart* hook_part_ = nullptr;  ///< part_ with the hook's nodes (set_part), or null
  /// In parts: the part whose nodes the unknowns are on (hook_part_ when given, else part_).
  const MeshPart& numbered_part() const { return hook_part_ ? *hook_part_ : *part_; }
  bool in_parts_ = false;
  /// What differs between a run on one process, a shared model and a mesh in parts.
  RankLayout layout_;
  /// The linear solve of the run: backends, their factorisations, refinement (one per run).
  std::unique_ptr<LinearSolve> linear_;
  /// The convergence test of the run (made once the stiffness's scale is known).
  std::unique_ptr<ConvergenceTest> convergence_;
  double k_scale_ = 0.0;
  bool rigid_checked_ = false;  ///< elastic part proven free of rigid-body modes

  const FeModel& model_;
  const MechanicalLoads& loads_;
  NewtonOptions options_;
  ContactHook* contact_;  ///< the hook of this run: given_contact_, or it renumbered (in parts)
  ContactHook* given_contact_;
  /// In parts, a hook with multipliers seen with the owned unknowns first (renumbered_hook.hpp).
  std::unique_ptr<ContactHook> renumbered_contact_;
  const Log& log_;
  DofMap dofs_;
  std::vector<ResultStep> steps_;
  std::unique_ptr<StepResults> results_;  ///< the fields of each step, for the run
  SolverStats stats_;
  // (After the members they borrow, which are initialised first.)
  /// Contact passes on the elastic factorisation kept for the run (the interface policy).
  InterfacePolicy interface_{options_, stats_, log_};
  /// The log's words for what the linear solve did.
  SolveLog solve_log_{log_, options_};
};

}  // namespace lunaster::engine
