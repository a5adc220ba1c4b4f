#pragma once
/// The deck runner: a sandboxed Lua state in which every catalogue command is a
/// global function (one generic trampoline), `_F` is the identity, globals are
/// strict, and concepts are typed userdata. Lua headers stay inside lua/*.cpp.
#include <exception>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

#include "catalog/args.hpp"
#include "catalog/spec.hpp"
#include "commands/registry.hpp"
#include "commands/session.hpp"
#include "lua/budget.hpp"

struct lua_State;

namespace lunaster::lua {

struct ExportFile;

/// Finds the handler of a command (nullptr if it has none). main() passes
/// cmd::find_handler; tests inject fakes.
using HandlerLookup = std::function<cmd::Handler(const std::string&)>;

/// Owns one lua_State for one run. Not copyable.
class Runner {
 public:
  /// `session` must outlive the runner; `lookup` resolves command handlers. A `guard`
  /// (which must outlive the runner) enforces its budget on the deck's Lua code.
  Runner(cmd::Session& session, HandlerLookup lookup, BudgetGuard* guard = nullptr);
  ~Runner();
  Runner(const Runner&) = delete;
  Runner& operator=(const Runner&) = delete;

  /// Runs a deck file (text only). Rethrows the typed lunaster::Error a command
  /// raised (with deck file:line and command filled in); Lua syntax and runtime
  /// errors become DeckError with the location Lua reports; a deck over its budget
  /// (or out of memory) raises an Error of kind TimeLimit (OutOfMemory).
  void run_file(const std::filesystem::path& deck);
  /// Runs a code_aster command file: converted to Lua line for line (lua/comm_convert.hpp) and
  /// run under the .comm's name, so every message names the .comm file and line. A file with
  /// forms the converter cannot translate stops before its first command (DeckError at the first).
  void run_comm(const std::filesystem::path& comm);
  /// Runs deck text; `chunk_name` is the file name used in messages.
  void run_string(const std::string& code, const std::string& chunk_name);
  /// Lua traceback of the last failed run (shown for InternalError only).
  const std::string& last_traceback() const { return traceback_; }

  cmd::Session& session() { return session_; }
  /// Records in `reads` (not owned; null to stop) every keyword the handlers read (tests).
  void set_keyword_reads(catalog::KeywordReads* reads) { reads_ = reads; }
  /// The Lua state (for tests and the bridge code in lua/).
  lua_State* state() { return state_; }

  // ---- used by the C callbacks in lua/*.cpp ----
  /// Body of the generic trampoline: convert, validate, echo, run the handler, push the result.
  int call_command(lua_State* L, const catalog::CommandSpec& spec);
  /// Stores the traceback of the error being raised (message handler of the protected call).
  void set_traceback(std::string traceback) { traceback_ = std::move(traceback); }
  /// Folder of the deck being run (for `require`).
  const std::filesystem::path& deck_dir() const { return deck_dir_; }

 private:
  void run_loaded(int load_status);
  catalog::ConceptPtr execute(lua_State* L, const catalog::CommandSpec& spec, const ErrorContext& where);

  cmd::Session& session_;
  HandlerLookup lookup_;
  BudgetGuard* guard_ = nullptr;
  lua_State* state_ = nullptr;
  std::exception_ptr pending_;    ///< typed error raised by the last failing command
  std::string pending_message_;   ///< its Lua error message, to recognise it at the top
  std::string traceback_;
  std::filesystem::path deck_dir_;
  catalog::KeywordReads* reads_ = nullptr;
};

/// A code_aster command file (.comm) or study description (.export), by extension.
bool is_comm_file(const std::filesystem::path& deck);
bool is_export_file(const std::filesystem::path& deck);

/// Binds an .export's command file and units to `session`, as `lunaster run X.export` does
/// before running its .comm (with Runner::run_comm).
void apply_export(const ExportFile& study, cmd::Session& session);

/// Runs one deck (a Lua deck, a .comm, or an .export naming a .comm, its units and its
/// limits) and maps the outcome to the exit code of STYLE.md §3
/// (0 OK, 1 some TEST_RESU NOOK, 2 DeckError, 3 SolveError, 4 InternalError,
/// 5 over the time budget, 6 over the memory budget or out of memory),
/// printing any error to `err` (with a traceback for InternalError only).
/// The budget is the deck header's (read_budget_header) with the fields of
/// `overrides` (the command line) replacing it; a hard stop ends the process.
/// An .export the caller has already read (to open its message file) is passed as `read`.
/// The time limit counts from `start` (`lunaster run`: the process's creation, process_start(),
/// or the deck's start under mpirun).
int run_deck(const std::filesystem::path& deck, cmd::Session& session, HandlerLookup lookup, std::ostream& err,
             const Budget& overrides = {}, const ExportFile* read = nullptr,
             std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());

}  // namespace lunaster::lua
