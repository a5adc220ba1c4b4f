// `lunaster verify`: deck collection, TEST_RESU line parsing, child processes and reports.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "lua/verify.hpp"

using namespace lunaster::lua;
namespace fs = std::filesystem;

TEST(Verify, CountsTestResuLines) {
  int ok = 0, nook = 0;
  count_checks(" OK  ANALYTIQUE  DEPL  A  DY  refe=-5.0e-02  calc=-4.9e-02\n"
               "NOOK ANALYTIQUE  DEPL  B  DY  refe=-5.0e-02  calc=-4.0e-02\n"
               "t.lua:3: TEST_RESU{ ... OK ... }\n"
               " OK  NON_REGRESSION  DEPL  A  DX\n",
               ok, nook);
  EXPECT_EQ(ok, 2);
  EXPECT_EQ(nook, 1);
  EXPECT_EQ(deck_status(0, 0, 1), "OK");
  EXPECT_EQ(deck_status(0, 0), "NO_CHECK");
  EXPECT_EQ(deck_status(0, 1), "NOOK");
  EXPECT_EQ(deck_status(1, 1), "NOOK");
  EXPECT_EQ(deck_status(2, 0), "ERROR");
  EXPECT_EQ(deck_status(-1, 0), "ERROR");
}

namespace {
/// A stand-in for the lunaster binary: `exe run DECK --out DIR` prints the deck's
/// lines except "exit N" and exits with N.
fs::path fake_executable(const fs::path& dir) {
  fs::path exe = dir / "fake_lunaster.sh";
  std::ofstream(exe) << "#!/bin/sh\ngrep -v '^exit' \"$2\"\nexit $(sed -n 's/^exit //p' \"$2\")\n";
  fs::permissions(exe, fs::perms::owner_all);
  return exe;
}
}  // namespace

TEST(Verify, RunsDecksInParallelAndWritesReports) {
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-verify";
  fs::remove_all(dir);
  fs::create_directories(dir / "suite" / "errors");
  fs::create_directories(dir / "suite" / "lib");
  std::ofstream(dir / "suite" / "lib" / "module.lua") << "return {}\n";
  std::ofstream(dir / "suite" / "a_ok.lua") << " OK  x\n OK  y\nexit 0\n";
  std::ofstream(dir / "suite" / "b_nook.lua") << " OK  x\nNOOK  y <z>\nexit 1\n";
  std::ofstream(dir / "suite" / "c_error.lua") << "t.lua:1: unknown name 'X'\nexit 2\n";
  std::ofstream(dir / "suite" / "errors" / "must_fail.lua") << "exit 2\n";
  auto decks = collect_decks({dir / "suite"});
  ASSERT_EQ(decks.size(), 3u);  // errors/ (must-fail decks) and lib/ (modules) are skipped
  EXPECT_EQ(decks[0].filename(), "a_ok.lua");
  // An explicit file is taken even from errors/.
  EXPECT_EQ(collect_decks({dir / "suite" / "errors" / "must_fail.lua"}).size(), 1u);

  VerifyOptions options;
  options.paths = {dir / "suite"};
  options.jobs = 2;
  options.executable = fake_executable(dir);
  options.out_dir = dir / "out";
  options.junit_file = (dir / "junit.xml").string();
  options.json_file = (dir / "report.json").string();
  std::ostringstream out;
  EXPECT_EQ(verify(options, out), 1);
  const std::string text = out.str();
  EXPECT_NE(text.find("1 passed, 2 failed\n"), std::string::npos) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("a_ok\\.lua +OK +2/0 +[0-9.]+\n"))) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("b_nook\\.lua +NOOK +1/1 +[0-9.]+\n"))) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("c_error\\.lua +ERROR +0/0 +[0-9.]+\n"))) << text;
  EXPECT_NE(text.find("t.lua:1: unknown name 'X'"), std::string::npos);  // output of failed decks is shown

  std::stringstream junit;
  junit << std::ifstream(dir / "junit.xml").rdbuf();
  EXPECT_NE(junit.str().find("tests=\"3\" failures=\"1\" errors=\"1\""), std::string::npos) << junit.str();
  EXPECT_NE(junit.str().find("NOOK  y &lt;z&gt;"), std::string::npos);
  std::stringstream json;
  json << std::ifstream(dir / "report.json").rdbuf();
  EXPECT_NE(json.str().find("\"status\": \"NOOK\", \"exit_code\": 1, \"checks_ok\": 1, \"checks_nook\": 1"),
            std::string::npos)
      << json.str();
  EXPECT_NE(json.str().find("\"passed\": 1,\n  \"failed\": 2"), std::string::npos);

  options.paths = {dir / "suite" / "a_ok.lua"};
  std::ostringstream single;
  EXPECT_EQ(verify(options, single), 0);
  EXPECT_NE(single.str().find("1 passed, 0 failed"), std::string::npos);
}

TEST(Verify, BudgetStatusesAndDefaults) {
  EXPECT_EQ(deck_status(5, 0), "TIMEOUT");
  EXPECT_EQ(deck_status(6, 0), "OUT_OF_MEMORY");
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-verify-budget";
  fs::create_directories(dir);
  std::ofstream(dir / "plain.lua") << "DEBUT()\n";
  std::ofstream(dir / "header.lua") << "-- lunaster: time_limit=60 memory_limit=512\nDEBUT()\n";
  std::ofstream(dir / "broken.lua") << "-- lunaster: time_limit=soon\nDEBUT()\n";
  Budget none;
  Budget plain = verify_budget(dir / "plain.lua", none);
  EXPECT_EQ(plain.seconds.value_or(0), 300.0);
  EXPECT_EQ(plain.megabytes.value_or(0), default_memory_budget_mb());
  Budget header = verify_budget(dir / "header.lua", none);
  EXPECT_EQ(header.seconds.value_or(0), 60.0);
  EXPECT_EQ(header.megabytes.value_or(0), 512.0);
  Budget cli;
  cli.seconds = 2;
  Budget overridden = verify_budget(dir / "header.lua", cli);
  EXPECT_EQ(overridden.seconds.value_or(0), 2.0);
  EXPECT_EQ(overridden.megabytes.value_or(0), 512.0);
  // The child reports the malformed header; the parent still guards it with the defaults.
  EXPECT_EQ(verify_budget(dir / "broken.lua", none).seconds.value_or(0), 300.0);
  // A memory limit is each process's: under --np 2 the two ranks share the default half of the machine.
  EXPECT_EQ(verify_budget(dir / "plain.lua", none, 2).megabytes.value_or(0), std::floor(default_memory_budget_mb() / 2));
  EXPECT_EQ(verify_budget(dir / "header.lua", none, 2).megabytes.value_or(0), 512.0);
}

TEST(Verify, ChildrenOverBudgetAreReportedAndAHungChildIsKilled) {
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-verify-kill";
  fs::remove_all(dir);
  fs::create_directories(dir / "suite");
  // The fake prints its arguments; a deck saying "hang" ignores its budget (exec: the pid stays the child's)
  // and would run 300 s.
  fs::path exe = dir / "fake_lunaster.sh";
  std::ofstream(exe) << "#!/bin/sh\necho \"args: $*\"\ngrep -q hang \"$2\" && exec sleep 300\n"
                        "grep -v '^exit' \"$2\"\nexit $(sed -n 's/^exit //p' \"$2\")\n";
  fs::permissions(exe, fs::perms::owner_all);
  std::ofstream(dir / "suite" / "a_hang.lua") << "-- lunaster: time_limit=0.5\nhang\n";
  std::ofstream(dir / "suite" / "b_slow.lua") << "-- lunaster: time_limit=1\nb_slow.lua:3: time limit of 1 s exceeded\nexit 5\n";
  std::ofstream(dir / "suite" / "c_big.lua") << "-- lunaster: memory_limit=64\nc_big.lua: memory limit of 64 MB exceeded\nexit 6\n";
  std::ofstream(dir / "suite" / "d_ok.lua") << " OK  x\nexit 0\n";
  VerifyOptions options;
  options.paths = {dir / "suite"};
  options.jobs = 2;
  options.executable = exe;
  options.out_dir = dir / "out";
  options.junit_file = (dir / "junit.xml").string();
  options.json_file = (dir / "report.json").string();
  std::ostringstream out;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(verify(options, out), 1);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Killed, not waited for: far below the hung child's 300 s, whatever the machine's load (how
  // soon after the kill time is the scheduler's; no earlier than the limit and the grace).
  EXPECT_GE(seconds, 0.5 + kVerifyKillGraceSeconds);
  EXPECT_LT(seconds, 60.0);
  const std::string text = out.str();
  std::smatch hang;
  ASSERT_TRUE(std::regex_search(text, hang, std::regex("a_hang\\.lua +TIMEOUT +0/0 +([0-9.]+)\n"))) << text;
  EXPECT_GE(std::stod(hang[1]), 0.5 + kVerifyKillGraceSeconds - 0.001) << text;  // printed to the millisecond
  EXPECT_TRUE(std::regex_search(text, std::regex("b_slow\\.lua +TIMEOUT +0/0"))) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("c_big\\.lua +OUT_OF_MEMORY +0/0"))) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("d_ok\\.lua +OK +1/0"))) << text;
  EXPECT_NE(text.find("a_hang.lua: time limit of 0.5 s exceeded; killed after 1.5 s"), std::string::npos) << text;
  EXPECT_NE(text.find("---- " + (dir / "suite" / "c_big.lua").string() + " (OUT_OF_MEMORY, exit 6, memory limit 64 MB)\n"),
            std::string::npos)
      << text;
  // The budget reaches the child: the header's, else the defaults.
  EXPECT_NE(text.find("--time-limit 1 --memory-limit"), std::string::npos) << text;
  EXPECT_NE(text.find("--time-limit 300 --memory-limit 64"), std::string::npos) << text;
  EXPECT_NE(text.find("1 passed, 3 failed\n"), std::string::npos) << text;

  std::stringstream junit;
  junit << std::ifstream(dir / "junit.xml").rdbuf();
  EXPECT_NE(junit.str().find("tests=\"4\" failures=\"0\" errors=\"3\""), std::string::npos) << junit.str();
  EXPECT_NE(junit.str().find("<error type=\"TIMEOUT\" message=\"time limit of 0.5 s exceeded\">"), std::string::npos);
  EXPECT_NE(junit.str().find("<error type=\"OUT_OF_MEMORY\" message=\"memory limit of 64 MB exceeded\">"),
            std::string::npos);
  std::stringstream json;
  json << std::ifstream(dir / "report.json").rdbuf();
  EXPECT_NE(json.str().find("\"status\": \"TIMEOUT\", \"exit_code\": -1"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"status\": \"OUT_OF_MEMORY\", \"exit_code\": 6"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"time_limit\": 0.5, \"memory_limit_mb\": "), std::string::npos) << json.str();
}

TEST(Verify, NpRunsEachDeckUnderTheMpirunOfThePath) {
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-verify-np";
  fs::remove_all(dir);
  for (const char* sub : {"suite", "bin", "not-executable", "empty"}) fs::create_directories(dir / sub);
  // A stand-in mpirun prints its arguments and runs the command after "-np N".
  std::ofstream(dir / "bin" / "mpirun") << "#!/bin/sh\necho \"launcher: $*\"\nshift 2\nexec \"$@\"\n";
  fs::permissions(dir / "bin" / "mpirun", fs::perms::owner_all);
  std::ofstream(dir / "not-executable" / "mpirun") << "not a program\n";
  fs::path exe = dir / "fake_lunaster.sh";
  std::ofstream(exe) << "#!/bin/sh\necho \" OK  x\"\n";
  fs::permissions(exe, fs::perms::owner_all);
  std::ofstream(dir / "suite" / "deck.lua") << "-- a deck\n";
  const std::string saved_path = std::getenv("PATH") ? std::getenv("PATH") : "";
  struct RestorePath {
    std::string value;
    ~RestorePath() { setenv("PATH", value.c_str(), 1); }
  } restore{saved_path};

  setenv("PATH", ((dir / "not-executable").string() + ":" + (dir / "bin").string()).c_str(), 1);
  EXPECT_EQ(find_on_path("mpirun"), dir / "bin" / "mpirun");  // a file that is not executable is skipped
  VerifyOptions options;
  options.paths = {dir / "suite"};
  options.executable = exe;
  options.out_dir = dir / "out";
  options.ranks = 2;
  options.json_file = (dir / "report.json").string();
  std::ostringstream out;
  EXPECT_EQ(verify(options, out), 0) << out.str();
  EXPECT_NE(out.str().find("deck.lua  OK             1/0"), std::string::npos) << out.str();
  std::stringstream json;
  json << std::ifstream(dir / "report.json").rdbuf();
  EXPECT_NE(json.str().find("launcher: -np 2 " + exe.string() + " run " + (dir / "suite" / "deck.lua").string() +
                            " --out " + (dir / "out" / "deck").string() + " --time-limit 300 --memory-limit "),
            std::string::npos)
      << json.str();

  setenv("PATH", (dir / "empty").string().c_str(), 1);
  EXPECT_TRUE(find_on_path("mpirun").empty());
  std::ostringstream missing;
  EXPECT_EQ(verify(options, missing), 2);
  EXPECT_NE(missing.str().find("verify: --np 2 runs each deck under mpirun, and there is no mpirun on the PATH"),
            std::string::npos)
      << missing.str();
}
