// Deck budgets: the header comment, the command-line override, and their enforcement inside
// the process (Lua hook and allocator, watchdog hard stop for C++ code that never returns).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <filesystem>
#include <fstream>
#include <new>
#include <regex>
#include <sstream>
#include <vector>
#include <thread>

#include "engine/core/memory.hpp"
#include "lua/budget.hpp"
#include "lua/runner.hpp"

using namespace lunaster;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-lua-budget";
  fs::create_directories(dir);
  return dir;
}

fs::path write_deck(const std::string& name, const std::string& text) {
  const fs::path path = scratch() / name;
  std::ofstream(path) << text;
  return path;
}

/// The DeckError text of read_budget_header on `text`, "" if it is accepted.
std::string header_error(const std::string& text) {
  try {
    lua::read_budget_header(write_deck("h.lua", text));
  } catch (const DeckError& e) {
    return e.what();
  }
  return "";
}

/// What these tests assert of time does not depend on the machine's load: a stop comes never
/// before its limit (the steady clock cannot run early), and it is the budget's stop (the exit
/// status, the message naming the limit and the line); how long after the limit it comes depends
/// on the scheduler (`ctest -j` runs deck solves beside these tests), so above the limit only a
/// hang guard is checked, far beyond any stop and far below what the runs stopped would take.
constexpr double kHangGuardSeconds = 30.0;

/// A death test's child writes the moment its run starts here (steady_clock is the machine's
/// monotonic clock, the same in both processes), so that the parent times the run itself and
/// not the child's start-up (the re-executed test binary, slow under a sanitizer).
fs::path child_start_file(const std::string& name) { return scratch() / (name + ".start"); }

void record_child_start(const fs::path& file) {
  std::ofstream(file) << std::chrono::steady_clock::now().time_since_epoch().count() << "\n";
}

/// Seconds from the child's recorded start to now.
double seconds_since_child_start(const fs::path& file) {
  std::ifstream in(file);
  std::chrono::steady_clock::rep ticks = 0;
  if (!(in >> ticks)) return -1.0;  // the child never started its run
  const std::chrono::steady_clock::time_point start{std::chrono::steady_clock::duration(ticks)};
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

catalog::ConceptPtr no_op(const catalog::Args&, cmd::Session&) { return nullptr; }
catalog::ConceptPtr spin_forever(const catalog::Args&, cmd::Session&) {
  volatile unsigned long long n = 0;
  for (;;) n = n + 1;  // a C++ solve that never returns to Lua
}
catalog::ConceptPtr eat_memory(const catalog::Args&, cmd::Session&) {
  std::vector<char*> blocks;
  for (;;) {
    blocks.push_back(new char[16 << 20]);
    std::memset(blocks.back(), 1, 16 << 20);  // resident, not only reserved
  }
}
catalog::ConceptPtr throw_bad_alloc(const catalog::Args&, cmd::Session&) { throw std::bad_alloc(); }
catalog::ConceptPtr factors_do_not_fit(const catalog::Args&, cmd::Session&) {
  throw SolveError::out_of_memory("MUMPS", 1000, "during factorisation, INFOG(1) = -9");
}

/// run_deck on `deck` with handler `debut` for DEBUT and no-ops elsewhere.
struct Outcome {
  int code = -1;
  double seconds = 0.0;
  std::string err;
};
Outcome run(const fs::path& deck, const lua::Budget& overrides = {}, cmd::Handler debut = no_op) {
  std::ostringstream out, err;
  Log log(out, 0);
  cmd::Session session(log);
  const auto start = std::chrono::steady_clock::now();
  Outcome result;
  result.code = lua::run_deck(
      deck, session, [debut](const std::string& name) -> cmd::Handler { return name == "DEBUT" ? debut : no_op; }, err,
      overrides);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.err = err.str();
  return result;
}

/// Runs decks inside this process: the watchdog's hard stop, kGrace past the deadline, would end
/// the whole test binary if the Lua hook came later than that (the deck's thread not run for half
/// a second, which a loaded machine can do), so these tests give the hard stop a grace as long as
/// the hang guard. The hook still has to stop each deck: a deck it missed would be ended by the
/// hard stop, failing the test binary. The death tests (BudgetRunDeathTest) keep kGrace.
class BudgetRun : public ::testing::Test {
 protected:
  void SetUp() override {
    lua::BudgetGuard::set_grace(std::chrono::milliseconds(static_cast<long long>(kHangGuardSeconds * 1000)));
  }
  void TearDown() override { lua::BudgetGuard::set_grace(lua::BudgetGuard::kGrace); }
};

}  // namespace

TEST(BudgetHeader, ReadsTimeAndMemoryFromTheLeadingComments) {
  auto budget = lua::read_budget_header(
      write_deck("a.lua", "#!/usr/bin/env lunaster\n-- A deck.\n\n-- lunaster: time_limit=60 memory_limit=512\nDEBUT()\n"));
  ASSERT_TRUE(budget.seconds && budget.megabytes);
  EXPECT_EQ(*budget.seconds, 60.0);
  EXPECT_EQ(*budget.megabytes, 512.0);
  budget = lua::read_budget_header(write_deck("b.lua", "--lunaster: time_limit = 1.5\n-- lunaster: memory_limit= 64\n"));
  EXPECT_EQ(budget.seconds.value_or(0), 1.5);
  EXPECT_EQ(budget.megabytes.value_or(0), 64.0);
  // Remarks in the "-- lunaster:" style of the decks are not budgets, at the top or below the code.
  budget = lua::read_budget_header(write_deck(
      "c.lua", "-- lunaster: largest relative error 2.7e-14 on LAGS_C\nDEBUT()\n-- lunaster: timing 3 s on 2 cores\n"));
  EXPECT_FALSE(budget.seconds || budget.megabytes);
  EXPECT_FALSE(lua::read_budget_header(scratch() / "missing.lua").seconds);
}

TEST(BudgetHeader, MalformedBudgetsNameFileLineAndKey) {
  const std::string file = (scratch() / "h.lua").string();
  EXPECT_EQ(header_error("-- lunaster: time_limit=abc\n"),
            file + ":1: budget header: time_limit: expected a positive number of seconds, got 'abc'");
  EXPECT_EQ(header_error("-- title\n-- lunaster: memory_limit=-5\n"),
            file + ":2: budget header: memory_limit: expected a positive number of MB, got '-5'");
  EXPECT_EQ(header_error("-- lunaster: time_limt=60\n"),
            file + ":1: budget header: expected time_limit=SECONDS or memory_limit=MB, got 'time_limt=60'\n"
                   "    did you mean 'time_limit'?");
  EXPECT_EQ(header_error("-- lunaster: time_limit=1\n-- lunaster: time_limit=2\n"),
            file + ":2: budget header: time_limit: expected one value, got a second one (the first is on line 1)");
  EXPECT_EQ(header_error("DEBUT()\n-- lunaster: time_limit=5\n"),
            file + ":2: budget header: expected the '-- lunaster:' budget line in the comment block at the top of "
                   "the deck, got it below the first line of code");
  EXPECT_EQ(header_error("-- lunaster: time_limit=0\n"),
            file + ":1: budget header: time_limit: expected a positive number of seconds, got '0'");
}

TEST(BudgetHeader, CommandLineValuesOverrideTheHeader) {
  lua::Budget header, cli;
  header.seconds = 60;
  header.megabytes = 512;
  cli.seconds = 2;
  const auto budget = lua::override_budget(header, cli);
  EXPECT_EQ(budget.seconds.value_or(0), 2.0);
  EXPECT_EQ(budget.megabytes.value_or(0), 512.0);
  EXPECT_EQ(lua::parse_budget_value("0.5").value_or(0), 0.5);
  for (const char* bad : {"", "0", "-1", "abc", "2s", "inf", "nan", "1e400"})
    EXPECT_FALSE(lua::parse_budget_value(bad)) << bad;
  EXPECT_EQ(lua::budget_text(300), "300");
  EXPECT_EQ(lua::budget_text(0.25), "0.25");
  EXPECT_GT(lua::default_memory_budget_mb(), 0.0);
  EXPECT_GT(engine::resident_bytes(), 0u);
}

TEST(Budget, MemoryLimitIsWhatTheSolversPlanForWhileTheDeckRuns) {
  // MUMPS's GESTION_MEMOIRE='AUTO' reads the budget from the engine: set while a guard with a
  // memory limit lives, cleared when it stops; a time limit alone sets none.
  ASSERT_EQ(engine::memory_budget(), 0u);
  {
    lua::Budget budget;
    budget.megabytes = 300;
    lua::BudgetGuard guard(budget, "deck.lua");
    EXPECT_EQ(engine::memory_budget(), std::size_t{300} << 20);
    guard.stop();
    EXPECT_EQ(engine::memory_budget(), 0u);
  }
  lua::Budget time_only;
  time_only.seconds = 60;
  lua::BudgetGuard guard(time_only, "deck.lua");
  EXPECT_EQ(engine::memory_budget(), 0u);
}

TEST(Budget, ProcessStartIsWhenTheProcessWasCreated) {
  // A child asks 0.2 s after its start: process_start() lies between the parent's moment before
  // fork() and the child's first moment (the kernel keeps the start to the end of its clock tick,
  // so up to a tick later), not at the moment of the call. Bounded by two readings of the same
  // clock around the creation, whatever the scheduler does between them.
  using clock = std::chrono::steady_clock;
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const clock::rep before_fork = clock::now().time_since_epoch().count();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const clock::rep first = clock::now().time_since_epoch().count();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const clock::rep times[3] = {first, lua::process_start().time_since_epoch().count(),
                                 clock::now().time_since_epoch().count()};
    const ssize_t written = write(fds[1], times, sizeof times);
    _exit(written == sizeof times ? 0 : 1);
  }
  close(fds[1]);
  clock::rep times[3] = {};
  ASSERT_EQ(read(fds[0], times, sizeof times), static_cast<ssize_t>(sizeof times));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  const auto at = [](clock::rep t) { return clock::time_point(clock::duration(t)); };
  const auto first = at(times[0]), start = at(times[1]), asked = at(times[2]);
  const auto tick = std::chrono::microseconds(1000000 / sysconf(_SC_CLK_TCK));
  const auto skew = std::chrono::milliseconds(1);  // the steady and boot clocks read one after the other
  EXPECT_GE(start, at(before_fork) - skew);
  EXPECT_LE(start, first + tick + skew);
  EXPECT_GE(asked - start, std::chrono::milliseconds(200) - tick - skew);  // not the moment of the call
}

TEST_F(BudgetRun, TheTimeLimitCountsFromTheStartGiven) {
  // A run whose process started 60 s before the deck (as a slow start would, exaggerated): a
  // 60.1 s limit leaves the deck 0.1 s, and it stops then, not 60.1 s after the deck began.
  const auto deck = write_deck("late.lua", "DEBUT()\nlocal i = 0\nwhile true do i = i + 1 end\n");
  std::ostringstream out, err;
  Log log(out, 0);
  cmd::Session session(log);
  lua::Budget budget;
  budget.seconds = 60.1;
  const auto now = std::chrono::steady_clock::now();
  const int code = lua::run_deck(
      deck, session, [](const std::string&) -> cmd::Handler { return no_op; }, err, budget, nullptr,
      now - std::chrono::seconds(60));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count();
  EXPECT_EQ(code, 5) << err.str();
  // The loop's line (3), or an earlier one if the 0.1 s left was up before the deck reached its
  // loop (a sanitizer build or a loaded machine; seen under make test-asan): which line is the
  // scheduler's, LuaLoopIsStoppedAtTheDeckLineAndPcallCannotCatchIt checks the line itself.
  EXPECT_TRUE(std::regex_search(err.str(), std::regex("late\\.lua:[123]: time limit of 60\\.1 s exceeded")))
      << err.str();
  EXPECT_GE(seconds, 0.099);  // the 0.1 s left, on the clock the deadline was set on
  EXPECT_LT(seconds, kHangGuardSeconds);  // counted from the deck's own start it would stop at 60.1 s
}

TEST_F(BudgetRun, LuaLoopIsStoppedAtTheDeckLineAndPcallCannotCatchIt) {
  // Header budget 0.5 s; the deck catches the first error and tries to go on.
  const auto deck = write_deck("loop.lua",
                               "-- lunaster: time_limit=0.5\nDEBUT()\nlocal ok = pcall(function()\n"
                               "  while true do end\nend)\nlocal i = 0\nwhile true do i = i + 1 end\n");
  const Outcome r = run(deck);
  EXPECT_EQ(r.code, 5) << r.err;
  // The first instruction after pcall raises again: line 6 (had pcall kept the deck going, the
  // watchdog's hard stop would have ended this process past the grace; run_deck returned instead).
  EXPECT_NE(r.err.find("loop.lua:6: time limit of 0.5 s exceeded"), std::string::npos) << r.err;
  EXPECT_GE(r.seconds, 0.5);
  EXPECT_LT(r.seconds, kHangGuardSeconds);
  // The command line wins over the header: a header of 60 s, 0.2 s given.
  const auto long_header = write_deck("loop60.lua", "-- lunaster: time_limit=60\nDEBUT()\nlocal i = 0\n"
                                                    "while true do i = i + 1 end\n");
  lua::Budget cli;
  cli.seconds = 0.2;
  const Outcome shorter = run(long_header, cli);
  EXPECT_EQ(shorter.code, 5);
  EXPECT_NE(shorter.err.find("time limit of 0.2 s exceeded"), std::string::npos) << shorter.err;
  EXPECT_GE(shorter.seconds, 0.2);
  EXPECT_LT(shorter.seconds, kHangGuardSeconds);  // the header's limit would have given 60 s
}

TEST(BudgetRunDeathTest, LuaDataBeyondTheMemoryBudgetIsOutOfMemory) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto deck = write_deck("grow.lua", "local t, i = {}, 0\nwhile true do i = i + 1; t[i] = i end\n");
  lua::Budget cli;
  cli.megabytes = 64;
  // Either the Lua allocator refuses (a clean error, in a Release build) or the resident memory
  // sampler stops the process first (a sanitizer's quarantine keeps freed blocks resident).
  EXPECT_EXIT(
      {
        const Outcome r = run(deck, cli);
        std::cerr << r.err;
        std::_Exit(r.code);  // no atexit handlers (a leak checker) in the child
      },
      ::testing::ExitedWithCode(6), "grow\\.lua: memory limit of 64 MB exceeded");
}

TEST_F(BudgetRun, DeckWithinItsBudgetIsUntouched) {
  lua::Budget cli;
  cli.seconds = 60;  // far above the loop's milliseconds, however loaded the machine
  const Outcome ok = run(write_deck("small.lua", "-- lunaster: memory_limit=512\nlocal t = {}\nfor i = 1, 1e5 do t[i] = i end\n"),
                     cli);
  EXPECT_EQ(ok.code, 0) << ok.err;
}

TEST_F(BudgetRun, AllocationFailuresInCommandsAreOutOfMemory) {
  const auto deck = write_deck("debut.lua", "DEBUT()\n");
  Outcome r = run(deck, {}, throw_bad_alloc);
  EXPECT_EQ(r.code, 6) << r.err;
  EXPECT_NE(r.err.find("debut.lua:1: DEBUT: out of memory"), std::string::npos) << r.err;
  r = run(deck, {}, factors_do_not_fit);
  EXPECT_EQ(r.code, 6) << r.err;
  EXPECT_NE(r.err.find("MUMPS: out of memory factorising 1000 equations"), std::string::npos) << r.err;
}

TEST(BudgetRunDeathTest, LongCppCommandIsStoppedAfterTheGrace) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto deck = write_deck("spin.lua", "-- lunaster: time_limit=1\nDEBUT()\n");
  const fs::path started = child_start_file("spin");
  fs::remove(started);
  EXPECT_EXIT(
      {
        record_child_start(started);
        run(deck, {}, spin_forever);
      },
      ::testing::ExitedWithCode(5),
      "spin\\.lua: time limit of 1 s exceeded while running .*spin\\.lua:2: DEBUT; the run is stopped");
  // Not before the budget (1 s) and the grace (0.5 s), measured from the run's start in the
  // child; spin_forever never returns, so the exit status and message above are the watchdog's.
  const double seconds = seconds_since_child_start(started);
  EXPECT_GE(seconds, 1.5);
  EXPECT_LT(seconds, kHangGuardSeconds);
}

TEST_F(BudgetRun, PcallInALoopCannotKeepTheDeckGoing) {
  const auto deck =
      write_deck("pcall_loop.lua", "-- lunaster: time_limit=0.5\nwhile true do pcall(function() while true do end end) end\n");
  // Had pcall kept the deck going, the watchdog's hard stop would have ended this process past
  // the grace; run_deck returned the Lua error instead.
  const Outcome r = run(deck);
  EXPECT_EQ(r.code, 5) << r.err;
  EXPECT_NE(r.err.find("pcall_loop.lua:2: time limit of 0.5 s exceeded"), std::string::npos) << r.err;
  EXPECT_GE(r.seconds, 0.5);
  EXPECT_LT(r.seconds, kHangGuardSeconds);
}

TEST(BudgetRunDeathTest, LongLuaLibraryCallIsStoppedAfterTheGrace) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // Backtracking inside string.find (C code of the Lua library, no instruction to hook).
  const auto deck = write_deck("backtrack.lua", "-- lunaster: time_limit=0.5\nlocal s = ('a'):rep(10000)\n"
                                                "local found = s:find('.-.-.-.-b')\n");
  const fs::path started = child_start_file("backtrack");
  fs::remove(started);
  EXPECT_EXIT(
      {
        record_child_start(started);
        run(deck);
      },
      ::testing::ExitedWithCode(5),
      "backtrack\\.lua: time limit of 0\\.5 s exceeded in the deck's Lua code; the run is stopped");
  // Not before the budget (0.5 s) and the grace (0.5 s), measured from the run's start in the child.
  const double seconds = seconds_since_child_start(started);
  EXPECT_GE(seconds, 1.0);
  EXPECT_LT(seconds, kHangGuardSeconds);
}

TEST(BudgetRunDeathTest, CppMemoryBeyondTheBudgetIsStopped) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // The limit must lie above the process's own start (the re-executed test binary): under a
  // sanitizer that is already 265 MB resident (measured at 9385219, /usr/bin/time -v), which a
  // 256 MB limit met before DEBUT began. eat_memory grows without bound, so either is reached.
#if defined(__SANITIZE_ADDRESS__)
  const std::string limit = "1024";
#else
  const std::string limit = "256";
#endif
  const auto deck = write_deck("eat.lua", "-- lunaster: memory_limit=" + limit + "\nDEBUT()\n");
  EXPECT_EXIT(run(deck, {}, eat_memory), ::testing::ExitedWithCode(6),
              "eat\\.lua: memory limit of " + limit +
                  " MB exceeded \\(resident memory [0-9]+ MB\\) while running .*eat\\.lua:2: DEBUT");
}
