/// The lunaster command line: run a deck, verify a suite, show help, dump the catalogue.
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "catalog/args.hpp"
#include "catalog/doc.hpp"
#include "commands/registry.hpp"
#include "engine/io/atomic_file.hpp"
#include "lua/allocator_settings.h"
#include "lua/comm_convert.hpp"
#include "lua/export_file.hpp"
#include "lua/runner.hpp"
#include "lua/verify.hpp"
#include "lua/version.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "engine/solver/blas.hpp"

namespace fs = std::filesystem;
using namespace lunaster;

namespace {

constexpr const char* kUsage = R"(usage:
  lunaster run DECK [--out DIR] [-v|-q] [--time-limit S] [--memory-limit MB] [--vale-calc=report|check]
                  [--solveur=MUMPS]           run a deck: DECK.lua, a code_aster DECK.comm, or a DECK.export
                                              naming a .comm, its units and limits (output: ./out/<deck name>)
  lunaster verify [PATHS...] [-j N] [--np N] [--out DIR] [--junit FILE] [--json FILE] [--time-limit S]
                  [--memory-limit MB] [--vale-calc=report|check] [--solveur=MUMPS]
                                              run decks (.lua, .export, and .comm without an .export;
                                              default: testcases/) and summarise TEST_RESU
                                              (--np N: each deck as `mpirun -np N lunaster run ...`)
  lunaster convert CASE.comm [-o CASE.lua] [--check]
                                              translate a code_aster .comm file to a deck, line for line
                                              (--check: only list what lunaster would not take)
  lunaster help [COMMAND]                     list commands, or the keywords of one command
  lunaster --dump-catalog md [FILE]           the catalogue as Markdown (docs/commands.md)
  lunaster --version                          the version, the commit and build, and the versions of the
                                              libraries it runs on (for a bug report); also `lunaster version`
  lunaster --help                             this text
budgets: --time-limit (wall-clock seconds) and --memory-limit (resident MB) override the deck
  header "-- lunaster: time_limit=S memory_limit=MB" (an .export's P time_limit / memory_limit);
  run has no limit unless one is given, verify defaults to 300 s and half of the machine's memory per deck
code_aster VALE_CALC: the VALE_CALC of a .comm (run alone or named by an .export) are code_aster's own
  non-regression values, not lunaster's: by default (--vale-calc=report) each is a CODE_ASTER report line,
  SAME or DIFF with its relative difference, and does not count (the VALE_REFE checks decide OK/NOOK);
  --vale-calc=check counts them as checks (OK/NOOK at their TOLE_MACHINE, as code_aster does).
  A Lua deck's VALE_CALC are lunaster's own recorded values: always checks
MPI: `mpirun -np N lunaster run DECK` runs the deck on N ranks (MUMPS factorises across them); rank 0
  alone prints and writes files, every rank returns the same exit status; verify is not run by mpirun
--solveur=MUMPS: every STAT_NON_LINE / MECA_NON_LINE solves with MUMPS whatever its SOLVEUR says, the
  model shared among the ranks under mpirun (as SOLVEUR=_F{METHODE='MUMPS', MATR_DISTRIBUEE='OUI'});
  the deck's other SOLVEUR keywords that MUMPS reads are kept
exit status: 0 OK (a deck that ran no check says NO_CHECK), 1 some TEST_RESU NOOK, 2 deck error, 3 solve error,
  4 internal error, 5 time limit exceeded, 6 memory limit exceeded (or out of memory)
)";

/// Writes to a first stream buffer and, if given, copies into a second one.
class TeeBuffer : public std::streambuf {
 public:
  TeeBuffer(std::streambuf* first, std::streambuf* copy) : first_(first), copy_(copy) {}

 protected:
  int overflow(int ch) override {
    if (ch == traits_type::eof()) return traits_type::not_eof(ch);
    if (copy_) copy_->sputc(static_cast<char>(ch));
    return first_->sputc(static_cast<char>(ch));
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (copy_) copy_->sputn(s, n);
    return first_->sputn(s, n);
  }
  int sync() override {
    if (copy_) copy_->pubsync();
    return first_->pubsync();
  }

 private:
  std::streambuf* first_;
  std::streambuf* copy_;
};

/// "3 comparison(s) with code_aster's VALE_CALC: 1 beyond tolerance, largest difference 3.5e-03 (DEPL  O  DY);
/// reported, not counted (--vale-calc=check counts them)".
std::string comparison_summary(const std::vector<cmd::Session::Comparison>& comparisons, bool reported) {
  int beyond = 0;
  const cmd::Session::Comparison* largest = nullptr;
  for (const auto& c : comparisons) {
    beyond += c.difference > c.tolerance;
    if (!largest || c.difference > largest->difference) largest = &c;
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.3e", largest->difference);
  return "lunaster: " + std::to_string(comparisons.size()) + " comparison(s) with code_aster's VALE_CALC: " +
         std::to_string(beyond) + " beyond tolerance, largest difference " + text + " (" + largest->what + "); " +
         (reported ? "reported, not counted (--vale-calc=check counts them)" : "counted as checks (--vale-calc=check)");
}

/// How long a rank that stopped on an error waits for the others at the end of the run
/// (engine/parallel/mpi_runtime.hpp): ranks that run the same deck reach the same error
/// within moments; longer means they are blocked in a collective call waiting for it.
constexpr double kRankWaitSeconds = 10.0;

/// Writes `text` to the file descriptor `fd`, whole.
void write_all(int fd, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

/// Every line of `text` with `prefix` in front.
std::string prefixed_lines(const std::string& prefix, const std::string& text) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out += prefix + line + "\n";
  return out;
}

int usage_error(const std::string& message) {
  std::cerr << "lunaster: " << message << "\n" << kUsage;
  return static_cast<int>(ErrorKind::Deck);
}

/// Reads the value of --time-limit / --memory-limit into `budget`; false (after a usage
/// message) if it is not a positive number.
bool budget_option(const std::string& verb, const std::string& option, const std::string& text, lua::Budget& budget) {
  const auto value = lua::parse_budget_value(text);
  const bool is_time = option == "--time-limit";
  if (!value) {
    usage_error(verb + ": " + option + " expects a positive number of " + (is_time ? "seconds" : "MB") + ", got '" +
                text + "'");
    return false;
  }
  (is_time ? budget.seconds : budget.megabytes) = *value;
  return true;
}

bool is_budget_option(const std::string& word) { return word == "--time-limit" || word == "--memory-limit"; }

bool is_solveur_option(const std::string& word) { return word.rfind("--solveur", 0) == 0; }

/// --solveur=METHODE: the method every STAT_NON_LINE solves with, whatever its SOLVEUR says.
/// MUMPS alone: every system the engine builds (symmetric or not, multipliers or not) is one
/// it factorises, and under mpirun it takes the model shared among the ranks.
bool solveur_option(const char* command, const std::string& word, std::string& solveur) {
  const std::string value = word.rfind("--solveur=", 0) == 0 ? word.substr(10) : std::string();
  if (value != "MUMPS") {
    std::cerr << "lunaster: " << command << ": --solveur expects --solveur=MUMPS (every STAT_NON_LINE then "
              << "factorises with MUMPS, the model shared among the ranks under mpirun), got '" << word << "'\n";
    return false;
  }
  solveur = value;
  return true;
}

int run_command(const std::vector<std::string>& args) {
  std::string deck;
  fs::path out;
  int verbosity = 1;
  bool vale_calc_report = true;  // a .comm's VALE_CALC are code_aster's: reported unless --vale-calc=check
  std::string solveur;
  lua::Budget budget;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (is_budget_option(args[i]) && i + 1 < args.size()) {
      if (!budget_option("run", args[i], args[i + 1], budget)) return static_cast<int>(ErrorKind::Deck);
      ++i;
    } else if (args[i] == "--out" && i + 1 < args.size()) out = args[++i];
    else if (args[i] == "--vale-calc=report" || args[i] == "--vale-calc=check")
      vale_calc_report = args[i] == "--vale-calc=report";
    else if (is_solveur_option(args[i])) {
      if (!solveur_option("run", args[i], solveur)) return static_cast<int>(ErrorKind::Deck);
    }
    else if (args[i] == "-v") verbosity = 2;
    else if (args[i] == "-q") verbosity = 0;
    else if (deck.empty() && args[i][0] != '-') deck = args[i];
    else return usage_error("unexpected argument '" + args[i] + "'");
  }
  if (deck.empty()) return usage_error("run: no deck given");
  if (out.empty()) out = fs::path("out") / fs::path(deck).stem();
  // An .export's message file (`F mess NAME R 6`) gets a copy of everything the run prints.
  std::ofstream mess;
  std::optional<lua::ExportFile> study;
  if (lua::is_export_file(deck)) {
    try {
      study = lua::read_export(deck);
    } catch (const Error& e) {
      std::cerr << e.what() << "\n";
      return static_cast<int>(e.kind());
    }
    for (const auto& [unit, f] : study->results)
      if (f.type == "mess" && engine::parallel::writes_output()) {  // under mpirun, rank 0's file
        fs::create_directories(out);
        mess.open(out / f.path.filename());
      }
  }
  TeeBuffer out_tee(std::cout.rdbuf(), mess.is_open() ? mess.rdbuf() : nullptr);
  TeeBuffer err_tee(std::cerr.rdbuf(), mess.is_open() ? mess.rdbuf() : nullptr);
  std::ostream log_stream(&out_tee), err_stream(&err_tee);
  Log log(log_stream, verbosity);
  cmd::Session session(log);
  session.deck_path = deck;
  session.output_dir = out;
  session.vale_calc_report = vale_calc_report;
  session.solveur_override = solveur;
  // A run's time limit counts from the process's creation, as verify counts it from the spawn;
  // under mpirun, from the deck's start (verify gives mpirun's own start-up a grace of its own,
  // kVerifyMpiKillGraceSeconds, and a rank cannot know when mpirun started).
  const auto start = engine::parallel::launched_by_mpi() ? std::chrono::steady_clock::now() : lua::process_start();
  int code = lua::run_deck(deck, session, cmd::find_handler, err_stream, budget, study ? &*study : nullptr, start);
  if (code <= 1) {
    int n_ok = 0;
    for (const auto& t : session.tests) n_ok += t.ok;
    log.info("lunaster: " + std::to_string(n_ok) + " check(s) OK, " + std::to_string(session.tests.size() - n_ok) +
             " NOOK");
    if (!session.comparisons.empty()) log.info(comparison_summary(session.comparisons, session.vale_calc_report));
  }
  // A deck that checked nothing proves nothing: a verification deck that lost its TEST_RESU would
  // pass unseen. The run says so whatever the verbosity, and `verify` and the CTest deck suite count
  // it as a failure (NO_CHECK); the exit status stays 0, as code_aster ends a study without
  // TEST_RESU normally, so that a production study run from a script is not reported as failed.
  if (code == 0 && session.tests.empty())
    log.always(std::string("lunaster: NO_CHECK: the deck checked nothing (") +
               (session.comparisons.empty() ? "it ran no TEST_RESU or TEST_TABLE"
                                            : "its code_aster VALE_CALC are only reported, --vale-calc=check counts them") +
               "); lunaster verify counts it as a failure");
  log_stream.flush();
  err_stream.flush();
  return code;
}

int verify_command(const std::vector<std::string>& args) {
  if (engine::parallel::launched_by_mpi()) {
    std::cerr << "lunaster: verify runs each deck as a child process and is not to be started by mpirun (every "
                 "rank would run the whole suite, and the children would inherit the launcher's environment): "
                 "run `lunaster verify --np N ...` to run each deck on N MPI ranks\n";
    return static_cast<int>(ErrorKind::Deck);
  }
  lua::VerifyOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool has_value = i + 1 < args.size();
    if ((args[i] == "-j" || args[i] == "--np") && has_value) {
      const std::string option = args[i];
      std::size_t used = 0;
      int value = 0;
      try {
        value = std::stoi(args[++i], &used);
      } catch (const std::exception&) {
      }
      if (used != args[i].size() || value < (option == "-j" ? 0 : 1))
        return usage_error("verify: " + option + " expects a " +
                           (option == "-j" ? "number" : "positive number of MPI ranks") + ", got '" + args[i] + "'");
      (option == "-j" ? options.jobs : options.ranks) = value;
    } else if (is_budget_option(args[i]) && has_value) {
      if (!budget_option("verify", args[i], args[i + 1], options.budget)) return static_cast<int>(ErrorKind::Deck);
      ++i;
    } else if (args[i] == "--junit" && has_value) options.junit_file = args[++i];
    else if (args[i] == "--json" && has_value) options.json_file = args[++i];
    else if (args[i] == "--vale-calc=report" || args[i] == "--vale-calc=check")
      options.vale_calc_report = args[i] == "--vale-calc=report";
    else if (is_solveur_option(args[i])) {
      if (!solveur_option("verify", args[i], options.solveur)) return static_cast<int>(ErrorKind::Deck);
    } else if (args[i] == "--out" && has_value) options.out_dir = args[++i];
    else if (args[i][0] == '-') return usage_error("verify: unexpected option '" + args[i] + "'");
    else options.paths.emplace_back(args[i]);
  }
  options.executable = fs::read_symlink("/proc/self/exe");
  return lua::verify(options, std::cout);
}

int help_command(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::cout << "commands (name, result, description); `lunaster help COMMAND` for keywords:\n"
              << catalog::command_list();
    return 0;
  }
  if (const auto* spec = catalog::find_command(args[0])) {
    std::cout << catalog::command_help(*spec);
    return 0;
  }
  std::vector<std::string> names;
  for (const auto& spec : catalog::all_commands()) names.push_back(spec.name);
  std::string suggestion = catalog::closest_name(args[0], names);
  std::cerr << "lunaster: unknown command '" << args[0] << "'"
            << (suggestion.empty() ? "" : " (did you mean " + suggestion + "?)") << "\n";
  return static_cast<int>(ErrorKind::Deck);
}

int dump_command(const std::vector<std::string>& args) {
  if (args.empty() || args[0] != "md") return usage_error("--dump-catalog: only 'md' is supported");
  const std::string text = catalog::catalog_markdown();
  if (args.size() < 2) {
    std::cout << text;
    return 0;
  }
  try {
    engine::write_file_atomically(args[1], [&](std::ostream& file) { file << text; });
  } catch (const Error& e) {
    std::cerr << "lunaster: " << e.message() << "\n";
    return static_cast<int>(ErrorKind::Deck);
  }
  return 0;
}

/// `lunaster --version`: this build and the libraries' versions (lua/version.hpp). Starts
/// neither MPI nor PETSc.
int version_command(const std::string& verb, const std::vector<std::string>& args) {
  if (!args.empty()) return usage_error(verb + ": unexpected argument '" + args[0] + "'");
  std::cout << lua::version_text(lua::build_info(), lua::library_versions()) << std::flush;
  return 0;
}

/// `lunaster convert CASE.comm [-o CASE.lua] [--check]`: 0 if everything was translated (or,
/// with --check, is known), 2 otherwise; the deck is written in both cases.
int convert_command(const std::vector<std::string>& args) {
  fs::path comm, out;
  bool check = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-o" && i + 1 < args.size()) out = args[++i];
    else if (args[i] == "--check") check = true;
    else if (comm.empty() && args[i][0] != '-') comm = args[i];
    else return usage_error("convert: unexpected argument '" + args[i] + "'");
  }
  if (comm.empty()) return usage_error("convert: no .comm file given");
  std::ifstream in(comm, std::ios::binary);
  if (!in) {
    std::cerr << "lunaster: convert: cannot read " << comm.string() << "\n";
    return static_cast<int>(ErrorKind::Deck);
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string name = comm.string();
  auto print = [&](const std::vector<lua::CommIssue>& issues) {
    for (const auto& issue : issues)
      std::cerr << name << ":" << issue.line << ": " << issue.what << ": " << issue.hint << "\n";
  };
  if (check) {
    const auto issues = lua::check_comm(text);
    print(issues);
    std::cerr << name << ": " << (issues.empty() ? "nothing to finish by hand, every command and keyword is known"
                                                  : std::to_string(issues.size()) + " issue(s)")
              << "\n";
    return issues.empty() ? 0 : static_cast<int>(ErrorKind::Deck);
  }
  if (out.empty()) out = fs::path(comm).replace_extension(".lua");
  std::error_code ec;
  if (out == comm || (fs::exists(out, ec) && fs::equivalent(out, comm, ec))) {
    std::cerr << "lunaster: convert: the output " << out.string() << " is the .comm file itself\n";
    return static_cast<int>(ErrorKind::Deck);
  }
  const auto conversion = lua::convert_comm(text);
  try {
    engine::write_file_atomically(out, [&](std::ostream& file) { file << conversion.lua; });
  } catch (const Error& e) {
    std::cerr << "lunaster: " << e.message() << "\n";
    return static_cast<int>(ErrorKind::Deck);
  }
  print(conversion.refused);
  return conversion.refused.empty() ? 0 : static_cast<int>(ErrorKind::Deck);
}

int run_verb(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::cout << kUsage;
    return args.empty() ? static_cast<int>(ErrorKind::Deck) : 0;
  }
  const std::string verb = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (verb == "run") return run_command(rest);
    if (verb == "verify") return verify_command(rest);
    if (verb == "help") return help_command(rest);
    if (verb == "convert") return convert_command(rest);
    if (verb == "--dump-catalog") return dump_command(rest);
    if (verb == "--version" || verb == "version") return version_command(verb, rest);
  } catch (const std::exception& e) {
    std::cerr << "lunaster: internal error: " << e.what() << "\n";
    return static_cast<int>(ErrorKind::Internal);
  }
  return usage_error("unknown verb '" + verb + "'");
}

/// The end of a run of several ranks (mpirun -np N): every rank returns the same exit
/// status, the worst of the ranks', and rank 0 names the ranks that ended otherwise.
/// A rank that stopped on an error may be the only one to: the others may be blocked in a
/// collective call (MUMPS) waiting for it. If they have not all ended kRankWaitSeconds
/// later, it aborts the run with its status rather than leaving them hanging.
int end_of_run(int code, const std::string& errors) {
  namespace parallel = engine::parallel;
  const int me = parallel::rank();
  const bool failed = code >= static_cast<int>(ErrorKind::Deck);
  const auto spread = parallel::spread(code, failed ? std::optional<double>(kRankWaitSeconds) : std::nullopt);
  if (!spread) {
    std::string text;
    if (me != 0)  // rank 0 has printed its own error already; this rank's would be lost
      text = prefixed_lines("lunaster: rank " + std::to_string(me) + ": ", errors);
    text += "lunaster: rank " + std::to_string(me) + " stopped with exit status " + std::to_string(code) +
            " and the other ranks have not ended " + lua::budget_text(kRankWaitSeconds) +
            " s later (still computing, or waiting for this rank): the run is aborted\n";
    std::fflush(stdout);
    write_all(parallel::standard_error_fd(), text);  // a silenced rank's own standard error
    parallel::abort_run(code);
  }
  const auto texts = parallel::gather_texts(std::to_string(code) + "\n" + errors);
  if (spread->lowest != spread->highest && me == 0) {
    std::string report;
    for (std::size_t r = 1; r < texts.size(); ++r) {
      const auto newline = texts[r].find('\n');
      const int rank_code = std::stoi(texts[r].substr(0, newline));
      if (rank_code == code) continue;
      report += "lunaster: rank " + std::to_string(r) + " ended with exit status " + std::to_string(rank_code) +
                " (rank 0: " + std::to_string(code) + ")\n";
      report += prefixed_lines("lunaster: rank " + std::to_string(r) + ": ", texts[r].substr(newline + 1));
    }
    std::cerr << report << std::flush;
  }
  return spread->highest;
}

/// Starts this program again with glibc's allocator settings (lua/allocator_settings.h) added to
/// its environment, when it was started directly rather than through the launcher (lunaster,
/// lua/launcher.c, which sets them before this program's libraries are loaded). Not when
/// GLIBC_TUNABLES is already set (by the launcher, by the user, who may set it empty to keep
/// glibc's defaults, or by an earlier start: the processes it launches, `verify`'s runs and
/// mpirun's ranks, inherit it), under valgrind (the new program would run outside it) or a
/// sanitizer (its own allocator). Called from the executable's pre-initialisation array, before
/// the libraries' constructors (OpenBLAS starts its threads in its own), so that only the
/// loading is done twice; it allocates nothing. If the new start fails the run goes on as it is.
void start_with_allocator_settings(int /*argc*/, char** argv, char** envp) {
#if !LUNASTER_ALLOCATOR_SETTINGS
  (void)argv;
  (void)envp;
#else
  constexpr std::size_t kMaxVariables = 4096;
  static const char* environment[kMaxVariables + 2];
  std::size_t n = 0;
  for (char** e = envp; e && *e; ++e) {
    if (std::strncmp(*e, "GLIBC_TUNABLES=", 15) == 0) return;
    if (std::strncmp(*e, "LD_PRELOAD=", 11) == 0 && std::strstr(*e, "vgpreload")) return;
    if (n == kMaxVariables) return;
    environment[n++] = *e;
  }
  environment[n++] = "GLIBC_TUNABLES=" LUNASTER_ALLOCATOR_TUNABLES;
  environment[n] = nullptr;
  execve("/proc/self/exe", argv, const_cast<char* const*>(environment));
#endif
}

}  // namespace

// Run by the dynamic loader before any library's initialisation (ELF DT_PREINIT_ARRAY).
__attribute__((section(".preinit_array"), used)) void (*const allocator_settings_entry)(int, char**, char**) =
    &start_with_allocator_settings;

int main(int argc, char** argv) {
  namespace parallel = lunaster::engine::parallel;
  // Under mpirun every rank learns its number before anything runs (a single process
  // initialises MPI only if a solver needs it: engine/parallel/mpi_runtime.hpp); only rank 0
  // prints, and a rank's errors are kept for the end of the run.
  lunaster::engine::configure_blas();  // before OpenBLAS's idle workers spin for long
  const bool several_ranks = parallel::launched_by_mpi();
  std::stringbuf rank_errors;
  std::streambuf* const standard_error = std::cerr.rdbuf();
  if (several_ranks) {
    parallel::ensure_initialised();
    parallel::silence_other_ranks();
    if (!parallel::writes_output()) std::cerr.rdbuf(&rank_errors);
  }
  const int code = run_verb(std::vector<std::string>(argv + 1, argv + argc));
  if (!several_ranks) return code;
  std::cout.flush();
  const int agreed = end_of_run(code, rank_errors.str());
  std::cerr.rdbuf(standard_error);  // rank_errors ends with main
  return agreed;
}
