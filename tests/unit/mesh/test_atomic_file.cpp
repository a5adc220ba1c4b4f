// Output files are replaced atomically (engine/io/atomic_file.hpp): a write that fails
// part-way leaves the previous file as it was and no temporary beside it.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/io/atomic_file.hpp"

namespace fs = std::filesystem;
using lunaster::DeckError;
using lunaster::engine::write_file_atomically;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-scratch" / "atomic_file" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, ReplacesTheFileWhenTheWriteCompletes) {
  const fs::path dir = scratch("replace");
  write_file_atomically(dir / "a.csv", [](std::ostream& o) { o << "x,y\n1,2\n"; });
  write_file_atomically(dir / "a.csv", [](std::ostream& o) { o << "x,y\n3,4\n"; });
  EXPECT_EQ(slurp(dir / "a.csv"), "x,y\n3,4\n");
  EXPECT_EQ(entries(dir), 1);
}

TEST(AtomicFile, AWriteThatFailsPartWayLeavesThePreviousFileAndNoTemporary) {
  const fs::path dir = scratch("fail");
  write_file_atomically(dir / "a.csv", [](std::ostream& o) { o << "x,y\n1,2\n"; });
  EXPECT_THROW(write_file_atomically(dir / "a.csv",
                                     [](std::ostream& o) {
                                       o << "x,y\n" << std::string(1 << 20, '9');  // half a file, then
                                       throw std::runtime_error("killed");           // the writer dies
                                     }),
               std::runtime_error);
  EXPECT_EQ(slurp(dir / "a.csv"), "x,y\n1,2\n");
  EXPECT_EQ(entries(dir), 1);
}

TEST(AtomicFile, AFolderThatDoesNotExistIsNamed) {
  const fs::path dir = scratch("missing");
  try {
    write_file_atomically(dir / "no" / "such" / "a.csv", [](std::ostream& o) { o << "x\n"; });
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_NE(e.message().find("a.csv"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("cannot create a file in"), std::string::npos) << e.message();
  }
  EXPECT_EQ(entries(dir), 0);
}

}  // namespace
