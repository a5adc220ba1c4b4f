#pragma once
/// Time stepping with subdivision: one step from instant to instant, split into sub-steps when
/// Newton fails on it, the history (contact statuses) put back to the step's start first.
#include <functional>

#include "engine/core/log.hpp"
#include "engine/contact/contact_hook.hpp"
#include "engine/nonlinear/tangent_source.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

class TimeStepper {
 public:
  /// Solves the instant t from u (u becomes the solution); throws ConvergenceError when Newton fails.
  using Solve = std::function<void(double t, Vector& u)>;
  /// Called with each converged instant (sub-steps included) and its solution.
  using Commit = std::function<void(double t, const Vector& u)>;
  /// `levels`: splits at most (0: none, a failure is thrown as it is); `parts`: sub-steps per
  /// split. `history` and `tangent`: the state a failed attempt leaves that the sub-steps must
  /// not start from (either may be null). All are borrowed.
  TimeStepper(int levels, int parts, ContactHook* history, TangentSource* tangent, const Log& log)
      : levels_(levels), parts_(parts), history_(history), tangent_(tangent), log_(log) {}
  /// Advances u from instant t0 to t1, splitting the step on ConvergenceError.
  void advance(double t0, double t1, Vector& u, const Solve& solve, const Commit& commit) const {
    advance(t0, t1, 0, u, solve, commit);
  }

 private:
  void advance(double t0, double t1, int level, Vector& u, const Solve& solve, const Commit& commit) const;
  int levels_, parts_;
  ContactHook* history_;
  TangentSource* tangent_;
  const Log& log_;
};

}  // namespace lunaster::engine
