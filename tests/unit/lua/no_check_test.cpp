// `lunaster verify` and a deck that checked nothing: `run` ends it with exit 0, no check line and
// a NO_CHECK line (lua/main.cpp); verify calls it NO_CHECK, a failure, in its table, JUnit and JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "lua/verify.hpp"

using namespace lunaster::lua;
namespace fs = std::filesystem;

TEST(VerifyNoCheck, ExitZeroWithoutACheckLineIsNoCheck) {
  EXPECT_EQ(deck_status(0, 0, 0), "NO_CHECK");
  EXPECT_EQ(deck_status(1, 0, 0), "NOOK");
  EXPECT_EQ(deck_status(1, 1, 0), "NOOK");
  EXPECT_EQ(deck_status(1, 0, 3), "NOOK");  // exit 1 with OK lines only: a NOOK the count missed
  EXPECT_EQ(deck_status(0, 0, 2), "OK");
}

TEST(VerifyNoCheck, CountedAsAFailureInEveryReport) {
  const fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-verify-no-check";
  fs::remove_all(dir);
  fs::create_directories(dir / "suite");
  // The stand-in for lunaster prints what `run` prints for a deck without TEST_RESU, or one check.
  const fs::path exe = dir / "run.sh";
  std::ofstream(exe) << "#!/bin/sh\ncase \"$2\" in\n"
                        "  */checked.lua) echo ' OK  ANALYTIQUE     DEPL  A  DY'; echo 'lunaster: 1 check(s) OK, 0 NOOK';"
                        " exit 0 ;;\n"
                        "  *) echo 'lunaster: 0 check(s) OK, 0 NOOK'; echo 'lunaster: NO_CHECK: the deck checked nothing';"
                        " exit 0 ;;\nesac\n";
  fs::permissions(exe, fs::perms::owner_all);
  std::ofstream(dir / "suite" / "checked.lua") << "-- one check\n";
  std::ofstream(dir / "suite" / "unchecked.lua") << "-- none\n";
  const VerifyOptions options{.paths = {dir / "suite"}, .jobs = 1, .junit_file = (dir / "junit.xml").string(),
                              .json_file = (dir / "report.json").string(), .out_dir = dir / "out", .executable = exe,
                              .budget = {}, .vale_calc_report = false, .solveur = {}, .ranks = 0};
  std::ostringstream out;
  EXPECT_EQ(verify(options, out), 1);
  const std::string text = out.str();
  EXPECT_TRUE(std::regex_search(text, std::regex("checked\\.lua +OK +1/0 "))) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex("unchecked\\.lua +NO_CHECK +0/0 "))) << text;
  EXPECT_NE(text.find("---- " + (dir / "suite" / "unchecked.lua").string() + " (NO_CHECK, exit 0)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("1 passed, 1 failed\n"), std::string::npos) << text;
  auto contents = [](const fs::path& file) {
    std::ostringstream text;
    text << std::ifstream(file).rdbuf();
    return text.str();
  };
  const std::string junit = contents(dir / "junit.xml"), json = contents(dir / "report.json");
  EXPECT_NE(junit.find("tests=\"2\" failures=\"1\" errors=\"0\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("<failure type=\"NO_CHECK\" message=\"no check ran"), std::string::npos) << junit;
  EXPECT_NE(json.find("\"status\": \"NO_CHECK\", \"exit_code\": 0, \"checks_ok\": 0, \"checks_nook\": 0"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"passed\": 1,\n  \"failed\": 1"), std::string::npos) << json;
}
