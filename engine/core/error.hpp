#pragma once
/// Error classes shared by every layer. The engine throws them without a deck
/// location; the Lua trampoline fills the location (file:line, command) in
/// before the message reaches the user. Exit codes follow STYLE.md §3.
#include <stdexcept>
#include <string>
#include <vector>

namespace lunaster {

/// The class of an error; the value is the process exit code. TimeLimit and OutOfMemory
/// are a deck over its budget (`lunaster run --time-limit/--memory-limit`, deck header).
enum class ErrorKind { Deck = 2, Solve = 3, Internal = 4, TimeLimit = 5, OutOfMemory = 6 };

/// Where in a deck an error arose. Empty fields are omitted when formatting.
struct ErrorContext {
  std::string file;          ///< deck file as given on the command line
  int line = 0;              ///< line of the command call in the deck
  std::string command;       ///< e.g. "STAT_NON_LINE"
  std::string keyword_path;  ///< e.g. "EXCIT[2].CHARGE"
};

/// What failed, in engine terms, with its numbers. The engine's messages speak of
/// iterations, residuals and tolerances; commands/ add the keywords the deck used
/// (ITER_GLOB_MAXI, CONTACT_INIT ...) from these fields.
struct Failure {
  enum class What {
    Unspecified,
    NewtonIterations,     ///< Newton did not converge within `limit` iterations
    StatusLoop,           ///< contact statuses still changing after `limit` iterations (`count` points)
    GeometryLoop,         ///< geometric residual `value` above `tolerance` after `limit` re-pairings
    RigidBodyMode,        ///< a body free to move: nothing holds it
    ContactConditioning,  ///< regular elastic part, singular or ill-conditioned system with contact terms
    SolveAccuracy,        ///< regular system without contact terms whose solve missed the accuracy asked
    OutOfMemory,          ///< a linear solver's factors do not fit
    NotAMedFile,          ///< a mesh file that is not MED
    IterativeSolve,       ///< an iterative linear solver that did not converge or cannot precondition this system
    NotInParts,           ///< a linear solver's option that a mesh in parts cannot take
    PartsBackend,         ///< a run in parts with a backend that does not solve in parts (`count` 1: the automatic choice)
    PartsMultipliers,     ///< a run in parts with multipliers and a backend that does not solve such a system
    BehaviourIntegration, ///< a behaviour found no admissible state at a point (the step is to be subdivided)
    SharedBehaviour,      ///< a nonlinear behaviour on a model shared among the ranks or in parts
  };
  What what = What::Unspecified;
  int limit = 0;
  int count = 0;
  int per_point = 0;                      ///< StatusLoop: `limit` is this many iterations per contact point
  double value = 0.0, tolerance = 0.0;
  bool residuals_known = false;           ///< relative/absolute below are the last Newton residuals
  double relative = 0.0, absolute = 0.0;
  int subdivision_levels = 0;             ///< step splits tried before giving up
};

/// Base of all lunaster errors. `what()` returns the fully formatted message.
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::string message, std::vector<std::string> hints = {});

  ErrorKind kind() const { return kind_; }
  /// The bare message, without location prefix.
  const std::string& message() const { return message_; }
  const std::vector<std::string>& hints() const { return hints_; }
  const ErrorContext& context() const { return context_; }
  /// Fills the fields of the context that are still empty (inner layers win).
  void fill_context(const ErrorContext& outer);
  /// Adds a hint line printed indented below the first line.
  void add_hint(std::string hint) { hints_.push_back(std::move(hint)); refresh(); }
  /// Replaces the message (commands/ rephrasing an engine failure in the deck's keywords).
  void set_message(std::string message) { message_ = std::move(message); refresh(); }
  void set_hints(std::vector<std::string> hints) { hints_ = std::move(hints); refresh(); }
  const Failure& failure() const { return failure_; }
  Failure& failure() { return failure_; }
  void set_failure(const Failure& f) { failure_ = f; }
  /// "deck.lua:42: STAT_NON_LINE: EXCIT[2].CHARGE: message" plus hint lines.
  std::string format() const;
  const char* what() const noexcept override { return formatted_.c_str(); }

 private:
  void refresh() { formatted_ = format(); }
  ErrorKind kind_;
  std::string message_;
  std::vector<std::string> hints_;
  ErrorContext context_;
  Failure failure_;
  std::string formatted_;
};

/// The input is wrong (deck, keyword value, mesh file, group name ...).
class DeckError : public Error {
 public:
  explicit DeckError(std::string message, std::vector<std::string> hints = {})
      : Error(ErrorKind::Deck, std::move(message), std::move(hints)) {}
  /// "expected <expected>, got <given>" at a keyword path.
  static DeckError at(std::string keyword_path, const std::string& expected, const std::string& given,
                      std::vector<std::string> hints = {});
};

/// The numerics failed: divergence, singular matrix, contact that did not settle.
class SolveError : public Error {
 public:
  explicit SolveError(std::string message, std::vector<std::string> hints = {})
      : Error(ErrorKind::Solve, std::move(message), std::move(hints)) {}

  /// A linear solver that could not allocate its factors: not a singular system, and
  /// not to be diagnosed as one.
  static SolveError out_of_memory(const std::string& backend, long long n_equations, const std::string& detail);
  bool out_of_memory() const { return out_of_memory_; }

 private:
  bool out_of_memory_ = false;
};

namespace engine {
/// Newton (or a contact loop) did not converge: a smaller step may help.
class ConvergenceError : public SolveError {
 public:
  using SolveError::SolveError;
};
}  // namespace engine

/// A bug in lunaster.
class InternalError : public Error {
 public:
  explicit InternalError(std::string message) : Error(ErrorKind::Internal, std::move(message)) {}
};

[[noreturn]] void assertion_failed(const char* expr, const std::string& msg, const char* file, int line);

}  // namespace lunaster

/// Always-on cheap check; throws InternalError naming the expression and place.
#define LUNASTER_ASSERT(cond, msg) \
  do { if (!(cond)) ::lunaster::assertion_failed(#cond, (msg), __FILE__, __LINE__); } while (0)
#ifndef NDEBUG
#define LUNASTER_DASSERT(cond, msg) LUNASTER_ASSERT(cond, msg)
#else
#define LUNASTER_DASSERT(cond, msg) do { } while (0)
#endif
