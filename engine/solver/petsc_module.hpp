#pragma once
/// The PETSc module (engine/solver/petsc/, liblunaster_petsc.so), loaded on first use.
#include <string>

namespace lunaster::engine {

/// The PETSc the module runs on: `library`, the version the loaded PETSc library gives
/// (PetscGetVersionNumber, which needs neither PetscInitialize nor MPI), and `headers`, the
/// version of the PETSc headers the module was compiled with ("3.18.5"). Loads the module
/// (about 50 ms: PETSc's libraries); SolveError if it cannot.
struct PetscVersion {
  std::string library, headers;
};
PetscVersion petsc_version();

}  // namespace lunaster::engine
