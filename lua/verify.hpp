#pragma once
/// `lunaster verify`: runs decks as child processes in parallel, collects their
/// TEST_RESU lines and exit codes, prints a summary and writes JUnit/JSON reports.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "lua/budget.hpp"

namespace lunaster::lua {

/// What `lunaster verify` was asked to do.
struct VerifyOptions {
  std::vector<std::filesystem::path> paths;  ///< decks or folders (default: testcases/)
  int jobs = 0;                              ///< parallel children; 0 = number of cores
  std::string junit_file;                    ///< JUnit XML report, if not empty
  std::string json_file;                     ///< JSON report, if not empty
  std::filesystem::path out_dir = "out/verify";  ///< each deck writes to out_dir/<deck name>
  std::filesystem::path executable;          ///< the lunaster binary run as `exe run DECK --out DIR`
  Budget budget;                             ///< --time-limit / --memory-limit: override every deck header
  bool vale_calc_report = true;              ///< a .comm's VALE_CALC are report lines (false: --vale-calc=check)
  std::string solveur;                       ///< --solveur=MUMPS: given to every deck's run
  int ranks = 0;                             ///< --np N: each deck runs as `mpirun -np N exe run ...` (0: no mpirun)
};

/// Default budget of a deck under `lunaster verify` (when neither the command line nor the deck header sets one).
constexpr double kVerifyDefaultSeconds = 300.0;
/// The parent stops a child this long after its time limit if it has not stopped itself.
constexpr double kVerifyKillGraceSeconds = 1.0;
/// Under --np, the extra time mpirun gets (its start-up, the ranks' own stop, and the
/// tearing down of the run); it is then asked to end the run (SIGTERM), and killed
/// kVerifyMpiTermSeconds later if it has not.
constexpr double kVerifyMpiKillGraceSeconds = 4.0;
constexpr double kVerifyMpiTermSeconds = 2.0;

/// One comparison of a .comm's VALE_CALC (code_aster's value) with lunaster's, as the deck printed it.
struct CodeAsterComparison {
  std::string check;  ///< NOM_CHAM, point, NOM_CMP [, LEGENDE]
  double lunaster = 0.0, code_aster = 0.0, difference = 0.0, tolerance = 0.0;
};

/// Result of one deck.
struct DeckOutcome {
  std::filesystem::path deck;
  int exit_code = -1;    ///< child's exit status (-1 if killed by a signal or not started)
  std::string status;    ///< "OK", "NOOK", "NO_CHECK", "ERROR", "TIMEOUT" or "OUT_OF_MEMORY"
  double time_limit = 0.0;       ///< the deck's budget: seconds (0 = none)
  double memory_limit_mb = 0.0;  ///< and MB (0 = none)
  int n_ok = 0, n_nook = 0;
  double seconds = 0.0;  ///< wall time
  std::string output;    ///< captured stdout + stderr
  std::vector<CodeAsterComparison> comparisons;  ///< CODE_ASTER lines of the output
};

/// Decks named by `paths`: files as given; folders searched recursively for *.lua,
/// *.export, and *.comm files that no .export of the same folder names, skipping folders
/// named `errors` (must-fail decks) and `lib` (modules that decks require). Sorted, unique.
std::vector<std::filesystem::path> collect_decks(const std::vector<std::filesystem::path>& paths);
/// Counts TEST_RESU lines (" OK ..." and "NOOK ...") in a deck's output.
void count_checks(const std::string& output, int& n_ok, int& n_nook);
/// The CODE_ASTER lines (checks or SAME/DIFF report lines) of a deck's output.
std::vector<CodeAsterComparison> code_aster_comparisons(const std::string& output);
/// The output folder of a deck under verify's `out_dir`: its name, with ".comm"/".export" kept
/// so that a .comm case and a Lua deck of the same name do not share a folder.
std::filesystem::path deck_out_dir(const std::filesystem::path& out_dir, const std::filesystem::path& deck);
/// "OK" (exit 0, a check line and no NOOK), "NOOK" (exit 1, or NOOK lines), "NO_CHECK" (exit 0 and
/// not one check line: the deck checked nothing), "TIMEOUT" (exit 5), "OUT_OF_MEMORY" (exit 6) or "ERROR".
std::string deck_status(int exit_code, int n_nook, int n_ok = 0);
/// The budget a deck runs with under verify: `overrides` (command line), else its header
/// (an .export's P time_limit / memory_limit),
/// else 300 s and half of the machine's memory. A malformed header is left to the child
/// to report as a deck error. A memory limit is each process's: under --np, `ranks`
/// processes share the default half of the machine.
Budget verify_budget(const std::filesystem::path& deck, const Budget& overrides, int ranks = 1);
/// Runs one deck as a child process (`exe run DECK --out DIR` plus the budget's
/// --time-limit/--memory-limit) and captures its output. The child enforces its budget
/// itself; if it is still running kVerifyKillGraceSeconds after its time limit, it is
/// killed (SIGKILL, that child only) and reported as TIMEOUT. With a `launcher` (mpirun
/// and its options, launcher[0] a path), the child is `launcher... exe run ...`: it gets
/// kVerifyMpiKillGraceSeconds more, then SIGTERM (mpirun ends its ranks), then SIGKILL.
DeckOutcome run_child(const std::filesystem::path& executable, const std::filesystem::path& deck,
                      const std::filesystem::path& out_dir, const Budget& budget = {},
                      const std::vector<std::string>& extra_args = {},
                      const std::vector<std::string>& launcher = {});
/// The executable `name` in a folder of the PATH, or empty.
std::filesystem::path find_on_path(const std::string& name);
/// JUnit XML for the outcomes (one testcase per deck).
std::string junit_xml(const std::vector<DeckOutcome>& outcomes);
/// JSON report for the outcomes.
std::string json_report(const std::vector<DeckOutcome>& outcomes);
/// Runs everything, prints the table and "N passed, M failed"; returns 0 if every deck is OK.
/// With `ranks`, each deck runs under the mpirun of the PATH (2 with a message if there is
/// none), and jobs defaults to the number of cores divided by `ranks`.
int verify(const VerifyOptions& options, std::ostream& out);

}  // namespace lunaster::lua
