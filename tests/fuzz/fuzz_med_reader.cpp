// libFuzzer harness: the MED reader on arbitrary bytes. MED-file opens files by
// name, so each input is written to a per-process temporary file first. Every
// input must end in a mesh or a lunaster::DeckError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "engine/core/error.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/mesh/orientation.hpp"

namespace {

std::string scratch_path() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/lunaster-fuzz-med-" + std::to_string(::getpid()) + ".med";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = scratch_path();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return 0;
  const bool written = std::fwrite(data, 1, size, file) == size;
  std::fclose(file);
  if (written) {
    try {
      lunaster::engine::Mesh mesh = lunaster::engine::read_med(path);
      lunaster::engine::orient_cells(mesh, path);  // as LIRE_MAILLAGE does after reading
      (void)mesh.n_cells();
    } catch (const lunaster::Error&) {
      // expected for malformed input
    }
  }
  std::remove(path.c_str());
  return 0;
}
