#pragma once
/// `lunaster --version`: this build (version, commit, build type) and the versions of the
/// libraries it runs on, as a bug report needs them. Nothing here starts MPI or PETSc.
#include <string>
#include <vector>

namespace lunaster::lua {

/// Which build this is.
struct BuildInfo {
  std::string version;     ///< CMake's project(VERSION), "0.1.0"
  std::string commit;      ///< `git describe --always --dirty` at build time, or "unknown" (no git checkout)
  std::string build_type;  ///< "Release", "Debug", ...
  std::string compiler;    ///< "GNU 12.2.0"
  std::string options;     ///< the build options that change the code: "-march=native", "sanitizers"
};

/// This build: a source file generated at every build (cmake/build_info.cmake), linked into
/// the engine's executable only, so that a new commit recompiles that one file.
const BuildInfo& build_info();

/// One library lunaster runs on.
struct LibraryVersion {
  std::string name;     ///< "MUMPS", "PETSc", "Open MPI", ...
  std::string version;  ///< "5.5.1"; empty when the library could not be asked (then `source` says why)
  std::string source;   ///< where the number comes from: "run time: cholmod_version()", "header: dmumps_c.h"
};

/// Every library, in a fixed order: MUMPS, PETSc, SuiteSparse, CHOLMOD, UMFPACK, MED-file, HDF5,
/// Lua, OpenBLAS, Eigen, and the MPI library. The number the library gives when it runs, where it
/// offers one without being started (the shared library actually loaded, which a package upgrade
/// can change under an old build), else the one of the header lunaster was compiled with. Loads
/// the PETSc module (about 50 ms), never initialises MPI.
std::vector<LibraryVersion> library_versions();

/// The text `lunaster --version` prints: "lunaster VERSION", the commit, the build, then one line
/// per library ("  NAME  VERSION  SOURCE", aligned).
std::string version_text(const BuildInfo& build, const std::vector<LibraryVersion>& libraries);

}  // namespace lunaster::lua
