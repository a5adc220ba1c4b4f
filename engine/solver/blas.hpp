#pragma once
/// The dense kernels under CHOLMOD, UMFPACK and MUMPS (dgemm, dsyrk, dtrsm,
/// dpotrf, ...) come from OpenBLAS, linked into every lunaster executable
/// directly. libcholmod, libumfpack and libdmumps name the system's
/// libblas.so.3 / liblapack.so.3, which Debian picks with update-alternatives
/// (its default is the unoptimised reference BLAS); a library the executable
/// itself names comes first in the dynamic linker's search order, so their
/// BLAS and LAPACK calls bind to OpenBLAS whatever the alternatives say.
#include <string>

namespace lunaster::engine {

/// Threads OpenBLAS uses for one call unless OPENBLAS_NUM_THREADS,
/// GOTO_NUM_THREADS or OMP_NUM_THREADS says otherwise.
inline constexpr int kBlasThreads = 1;

/// Sets up the dense kernels once per process, before the first BLAS call
/// (later calls do nothing): OpenBLAS's kernel family and thread count, OpenMP's,
/// and SuiteSparse's allocator (large blocks on huge pages). Called at the start of
/// `lunaster` (which stops OpenBLAS's idle workers before they spin) and by
/// make_linear_solver, never per BLAS call.
void configure_blas();

/// Threads OpenBLAS uses for one call.
int blas_threads();

/// OpenMP parallel regions (CHOLMOD's) this process ran on the calling thread without
/// making a team of one (GOMP_parallel in blas.cpp).
long openmp_regions_inlined();

/// Two OpenBLAS threads while it lives, for one call whose dense kernels are large (a 3D
/// supernodal factorisation: its big supernodes' dgemm and dsyrk scale; the small ones of a
/// 2D factor do not, and between calls the second thread only spins). Then one thread
/// again, its worker stopped. Nothing when `wide` is false, when the user's environment
/// sets OpenBLAS's thread count, under an MPI run of several ranks (they share the cores)
/// or on one core.
class WideBlas {
 public:
  explicit WideBlas(bool wide);
  ~WideBlas();
  WideBlas(const WideBlas&) = delete;
  WideBlas& operator=(const WideBlas&) = delete;

 private:
  bool active_ = false;
};

/// OpenBLAS's kernel family ("SkylakeX", "Haswell", ...).
std::string blas_core();

/// Path of the shared object that provides the `dgemm_` this process calls
/// (the one every library's BLAS call binds to), or "" if it cannot be told.
std::string blas_library();

}  // namespace lunaster::engine
