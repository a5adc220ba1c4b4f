#include "engine/nonlinear/time_stepper.hpp"

#include <cstdio>
#include <string>

#include "engine/core/error.hpp"
#include "engine/nonlinear/sci.hpp"

namespace lunaster::engine {

void TimeStepper::advance(double t0, double t1, int level, Vector& u, const Solve& solve,
                          const Commit& commit) const {
  Vector trial = u;
  const ContactSnapshot state = history_ ? history_->snapshot() : ContactSnapshot{};
  try {
    solve(t1, trial);
  } catch (const ConvergenceError& err) {
    // The sub-steps start from the statuses of the step, not from the diverged attempt's.
    if (history_) history_->restore(state);
    if (tangent_) tangent_->restore();
    if (level >= levels_) {
      if (levels_ == 0) throw;
      ConvergenceError final(err.message(), err.hints());
      final.set_failure(err.failure());
      final.failure().subdivision_levels = level;
      final.add_hint("step [" + sci(t0) + ", " + sci(t1) + "] still failed after " + std::to_string(level) +
                     " subdivision level(s)");
      throw final;
    }
    log_.warning("step to instant " + sci(t1) + " failed (" + err.message() + "); splitting it into " +
                 std::to_string(parts_) + " sub-steps (level " + std::to_string(level + 1) + ")");
    double ta = t0;
    for (int k = 1; k <= parts_; ++k) {
      const double tb = k == parts_ ? t1 : t0 + (t1 - t0) * k / parts_;
      advance(ta, tb, level + 1, u, solve, commit);
      ta = tb;
    }
    return;
  }
  u = trial;
  commit(t1, u);
}

}  // namespace lunaster::engine
