#pragma once
/// The contact algorithm as the Newton driver (static_solver.hpp) sees it.
/// Implemented in engine/contact (contact_problem.hpp); the driver knows no
/// contact method, only this interface. It lives here, below the driver (engine/nonlinear),
/// so that the folder implementing it does not include the folder that calls it.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/linear_relations.hpp"
#include "engine/core/linalg.hpp"
#include "engine/core/log.hpp"
#include "engine/fields/fields.hpp"

namespace lunaster::engine {

/// Contact state at the start of a step: the statuses, and whether the first
/// pairing of the run is still to come. Restored when a failed step is split,
/// so that the sub-steps start from the state of the step, not from the
/// diverged attempt.
struct ContactSnapshot {
  std::vector<char> active;
  bool first_step = true;
  /// A hook's own pairing at the snapshot, for a hook that does not pair again at the start
  /// of every step (mortar keeps the last converged pairing); null otherwise. Opaque here.
  std::shared_ptr<const void> pairing;
};

/// One unknown a hook removes from the linear solve by a linear relation between Newton
/// increments: du[eq] = sum_k coef_k du[term_k] + value. The terms never name an eliminated
/// equation (the hook closes its relations) and may name Dirichlet-constrained ones (their
/// increment is zero). The driver solves Q^T K Q v = -Q^T (r + K b) with u = Q v + b, an SPD
/// system when K is SPD on the remaining unknowns, and then sets du[eq] from the relation.
/// The relations' reactions are the hook's to add to the residual in add_to_system (Newton's
/// convergence is judged on that residual).
struct Elimination {
  int eq = -1;
  std::vector<std::pair<int, double>> terms;
  double value = 0.0;
};

class ContactHook {
 public:
  virtual ~ContactHook() = default;
  /// The Dirichlet conditions of the run, once, before add_dofs (a hook that ties
  /// unknowns together skips the relations these already impose).
  virtual void set_dirichlet(const std::vector<DirichletValue>& /*dirichlet*/) {}
  /// The displacement components (node, component) that the run's linear relations of two
  /// terms or more tie to other unknowns, once, before add_dofs (a hook whose conditions act
  /// on the same components may say so).
  virtual void set_related(const std::vector<std::pair<int, int>>& /*node_components*/) {}
  /// Hands over the linear relations the hook's discretisation puts between displacement
  /// components (discrete contact's QUAD8 mid-side ties), once, before set_dirichlet: the run's
  /// relation facility then holds them beside the deck's (and may solve each for one unknown:
  /// ELIM_LAGR), and the hook keeps none of them. Empty: none, or none to hand.
  /// `which`, when given, picks the relations to hand over; the hook keeps the others.
  virtual std::vector<LinearRelation> take_relations(const std::function<bool(const LinearRelation&)>& which = {}) {
    (void)which;
    return {};
  }
  /// Adds contact unknowns (LAGS_C ...) to the numbering, once, before any step.
  virtual void add_dofs(DofMap& dofs) = 0;
  /// A model shared among the ranks of an MPI run, once after add_dofs: `owned_nodes` flags,
  /// per mesh node, the nodes whose equations are this rank's. The hook may then share its pairing
  /// among the ranks (each projects some points and receives the others') and build the
  /// tangent terms of the points that touch this rank's columns only (the driver keeps those
  /// columns). Its residual stays whole on every rank. Collective from then on: every rank
  /// calls begin_step, settle and add_to_system alike.
  virtual void share_among_ranks(const std::vector<char>& /*owned_nodes*/) {}
  /// The instant about to be solved, before begin_step: for terms that follow the load
  /// functions (a relation's right-hand side).
  virtual void set_instant(double /*t*/) {}
  /// Start of an instant, with the converged displacement of the previous one.
  virtual void begin_step(const Vector& u, const Log& log) = 0;
  /// Adds the contact tangent and residual at iterate u (residual = internal - external).
  /// The triplets (their number, order and positions; not their values) depend only on
  /// `pattern_version()`: status changes leave zeros in place, so the driver keeps its
  /// system pattern and the solvers their analysis. Rows and columns of
  /// `condensed_equations()` hold zeros; the driver puts a unit diagonal there.
  virtual void add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) = 0;
  /// The residual part of add_to_system alone, with the same side effects (statuses updated
  /// inside Newton), when the hook can give it for less than the tangent: the driver tests
  /// convergence on it and calls add_to_system only for an iteration that solves, so the
  /// tangent of a converged iterate is never built. Returns false, `residual` untouched,
  /// when not provided.
  virtual bool add_residual(const Vector& /*u*/, Vector& /*residual*/) { return false; }
  /// Unknowns the hook eliminates from the next linear solve (valid after add_to_system):
  /// the driver solves for the others and then calls `recover`. Empty: none.
  virtual const std::vector<int>& condensed_equations() const {
    static const std::vector<int> none;
    return none;
  }
  /// After a linear solve that left out `condensed_equations()`, sets those unknowns in u
  /// from the other (updated) ones.
  virtual void recover(Vector& /*u*/) {}
  /// Unknowns eliminated by linear relations in the next linear solve (valid after
  /// add_to_system); their rows and columns of the contact triplets hold nothing. Empty: none.
  virtual const std::vector<Elimination>& eliminations() const {
    static const std::vector<Elimination> none;
    return none;
  }
  /// Every equation a contact term of this run may touch, whatever the pairing (sorted): the
  /// unknowns of the contact surfaces' nodes and the hook's own. The rest of the system is
  /// then the elastic stiffness alone, and the driver may keep it factorised for the whole run
  /// (InterfaceSolver). Empty: not known.
  virtual std::vector<int> surface_equations() const { return {}; }
  /// The displacement components (DX, DY, DZ) that the contact terms of the present pairing
  /// may reach, active or not: a component that no normal has adds no term (the normal one
  /// alone on a flat surface square to an axis). Default: every one.
  virtual std::array<bool, 3> displacement_components() const { return {true, true, true}; }
  /// False when the contact conditions are not yet met at the last add_to_system (statuses
  /// changed there, or an active condition is violated): Newton goes on even if the residual
  /// is small (semi-smooth Newton on the statuses).
  virtual bool newton_converged() const { return true; }
  /// Called when Newton converged with the current statuses/geometry frozen.
  /// Updates statuses and pairing; returns true when nothing changed (settled).
  virtual bool settle(const Vector& u, const Log& log) = 0;
  /// Changes whenever the triplets of add_to_system change their positions (a new pairing).
  virtual long pattern_version() const { return 0; }
  /// Changes whenever the statuses change (a key, not a count).
  virtual unsigned long long status_key() const { return 0; }
  /// Kind of the system solved with the current statuses (after condensation).
  virtual MatrixKind matrix_kind() const = 0;
  /// Number of contact points (or slave nodes) currently active. With none, the
  /// bodies must be held by Dirichlet conditions alone: the driver checks it.
  virtual int n_active() const = 0;
  /// False for a hook that adds linear relations only (no contact zone): the driver then runs
  /// no contact pass and says nothing of contact.
  virtual bool has_contact() const { return true; }
  /// Unknowns that the hook's linear relations tie to others: counted as held when the
  /// driver looks for bodies that nothing holds (with no active contact point).
  virtual std::vector<int> related_equations() const { return {}; }
  /// Stores contact results (LAGS_C in DEPL is already in u; CONT_NOEU ...).
  virtual void write_fields(const Vector& u, ResultStep& step) const = 0;
  /// The initial state (NUME_ORDRE 0, before any pairing): the components the hook adds to
  /// DEPL at later steps, at their value before contact, so that every step of a result has
  /// the same components (a MED field has one list of components for all its steps). A hook
  /// whose contact unknowns are already in u adds nothing.
  virtual void write_initial_fields(ResultStep& /*step*/) const {}
  /// State at the start of a step, and its restoration (step subdivision).
  virtual ContactSnapshot snapshot() const { return {}; }
  virtual void restore(const ContactSnapshot& /*state*/) {}
  /// What the hook can say of a failed iteration (a singular system, Newton out of iterations):
  /// e.g. friction's points that all slip, or whose statuses cycled. Empty: nothing.
  virtual std::vector<std::string> failure_hints() const { return {}; }
  /// A step converged at u: the contact history (friction's statuses and tractions) at its end
  /// becomes the next step's start. Called before the step's results are written.
  virtual void commit_step(const Vector& /*u*/) {}
};

}  // namespace lunaster::engine
