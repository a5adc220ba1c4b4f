// `lunaster --version`: every library answers with a version, without MPI being started, and
// the text has one aligned line per library. (tests/cli/version.sh checks the executable's
// output: the commit, the build, and the Lua version against lua.h.)
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <gtest/gtest.h>
#include <lua.h>
#include <mpi.h>

#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>

#include "lua/version.hpp"

using namespace lunaster::lua;

TEST(Version, EveryLibraryGivesADottedVersionAndWhereItComesFrom) {
  const auto libraries = library_versions();
  std::vector<std::string> names;
  for (const auto& l : libraries) names.push_back(l.name);
  EXPECT_EQ(names, (std::vector<std::string>{"MUMPS", "PETSc", "SuiteSparse", "CHOLMOD", "UMFPACK", "MED-file", "HDF5",
                                             "Lua", "OpenBLAS", "Eigen", "Open MPI"}));
  const std::regex dotted(R"(\d+\.\d+\.\d+)");
  for (const auto& l : libraries) {
    EXPECT_TRUE(std::regex_match(l.version, dotted)) << l.name << ": '" << l.version << "' (" << l.source << ")";
    EXPECT_TRUE(l.source.rfind("run time: ", 0) == 0 || l.source.rfind("header: ", 0) == 0) << l.name << ": " << l.source;
  }
  // The libraries that can say their version when they run do: the one loaded is the one reported.
  const std::set<std::string> run_time = {"PETSc", "SuiteSparse", "CHOLMOD", "MED-file", "HDF5", "OpenBLAS", "Open MPI"};
  for (const auto& l : libraries)
    EXPECT_EQ(l.source.rfind("run time: ", 0) == 0, run_time.count(l.name) == 1) << l.name << ": " << l.source;
  EXPECT_EQ(libraries[7].version, LUA_VERSION_MAJOR "." LUA_VERSION_MINOR "." LUA_VERSION_RELEASE);
  // OpenBLAS says which kernels it chose for this machine.
  EXPECT_NE(libraries[8].source.find(", core "), std::string::npos) << libraries[8].source;
}

TEST(Version, AsksWithoutStartingMpi) {
  // In a process of its own (the "threadsafe" style starts this test binary again for it): the
  // tests that run decks before this one may have started MPI in this process.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        int started = 1;
        MPI_Initialized(&started);
        if (started) std::exit(2);  // started before: the test would prove nothing
        library_versions();
        MPI_Initialized(&started);
        std::exit(started ? 1 : 0);
      },
      testing::ExitedWithCode(0), "");
}

TEST(Version, TextHasTheBuildThenOneAlignedLinePerLibrary) {
  const BuildInfo build{"1.2.3", "0123456789ab-dirty", "Release", "GNU 12.2.0", "-march=native"};
  const std::vector<LibraryVersion> libraries = {{"MUMPS", "5.5.1", "header: dmumps_c.h"},
                                                 {"PETSc", "", "not available: no module"},
                                                 {"Open MPI", "4.1.4", "run time: MPI_Get_library_version()"}};
  EXPECT_EQ(version_text(build, libraries),
            "lunaster 1.2.3\n"
            "commit 0123456789ab-dirty\n"
            "build Release, GNU 12.2.0, -march=native\n"
            "libraries:\n"
            "  MUMPS     5.5.1  header: dmumps_c.h\n"
            "  PETSc     ?      not available: no module\n"
            "  Open MPI  4.1.4  run time: MPI_Get_library_version()\n");
}
