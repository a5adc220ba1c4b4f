/// Loads the PETSc backend module (engine/solver/petsc/) on first use.
#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/solver/backends.hpp"

namespace lunaster::engine {
namespace {

using Factory = LinearSolver* (*)(const IterativeSettings*);

/// The module sits beside the executable (build tree, or an installed bin/ with its
/// module), else in the build tree this binary came from (unit tests run from tests/).
Factory load_factory() {
  static Factory factory = nullptr;
  static std::string failure;
  if (factory) return factory;
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
    factory = reinterpret_cast<Factory>(dlsym(handle, "lunaster_petsc_solver"));
    if (!factory) throw InternalError("the PETSc module has no entry point lunaster_petsc_solver");
    return factory;
  }
  failure = "the PETSc module liblunaster_petsc.so was not found (looked for " + tried + ")";
  throw SolveError(failure, {"build lunaster with PETSc (libpetsc-real-dev) and keep the module beside the executable"});
}

}  // namespace

std::unique_ptr<LinearSolver> make_petsc_solver(const IterativeSettings& settings) {
  return std::unique_ptr<LinearSolver>(load_factory()(&settings));
}

}  // namespace lunaster::engine
