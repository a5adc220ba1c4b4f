/// `lunaster --version`: the libraries' own version numbers. The only file of lua/ that
/// includes the libraries' headers, for their version macros and functions.
#define OMPI_SKIP_MPICXX 1  // mpi.h (also through med.h's hdf5.h): the C API only
#define MPICH_SKIP_MPICXX 1
#include "lua/version.hpp"

#include <SuiteSparse_config.h>
#include <cblas.h>
#include <cholmod.h>
#include <dmumps_c.h>
#include <lua.h>
#include <med.h>
#include <mpi.h>
#include <openblas_config.h>
#include <umfpack.h>

#include <Eigen/Core>
#include <algorithm>
#include <cctype>
#include <sstream>

#include "engine/core/error.hpp"
#include "engine/solver/petsc_module.hpp"

namespace lunaster::lua {

namespace {

std::string dotted(long major, long minor, long release) {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}

/// `from` when the loaded library and the header agree, else both numbers.
std::string run_time(const std::string& from, const std::string& header, const std::string& library) {
  return "run time: " + from + (header == library ? "" : " (header: " + header + ")");
}

/// The words of `text` (OpenBLAS's configuration string, MPI's library string).
std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

LibraryVersion petsc() {
  try {
    const auto v = engine::petsc_version();
    return {"PETSc", v.library,
            run_time("PetscGetVersionNumber() of the module liblunaster_petsc.so, PETSc not started", v.headers,
                     v.library)};
  } catch (const Error& e) {
    return {"PETSc", "", "not available: " + e.message()};
  }
}

LibraryVersion openblas() {
  const std::string header = words(OPENBLAS_VERSION).back();  // " OpenBLAS 0.3.21 "
  const char* config = openblas_get_config();                 // "OpenBLAS 0.3.21 DYNAMIC_ARCH ... MAX_THREADS=64"
  const auto w = words(config ? config : "");
  const std::string version = w.size() > 1 && w[0] == "OpenBLAS" ? w[1] : "";
  const char* core = openblas_get_corename();
  return {"OpenBLAS", version,
          run_time("openblas_get_config(): " + std::string(config ? config : "") + ", core " + (core ? core : "?"),
                   header, version)};
}

/// MPI_Get_library_version, which the MPI standard allows before MPI_Init.
LibraryVersion mpi() {
  char text[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int length = 0;
  std::string library;
  if (MPI_Get_library_version(text, &length) == MPI_SUCCESS) library.assign(text, std::max(0, length));
  library = library.substr(0, library.find(','));  // "Open MPI v4.1.4, package: Debian OpenMPI, ..."
  while (!library.empty() && std::isspace(static_cast<unsigned char>(library.back()))) library.pop_back();
#ifdef OMPI_MAJOR_VERSION
  const std::string name = "Open MPI", header = dotted(OMPI_MAJOR_VERSION, OMPI_MINOR_VERSION, OMPI_RELEASE_VERSION);
  const std::string prefix = "Open MPI v";
  if (library.rfind(prefix, 0) == 0)
    return {name, library.substr(prefix.size()), run_time("MPI_Get_library_version(), MPI not started", header,
                                                          library.substr(prefix.size()))};
  return {name, header, "header: mpi.h" + (library.empty() ? "" : " (the library says '" + library + "')")};
#else
  return {"MPI", library, "run time: MPI_Get_library_version(), MPI not started"};
#endif
}

}  // namespace

std::vector<LibraryVersion> library_versions() {
  std::vector<LibraryVersion> out;
  // MUMPS gives its version only in the structure its initialisation fills (JOB=-1), which starts MPI.
  out.push_back({"MUMPS", MUMPS_VERSION, "header: dmumps_c.h (the library tells it only once MPI is started)"});
  out.push_back(petsc());
  int v[3] = {0, 0, 0};
  SuiteSparse_version(v);
  out.push_back({"SuiteSparse", dotted(v[0], v[1], v[2]),
                 run_time("SuiteSparse_version()",
                          dotted(SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION),
                          dotted(v[0], v[1], v[2]))});
  cholmod_version(v);
  out.push_back({"CHOLMOD", dotted(v[0], v[1], v[2]),
                 run_time("cholmod_version()", dotted(CHOLMOD_MAIN_VERSION, CHOLMOD_SUB_VERSION, CHOLMOD_SUBSUB_VERSION),
                          dotted(v[0], v[1], v[2]))});
  out.push_back({"UMFPACK", dotted(UMFPACK_MAIN_VERSION, UMFPACK_SUB_VERSION, UMFPACK_SUBSUB_VERSION),
                 "header: umfpack.h (the library has no version function)"});
  med_int major = 0, minor = 0, release = 0;
  const bool med = MEDlibraryNumVersion(&major, &minor, &release) >= 0;
  const std::string med_version = med ? dotted(major, minor, release) : "";
  out.push_back({"MED-file", med_version,
                 run_time("MEDlibraryNumVersion()", dotted(MED_NUM_MAJEUR, MED_NUM_MINEUR, MED_NUM_RELEASE), med_version)});
  // lunaster calls no HDF5 function itself: libmedC brings its HDF5, and says which it runs on.
  const bool hdf = MEDlibraryHdfNumVersion(&major, &minor, &release) >= 0;
  const std::string hdf_version = hdf ? dotted(major, minor, release) : "";
  out.push_back({"HDF5", hdf_version,
                 run_time("MEDlibraryHdfNumVersion(), the HDF5 under libmedC",
                          dotted(H5_VERS_MAJOR, H5_VERS_MINOR, H5_VERS_RELEASE), hdf_version)});
  // The Lua library gives its major and minor version only (lua_version(): 504).
  const long lua = static_cast<long>(lua_version(nullptr));
  out.push_back({"Lua", LUA_VERSION_MAJOR "." LUA_VERSION_MINOR "." LUA_VERSION_RELEASE,
                 "header: lua.h (the library says " + std::to_string(lua / 100) + "." + std::to_string(lua % 100) + ")"});
  out.push_back(openblas());
  out.push_back({"Eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION),
                 "header: Eigen/Core (a header-only library)"});
  out.push_back(mpi());
  return out;
}

std::string version_text(const BuildInfo& build, const std::vector<LibraryVersion>& libraries) {
  auto shown = [](const LibraryVersion& l) { return l.version.empty() ? std::string("?") : l.version; };
  std::size_t name_width = 0, version_width = 0;
  for (const auto& l : libraries) {
    name_width = std::max(name_width, l.name.size());
    version_width = std::max(version_width, shown(l).size());
  }
  std::ostringstream out;
  out << "lunaster " << build.version << "\n"
      << "commit " << build.commit << "\n"
      << "build " << build.build_type << ", " << build.compiler << (build.options.empty() ? "" : ", ") << build.options
      << "\n"
      << "libraries:\n";
  for (const auto& l : libraries) {
    const std::string version = shown(l);
    out << "  " << l.name << std::string(name_width + 2 - l.name.size(), ' ') << version
        << std::string(version_width + 2 - version.size(), ' ') << l.source << "\n";
  }
  return out.str();
}

}  // namespace lunaster::lua
