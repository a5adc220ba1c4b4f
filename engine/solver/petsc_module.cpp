/// Loads the PETSc backend module (engine/solver/petsc/) on first use.
#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/solver/backends.hpp"
#include "engine/solver/petsc_module.hpp"

namespace lunaster::engine {
namespace {

using Factory = LinearSolver* (*)(const IterativeSettings*);
using VersionEntry = int (*)(char*, size_t);

/// The module sits beside the executable (build tree, or an installed bin/ with its
/// module), else in the build tree this binary came from (unit tests run from tests/).
void* load_module() {
  static void* module = nullptr;
  static std::string failure;
  if (module) return module;
  if (!failure.empty()) throw SolveError(failure);
  namespace fs = std::filesystem;
  std::vector<fs::path> places;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) places.push_back(exe.parent_path() / "liblunaster_petsc.so");
#ifdef LUNASTER_MODULE_DIR
  places.push_back(fs::path(LUNASTER_MODULE_DIR) / "liblunaster_petsc.so");
#endif
  std::string tried;
  for (const fs::path& place : places) {
    if (!fs::exists(place, ec)) {
      tried += (tried.empty() ? "" : ", ") + place.string();
      continue;
    }
    void* handle = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      failure = std::string("the PETSc module could not be loaded: ") + dlerror();
      throw SolveError(failure, {"install the Debian package libpetsc-real-dev (scripts/install-deps.sh)"});
    }
    return module = handle;
  }
  failure = "the PETSc module liblunaster_petsc.so was not found (looked for " + tried + ")";
  throw SolveError(failure, {"build lunaster with PETSc (libpetsc-real-dev) and keep the module beside the executable"});
}

/// The module's entry point `name`.
template <typename Entry>
Entry entry_point(const char* name) {
  auto* entry = reinterpret_cast<Entry>(dlsym(load_module(), name));
  if (!entry) throw InternalError(std::string("the PETSc module has no entry point ") + name);
  return entry;
}

}  // namespace

std::unique_ptr<LinearSolver> make_petsc_solver(const IterativeSettings& settings) {
  static const Factory factory = entry_point<Factory>("lunaster_petsc_solver");
  return std::unique_ptr<LinearSolver>(factory(&settings));
}

PetscVersion petsc_version() {
  char text[64] = {};
  if (entry_point<VersionEntry>("lunaster_petsc_version")(text, sizeof text))
    throw SolveError("PETSc did not give its version (PetscGetVersionNumber failed)");
  const std::string both = text;
  const auto blank = both.find(' ');
  return {both.substr(0, blank), blank == std::string::npos ? std::string() : both.substr(blank + 1)};
}

}  // namespace lunaster::engine
