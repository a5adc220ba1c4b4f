// `lunaster verify`: deck collection, TEST_RESU line parsing, child processes and reports.
#include <gtest/gtest.h>

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
  EXPECT_EQ(deck_status(0, 0), "OK");
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
  std::ofstream(dir / "suite" / "a_ok.lua") << " OK  x\n OK  y\nexit 0\n";
  std::ofstream(dir / "suite" / "b_nook.lua") << " OK  x\nNOOK  y <z>\nexit 1\n";
  std::ofstream(dir / "suite" / "c_error.lua") << "t.lua:1: unknown name 'X'\nexit 2\n";
  std::ofstream(dir / "suite" / "errors" / "must_fail.lua") << "exit 2\n";
  auto decks = collect_decks({dir / "suite"});
  ASSERT_EQ(decks.size(), 3u);  // errors/ is skipped
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
