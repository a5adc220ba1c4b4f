#pragma once
/// The interface (Schur) policy: whether the contact passes of a run solve on the elastic
/// factorisation kept for the run (InterfaceSolver), factorising only the dense Schur
/// complement of the contact surfaces' equations at each pass, and when it is given up.
#include <memory>
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/log.hpp"
#include "engine/nonlinear/constraints.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/nonlinear/linear_solve.hpp"
#include "engine/nonlinear/newton_options.hpp"
#include "engine/solver/interface_solver.hpp"

namespace lunaster::engine {

class InterfacePolicy {
 public:
  /// `options`, `stats` and `log` are the driver's, borrowed. The decision holds for the
  /// solver's lifetime (not reset between runs).
  InterfacePolicy(const NewtonOptions& options, SolverStats& stats, const Log& log)
      : options_(options), stats_(stats), log_(log) {}
  /// The interface solver solves this iteration's system.
  bool active() const { return use_ == 1; }
  /// Decided at the first contact solve, from its terms (`allowed`: the run lets it be used at
  /// all: the automatic choice of CHOLMOD, a constant tangent, the model whole on this
  /// process); given up when relations are eliminated (`eliminations`), when a term reaches
  /// an equation outside the interface, or when the hook's tangent is unsymmetric. `k_ff` gets
  /// the zero diagonals the interface needs.
  void decide(const Constraints& cons, const std::vector<Triplet>& contact, bool eliminations,
              const ContactHook& hook, const DofMap& dofs, SparseMatrix& k_ff, bool allowed);
  /// Factorises the reference from K_ff when it is not of this `generation` (once per run); on
  /// failure the interface solver is dropped and the whole system is solved from then on.
  /// `analysis_said`: the last symbolic analysis said in the log (shared with the backends').
  void ensure_reference(SparseMatrix& k_ff, long generation, std::string& analysis_said);
  /// The interface solver, its factor state, its equations and, per free equation, whether it
  /// is one of them (while active()).
  InterfaceSolver& solver() { return *solver_; }
  LinearSolve::FactorState& state() { return state_; }
  const std::vector<int>& equations() const { return solver_->interface(); }
  const std::vector<char>& on_interface() const { return on_interface_; }

 private:
  /// Decides use_ (first contact solve), from the contact terms of that solve.
  void choose(const Constraints& cons, const std::vector<Triplet>& contact, const ContactHook& hook,
              const DofMap& dofs, SparseMatrix& k_ff, bool allowed);
  void drop() { use_ = -1, solver_.reset(), stats_.interface_equations = 0; }
  const NewtonOptions& options_;
  SolverStats& stats_;
  const Log& log_;
  /// 0 not decided yet, 1 used, -1 not (decided at the first solve).
  int use_ = 0;
  std::unique_ptr<InterfaceSolver> solver_;
  long reference_ = -1;  ///< K_ff generation of the factorised reference
  LinearSolve::FactorState state_;
  std::vector<char> on_interface_;  ///< per free equation: on the interface
  /// With an interface of the components the contact terms reach: terms at most this large
  /// count for nothing when it is chosen and checked (kNegligibleTerm of the largest term of
  /// the first contact solve), and the share of the reference's factorisation its dense one
  /// may cost. Both 0 with the whole surfaces.
  double floor_ = 0.0;
  double dense_share_ = 0.0;
  static constexpr double kNegligibleTerm = 1e-12;
};

}  // namespace lunaster::engine
