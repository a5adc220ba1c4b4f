#include "lua/verify.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "engine/io/atomic_file.hpp"
#include "lua/export_file.hpp"

extern char** environ;

namespace lunaster::lua {

namespace fs = std::filesystem;

namespace {

/// The command file an .export names (`F comm NAME D 1`), read leniently: the child run
/// reports whatever else is wrong with the file.
fs::path export_comm(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string f, type, path;
    if (words >> f >> type >> path && f == "F" && type == "comm")
      return fs::path(path).is_absolute() ? fs::path(path) : file.parent_path() / path;
  }
  return {};
}

}  // namespace

std::vector<fs::path> collect_decks(const std::vector<fs::path>& paths) {
  std::vector<fs::path> decks;
  for (const auto& path : paths) {
    if (!fs::is_directory(path)) {
      decks.push_back(path);
      continue;
    }
    for (auto it = fs::recursive_directory_iterator(path); it != fs::recursive_directory_iterator(); ++it) {
      // errors/: must-fail decks; lib/: modules the decks require, not decks.
      if (it->is_directory() && (it->path().filename() == "errors" || it->path().filename() == "lib")) {
        it.disable_recursion_pending();
        continue;
      }
      if (!it->is_regular_file()) continue;
      const auto ext = it->path().extension();
      if (ext == ".lua" || ext == ".export" || ext == ".comm") decks.push_back(it->path());
    }
  }
  // A .comm named by an .export of the list runs through that .export only.
  std::set<fs::path> named;
  for (const auto& deck : decks)
    if (deck.extension() == ".export")
      if (auto comm = export_comm(deck); !comm.empty()) named.insert(comm.lexically_normal());
  decks.erase(std::remove_if(decks.begin(), decks.end(),
                             [&](const fs::path& d) {
                               return d.extension() == ".comm" && named.count(d.lexically_normal());
                             }),
              decks.end());
  std::sort(decks.begin(), decks.end());
  decks.erase(std::unique(decks.begin(), decks.end()), decks.end());
  return decks;
}

void count_checks(const std::string& output, int& n_ok, int& n_nook) {
  n_ok = n_nook = 0;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(" OK ", 0) == 0 || line.rfind("OK ", 0) == 0) ++n_ok;
    else if (line.rfind("NOOK ", 0) == 0 || line.rfind(" NOOK ", 0) == 0) ++n_nook;
  }
}

std::vector<CodeAsterComparison> code_aster_comparisons(const std::string& output) {
  std::vector<CodeAsterComparison> out;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    // "<status> CODE_ASTER     <what>  refe=<code_aster>  calc=<lunaster>  err=<d>  tol=<t>  <critere>"
    if (line.size() < 16 || line.compare(5, 11, "CODE_ASTER ") != 0) continue;
    const auto refe = line.find("  refe="), calc = line.find("  calc="), err = line.find("  err="),
               tol = line.find("  tol=");
    if (refe == std::string::npos || calc == std::string::npos || err == std::string::npos || tol == std::string::npos)
      continue;
    CodeAsterComparison c;
    const auto start = line.find_first_not_of(' ', 16);
    c.check = line.substr(start, refe - start);
    try {
      c.code_aster = std::stod(line.substr(refe + 7));
      c.lunaster = std::stod(line.substr(calc + 7));
      c.difference = std::stod(line.substr(err + 6));
      c.tolerance = std::stod(line.substr(tol + 6));
    } catch (const std::exception&) {
      continue;
    }
    out.push_back(c);
  }
  return out;
}

fs::path deck_out_dir(const fs::path& out_dir, const fs::path& deck) {
  return out_dir / (deck.extension() == ".lua" ? deck.stem() : deck.filename());
}

std::string deck_status(int exit_code, int n_nook, int n_ok) {
  if (exit_code == 0) return n_nook ? "NOOK" : n_ok ? "OK" : "NO_CHECK";
  if (exit_code == 1) return "NOOK";
  if (exit_code == 5) return "TIMEOUT";
  if (exit_code == 6) return "OUT_OF_MEMORY";
  return "ERROR";
}

Budget verify_budget(const fs::path& deck, const Budget& overrides, int ranks) {
  Budget header;
  try {
    if (deck.extension() == ".export") header = read_export(deck).budget;
    else if (deck.extension() != ".comm") header = read_budget_header(deck);
  } catch (const std::exception&) {
    // The child reports the malformed header as a deck error; the defaults guard it meanwhile.
  }
  Budget budget = override_budget(header, overrides);
  if (!budget.seconds) budget.seconds = kVerifyDefaultSeconds;
  if (!budget.megabytes) budget.megabytes = std::floor(default_memory_budget_mb() / std::max(1, ranks));
  return budget;
}

fs::path find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

DeckOutcome run_child(const fs::path& executable, const fs::path& deck, const fs::path& out_dir, const Budget& budget,
                      const std::vector<std::string>& extra_args, const std::vector<std::string>& launcher) {
  DeckOutcome outcome;
  outcome.deck = deck;
  outcome.time_limit = budget.seconds.value_or(0.0);
  outcome.memory_limit_mb = budget.megabytes.value_or(0.0);
  const auto start = std::chrono::steady_clock::now();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    outcome.status = "ERROR";
    outcome.output = "cannot create a pipe";
    return outcome;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  std::vector<std::string> words = launcher;
  words.insert(words.end(), {executable.string(), "run", deck.string(), "--out", out_dir.string()});
  if (budget.seconds) words.insert(words.end(), {"--time-limit", budget_text(*budget.seconds)});
  if (budget.megabytes) words.insert(words.end(), {"--memory-limit", budget_text(*budget.megabytes)});
  words.insert(words.end(), extra_args.begin(), extra_args.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  // Each mpirun its own OpenMPI session directory tree: the jobs that verify -j runs at once
  // would otherwise share /tmp/ompi.<host>.<uid> (or the user's orte_tmpdir_base), which
  // two of them create at once or the first to end removes while another creates its
  // directory in it: that one's MPI_Init fails ("mkdir ... File exists"). Below the user's
  // base when one is set.
  std::vector<char*> envp;
  std::string session_setting;
  fs::path session;
  if (!launcher.empty()) {
    const char* base = std::getenv("OMPI_MCA_orte_tmpdir_base");
    std::string pattern = ((base && *base ? fs::path(base) : fs::temp_directory_path()) / "lunaster-mpi-XXXXXX").string();
    if (mkdtemp(pattern.data())) {
      session = pattern;
      session_setting = "OMPI_MCA_orte_tmpdir_base=" + pattern;
    }
  }
  for (char** e = environ; *e; ++e)
    if (session_setting.empty() || std::strncmp(*e, "OMPI_MCA_orte_tmpdir_base=", 26) != 0) envp.push_back(*e);
  if (!session_setting.empty()) envp.push_back(session_setting.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  const std::string program = words.front();
  int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  bool killed = false;
  if (rc == 0) {
    // Wall-clock watchdog: the child stops itself at its limit; past the grace it is killed.
    // mpirun is first asked to end its run (SIGTERM): killed outright, it would leave its
    // ranks running.
    using clock = std::chrono::steady_clock;
    const auto seconds = [](double s) {
      return std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(s));
    };
    const double grace = kVerifyKillGraceSeconds + (launcher.empty() ? 0.0 : kVerifyMpiKillGraceSeconds);
    std::optional<clock::time_point> kill_at;
    if (budget.seconds) kill_at = start + seconds(*budget.seconds + grace);
    bool terminated = false;
    char buffer[4096];
    pollfd reader{fds[0], POLLIN, 0};
    for (;;) {
      int timeout_ms = -1;
      if (kill_at && !killed)
        timeout_ms = static_cast<int>(std::max<long long>(
            0, std::chrono::duration_cast<std::chrono::milliseconds>(*kill_at - clock::now()).count() + 1));
      const int ready = poll(&reader, 1, timeout_ms);
      if (ready < 0 && errno == EINTR) continue;
      if (ready == 0) {
        if (!launcher.empty() && !terminated) {
          kill(pid, SIGTERM);  // mpirun ends its ranks
          terminated = true;
          kill_at = clock::now() + seconds(kVerifyMpiTermSeconds);
          continue;
        }
        kill(pid, SIGKILL);  // the child only: it starts no processes of its own (or mpirun ignored SIGTERM)
        killed = true;
        continue;
      }
      const ssize_t n = read(fds[0], buffer, sizeof buffer);
      if (n > 0) outcome.output.append(buffer, static_cast<std::size_t>(n));
      else if (n < 0 && errno == EINTR) continue;
      else break;
    }
    killed = killed || terminated;
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
    }
    outcome.exit_code = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
    if (killed)
      outcome.output += "\nlunaster verify: " + deck.string() + ": time limit of " + budget_text(*budget.seconds) +
                        " s exceeded; killed after " + budget_text(*budget.seconds + grace) + " s\n";
    else if (WIFSIGNALED(wstatus))
      outcome.output += "\nkilled by signal " + std::to_string(WTERMSIG(wstatus)) + "\n";
  } else {
    outcome.output = "cannot start " + program;
  }
  if (!session.empty()) {
    std::error_code ignored;
    fs::remove_all(session, ignored);
  }
  close(fds[0]);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  count_checks(outcome.output, outcome.n_ok, outcome.n_nook);
  outcome.comparisons = code_aster_comparisons(outcome.output);
  outcome.status = killed ? "TIMEOUT" : deck_status(outcome.exit_code, outcome.n_nook, outcome.n_ok);
  return outcome;
}

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20 && ch != '\n' && ch != '\t') out += ' ';
        else out += ch;
    }
  }
  return out;
}

std::string json_escape(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", ch);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

/// The last `n_lines` lines of `text` (the end of a failed deck's output says why).
std::string tail(const std::string& text, int n_lines) {
  std::size_t pos = text.size();
  if (pos > 0 && text[pos - 1] == '\n') --pos;
  for (int i = 0; i < n_lines && pos != std::string::npos && pos > 0; ++i) pos = text.rfind('\n', pos - 1);
  std::string out = (pos == std::string::npos || pos == 0) ? text : "[...]" + text.substr(pos);
  if (!out.empty() && out.back() != '\n') out += '\n';
  return out;
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9e", v);
  return buf;
}

std::string seconds_text(double s) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << s;
  return out.str();
}

}  // namespace

std::string junit_xml(const std::vector<DeckOutcome>& outcomes) {
  int failures = 0, errors = 0;
  double total = 0.0;
  for (const auto& o : outcomes) {
    failures += o.status == "NOOK" || o.status == "NO_CHECK";
    errors += o.status == "ERROR" || o.status == "TIMEOUT" || o.status == "OUT_OF_MEMORY";
    total += o.seconds;
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n"
      << "  <testsuite name=\"lunaster.verify\" tests=\"" << outcomes.size() << "\" failures=\"" << failures
      << "\" errors=\"" << errors << "\" time=\"" << seconds_text(total) << "\">\n";
  for (const auto& o : outcomes) {
    out << "    <testcase classname=\"decks\" name=\"" << xml_escape(deck_out_dir("", o.deck).string()) << "\" file=\""
        << xml_escape(o.deck.string()) << "\" time=\"" << seconds_text(o.seconds) << "\">";
    if (!o.comparisons.empty()) {
      // The migration report: lunaster against code_aster's VALE_CALC, one property per check.
      out << "\n      <properties>";
      for (const auto& c : o.comparisons)
        out << "\n        <property name=\"code_aster: " << xml_escape(c.check) << "\" value=\"lunaster="
            << number_text(c.lunaster) << " code_aster=" << number_text(c.code_aster)
            << " difference=" << number_text(c.difference) << " tolerance=" << number_text(c.tolerance) << "\"/>";
      out << "\n      </properties>\n    ";
    }
    if (o.status == "NOOK")
      out << "\n      <failure message=\"" << o.n_nook << " NOOK check(s)\">" << xml_escape(o.output) << "</failure>\n    ";
    else if (o.status == "NO_CHECK")
      out << "\n      <failure type=\"NO_CHECK\" message=\"no check ran (no TEST_RESU or TEST_TABLE)\">" << xml_escape(o.output)
          << "</failure>\n    ";
    else if (o.status == "ERROR")
      out << "\n      <error type=\"ERROR\" message=\"exit status " << o.exit_code << "\">" << xml_escape(o.output)
          << "</error>\n    ";
    else if (o.status == "TIMEOUT")
      out << "\n      <error type=\"TIMEOUT\" message=\"time limit of " << budget_text(o.time_limit) << " s exceeded\">"
          << xml_escape(o.output) << "</error>\n    ";
    else if (o.status == "OUT_OF_MEMORY")
      out << "\n      <error type=\"OUT_OF_MEMORY\" message=\"memory limit of " << budget_text(o.memory_limit_mb)
          << " MB exceeded\">" << xml_escape(o.output) << "</error>\n    ";
    out << "</testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  return out.str();
}

std::string json_report(const std::vector<DeckOutcome>& outcomes) {
  int passed = 0;
  std::ostringstream out;
  out << "{\n  \"decks\": [";
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const auto& o = outcomes[i];
    passed += o.status == "OK";
    out << (i ? "," : "") << "\n    {\"deck\": " << json_escape(o.deck.string()) << ", \"status\": \"" << o.status
        << "\", \"exit_code\": " << o.exit_code << ", \"checks_ok\": " << o.n_ok << ", \"checks_nook\": " << o.n_nook
        << ", \"seconds\": " << seconds_text(o.seconds) << ", \"time_limit\": " << budget_text(o.time_limit)
        << ", \"memory_limit_mb\": " << budget_text(o.memory_limit_mb);
    if (!o.comparisons.empty()) {
      out << ", \"code_aster\": [";
      for (std::size_t k = 0; k < o.comparisons.size(); ++k) {
        const auto& c = o.comparisons[k];
        out << (k ? ", " : "") << "{\"check\": " << json_escape(c.check) << ", \"lunaster\": " << number_text(c.lunaster)
            << ", \"code_aster\": " << number_text(c.code_aster) << ", \"difference\": " << number_text(c.difference)
            << ", \"tolerance\": " << number_text(c.tolerance)
            << ", \"within\": " << (c.difference <= c.tolerance ? "true" : "false") << "}";
      }
      out << "]";
    }
    out << ", \"output\": " << json_escape(o.output) << "}";
  }
  out << "\n  ],\n  \"passed\": " << passed << ",\n  \"failed\": " << outcomes.size() - passed << "\n}\n";
  return out.str();
}

int verify(const VerifyOptions& options, std::ostream& out) {
  std::vector<fs::path> paths = options.paths;
  if (paths.empty()) paths.push_back("testcases");
  for (const auto& p : paths)
    if (!fs::exists(p)) {
      out << "verify: no such deck or folder: " << p.string() << "\n";
      return 2;
    }
  std::vector<std::string> launcher;
  if (options.ranks > 0) {
    const fs::path mpirun = find_on_path("mpirun");
    if (mpirun.empty()) {
      out << "verify: --np " << options.ranks
          << " runs each deck under mpirun, and there is no mpirun on the PATH (Debian: apt-get install openmpi-bin)\n";
      return 2;
    }
    launcher = {mpirun.string(), "-np", std::to_string(options.ranks)};
  }
  const auto decks = collect_decks(paths);
  std::vector<DeckOutcome> outcomes(decks.size());
  // A deck under --np N keeps N processes busy (MPI ranks wait for each other by polling).
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int jobs = options.jobs > 0 ? options.jobs : std::max(1, cores / std::max(1, options.ranks));
  jobs = std::min<int>(jobs, std::max<std::size_t>(decks.size(), 1));
  std::atomic<std::size_t> next{0};
  std::vector<std::string> extra;
  if (!options.vale_calc_report) extra.push_back("--vale-calc=check");
  if (!options.solveur.empty()) extra.push_back("--solveur=" + options.solveur);
  auto worker = [&] {
    for (std::size_t i = next++; i < decks.size(); i = next++)
      outcomes[i] = run_child(options.executable, decks[i], deck_out_dir(options.out_dir, decks[i]),
                              verify_budget(decks[i], options.budget, options.ranks), extra, launcher);
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);
  for (auto& t : threads) t.join();

  std::size_t width = 4;
  for (const auto& d : decks) width = std::max(width, d.string().size());
  int passed = 0;
  out << std::left << std::setw(static_cast<int>(width)) << "deck" << "  status         checks OK/NOOK   time (s)\n";
  for (const auto& o : outcomes) {
    passed += o.status == "OK";
    std::string checks = std::to_string(o.n_ok) + "/" + std::to_string(o.n_nook);
    out << std::left << std::setw(static_cast<int>(width)) << o.deck.string() << "  " << std::setw(13) << o.status << "  "
        << std::setw(15) << checks << "  " << std::right << std::setw(8) << seconds_text(o.seconds) << "\n";
  }
  // The migration report: converted code_aster cases against code_aster's own VALE_CALC.
  std::size_t n_compared = 0, n_beyond = 0;
  for (const auto& o : outcomes) {
    for (const auto& c : o.comparisons) {
      if (!n_compared++) out << "\ncomparisons with code_aster (VALE_CALC of .comm cases): lunaster, code_aster, relative difference\n";
      n_beyond += c.difference > c.tolerance;
      out << "  " << o.deck.filename().string() << "  " << c.check << "  " << number_text(c.lunaster) << "  "
          << number_text(c.code_aster) << "  " << std::scientific << std::setprecision(2) << c.difference
          << (c.difference > c.tolerance ? "  beyond " : "  within ") << c.tolerance << std::defaultfloat << "\n";
    }
  }
  if (n_compared)
    out << n_compared << " comparison(s), " << n_beyond << " beyond tolerance"
        << (options.vale_calc_report ? " (reported, not counted: code_aster's values; --vale-calc=check counts them)"
                                     : " (counted as checks: --vale-calc=check)")
        << "\n\n";
  for (const auto& o : outcomes) {
    if (o.status == "OK") continue;
    out << "\n---- " << o.deck.string() << " (" << o.status << ", exit " << o.exit_code;
    if (o.status == "TIMEOUT") out << ", time limit " << budget_text(o.time_limit) << " s";
    if (o.status == "OUT_OF_MEMORY") out << ", memory limit " << budget_text(o.memory_limit_mb) << " MB";
    out << ")\n" << tail(o.output, 40);
  }
  // Reports are replaced atomically: an interrupted run leaves the previous report whole.
  if (!options.junit_file.empty())
    engine::write_file_atomically(options.junit_file, [&](std::ostream& f) { f << junit_xml(outcomes); });
  if (!options.json_file.empty())
    engine::write_file_atomically(options.json_file, [&](std::ostream& f) { f << json_report(outcomes); });
  const int failed = static_cast<int>(outcomes.size()) - passed;
  out << passed << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}

}  // namespace lunaster::lua
