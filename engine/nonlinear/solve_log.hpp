#pragma once
/// The log's words for what the linear solve of a run did (LinearSolve's backend choice and
/// events): each said in the engine's terms, the lines that hold while they hold said once.
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/log.hpp"
#include "engine/nonlinear/linear_solve.hpp"
#include "engine/nonlinear/newton_options.hpp"

namespace lunaster::engine {

class SolveLog {
 public:
  /// `log` and `options` are the driver's, borrowed.
  SolveLog(const Log& log, const NewtonOptions& options) : log_(log), options_(options) {}
  /// Where a solve took place, for the words of its events.
  struct Where {
    double t = 0.0;                              ///< the instant
    const Mesh* mesh = nullptr;                  ///< to name an equation's node
    const DofMap* dofs = nullptr;
    const std::vector<int>* free_index = nullptr;  ///< per equation: its column in the system
    int interface_equations = 0;                 ///< solved by the interface solver on so many equations; 0: not
  };
  /// The backend chosen for a system of this kind and size, when it is not the one named.
  void backend(const LinearSolve::Backend& chosen, MatrixKind kind, int n_free) const;
  /// One thing the linear solve did.
  void event(const LinearSolve::Event& e, const Where& at);
  /// The last symbolic analysis said (shared with the interface solver's reference).
  std::string& analysis_said() { return analysis_logged_; }

 private:
  void factorised(const LinearSolver& solver, const Where& at);
  const Log& log_;
  const NewtonOptions& options_;
  std::string ordering_logged_;       ///< the last ordering line of the log (an ordering asked for)
  std::string factorisation_logged_;  ///< the last factorisation line of the log (one asked for)
  std::string memory_logged_;         ///< the last line of the log on where the factors are
  std::string approximation_logged_;  ///< the last line on the filtering and compression asked for
  std::string analysis_logged_;       ///< the last symbolic analysis said in the log (verbosity 2)
  std::string singular_said_;         ///< the last singular matrix the run went past, as the log said it
};

}  // namespace lunaster::engine
