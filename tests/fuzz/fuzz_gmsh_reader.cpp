// libFuzzer harness: the Gmsh reader and the code_aster .mail reader on arbitrary text. Every input must end in a
// mesh or a lunaster::DeckError; a crash, a sanitizer report, a hang or an
// out-of-memory is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/error.hpp"
#include "engine/io/aster_mail_reader.hpp"
#include "engine/io/gmsh_reader.hpp"
#include "engine/mesh/orientation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    lunaster::engine::Mesh mesh = lunaster::engine::read_gmsh_text(text, "fuzz.msh");
    lunaster::engine::orient_cells(mesh, "fuzz.msh");  // as LIRE_MAILLAGE does after reading
    (void)mesh.n_cells();
  } catch (const lunaster::Error&) {
    // expected for malformed input
  }
  try {
    lunaster::engine::Mesh mesh = lunaster::engine::read_aster_mail_text(text, "fuzz.mail");
    lunaster::engine::orient_cells(mesh, "fuzz.mail");
  } catch (const lunaster::Error&) {
  }
  return 0;
}
