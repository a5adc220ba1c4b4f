/// OpenBLAS and OpenMP set-up (see blas.hpp).
#include "engine/solver/blas.hpp"

#include <SuiteSparse_config.h>
#include <cblas.h>
#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "engine/core/memory.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {
namespace {

bool has_env(const char* name) { return std::getenv(name) != nullptr; }

/// The user set OpenBLAS's thread count through its environment: that count stands.
bool threads_from_environment() {
  return has_env("OPENBLAS_NUM_THREADS") || has_env("GOTO_NUM_THREADS") || has_env("OMP_NUM_THREADS");
}

/// Stops OpenBLAS's idle workers (each would spin in sched_yield before sleeping); OpenBLAS
/// starts them again when a later call asks for more than one thread.
void stop_blas_workers() {
  using Shutdown = int (*)();
  if (const auto stop = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"))) stop();
}

/// Debian 12's OpenBLAS (0.3.21, built for every x86-64 core and choosing at
/// load time) does not know CPUs released after it (Intel family 6 model 0xCF,
/// the machine this project runs on, among them) and falls back to its generic
/// SSE3 "Prescott" kernels: 1.3-1.5x slower than its AVX-512 ones here. When it
/// did and the CPU has AVX-512 or AVX2, its own kernel selection is run again
/// with OPENBLAS_CORETYPE naming that family, as OpenBLAS documents for this
/// case. This must happen before the first BLAS call; the two entry points are
/// looked up at run time, so a library without them is simply left as it chose.
void select_openblas_kernels() {
  if (has_env("OPENBLAS_CORETYPE") || std::strcmp(openblas_get_corename(), "Prescott") != 0) return;
  const char* family = nullptr;
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
    family = "SkylakeX";
  else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    family = "Haswell";
  if (!family) return;
  using Hook = void (*)();
  const auto quit = reinterpret_cast<Hook>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_quit"));
  const auto init = reinterpret_cast<Hook>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init"));
  if (!quit || !init) return;
  setenv("OPENBLAS_CORETYPE", family, 0);
  quit();
  init();
  unsetenv("OPENBLAS_CORETYPE");  // read once by init: the environment stays as the user gave it
}

/// Blocks from 4 MB up (a factor's values, its supernodal workspace) start on a 2 MB
/// boundary and are advised as transparent huge pages (engine/core/memory.hpp).
void* large_pages_malloc(std::size_t size) {
  constexpr std::size_t kLargeBlock = std::size_t{4} << 20, kHugePage = std::size_t{2} << 20;
  if (size < kLargeBlock) return std::malloc(size);
  void* p = nullptr;
  if (posix_memalign(&p, kHugePage, size) != 0) return nullptr;
  advise_huge_pages(p, size);
  return p;
}

/// The OpenMP environment asks for threads of its own: OpenMP is then left as the user set it.
bool openmp_from_environment() { return has_env("OMP_MAX_ACTIVE_LEVELS") || has_env("OMP_THREAD_LIMIT"); }

std::atomic<long> inlined_regions{0};

}  // namespace

}  // namespace lunaster::engine

/// GCC's entry point for `#pragma omp parallel`, as libgomp exports it (GOMP_4.0), defined here so
/// that the solver libraries' parallel regions bind to it: the executable comes first in the
/// dynamic linker's search order. CHOLMOD's supernodal factorisation (the only OpenMP user
/// among the libraries of a serial run) opens several regions per supernode for its scatter
/// loops. This project runs them on the calling thread (configure_blas), and libgomp still
/// built a team of one for each and woke its barrier with a system call on leaving: 120,000
/// futex calls in the glued 2D k = 16 solve, a third of its system time. A region asked of us
/// runs `fn` here, outside any team, where omp_get_num_threads() is 1 and
/// omp_get_thread_num() 0, as in a team of one (worksharing, single and task constructs
/// without a team run on the one thread, as libgomp documents for orphaned constructs).
/// When the OpenMP environment asks for threads, or inside a region of libgomp's, the region
/// goes to libgomp's own entry point.
extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned num_threads, unsigned flags) {
  using Entry = void (*)(void (*)(void*), void*, unsigned, unsigned);
  using Level = int (*)();
  static const Entry libgomp = reinterpret_cast<Entry>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  static const Level level = reinterpret_cast<Level>(dlsym(RTLD_NEXT, "omp_get_level"));
  static const bool inline_regions = !lunaster::engine::openmp_from_environment();
  if (libgomp && (!inline_regions || (level && level() > 0))) {
    libgomp(fn, data, num_threads, flags);
    return;
  }
  lunaster::engine::inlined_regions.fetch_add(1, std::memory_order_relaxed);
  fn(data);
}

namespace lunaster::engine {

long openmp_regions_inlined() { return inlined_regions.load(std::memory_order_relaxed); }

void configure_blas() {
  static const bool done = [] {
    select_openblas_kernels();
    // OpenBLAS reads these itself when it is loaded; an explicit count would override them.
    if (!threads_from_environment()) {
      openblas_set_num_threads(kBlasThreads);
      // Loaded without a count, OpenBLAS started a worker per further core, and each spins in
      // sched_yield for about 2^28 cycles before sleeping: 0.13 s of CPU, half of it system
      // time, beside the first 0.15 s of every run (perf on the glued k = 16 deck). One
      // thread never uses them, so stop them; OpenBLAS starts them again if a later
      // openblas_set_num_threads asks for more (its server restarts on demand).
      if (kBlasThreads == 1) stop_blas_workers();
    }
    // A worker that OpenBLAS starts for a wide factorisation (WideBlas) waits for its next task
    // spinning in sched_yield for 2^28 cycles (about 0.1 s) before it sleeps: on the 3D contact
    // benchmark that was 8 % of the run's CPU samples, each yield a system call (and on a
    // virtual machine a hypervisor exit), between calls that come a few microseconds apart or
    // not for the rest of the run. 2^20 cycles (well under a millisecond) keeps it awake through
    // a factorisation's BLAS calls: `cont3d` 0.59 s against 0.72 s (system time 0.16 against
    // 0.36 s), 2^24 gave the same within the spread, the elastic and mortar 3D runs unchanged
    // (medians of 11); on the refined CONTINUE deck's MUMPS factorisation 2^20 took the system
    // time to 8 s, against 16-17 s with 2^24 and 26-27 s with OpenBLAS's default
    // (tests/bench/README.md). OpenBLAS reads the setting from its environment, at load and
    // again when asked; the environment is then left as the user gave it.
    if (!has_env("OPENBLAS_THREAD_TIMEOUT")) {
      using ReadEnvironment = void (*)();
      if (const auto read = reinterpret_cast<ReadEnvironment>(dlsym(RTLD_DEFAULT, "openblas_read_env"))) {
        setenv("OPENBLAS_THREAD_TIMEOUT", "20", 1);
        read();
        unsetenv("OPENBLAS_THREAD_TIMEOUT");
      }
    }
    // CHOLMOD's and UMFPACK's large blocks on transparent huge pages (where the kernel offers
    // them on request): the glued k = 16 deck went from 56,000 to 24,000 page faults and
    // from 0.18 to 0.12 s of system time. Freed by free() as before.
    SuiteSparse_config.malloc_func = large_pages_malloc;
    // CHOLMOD's supernodal factorisation opens an OpenMP region of 4 threads
    // (a constant of its build) around every large supernode's scatter loops:
    // on 2 cores that is tens of thousands of futex waits and context switches
    // per factorisation for memory-bound loops. Make every OpenMP region run on
    // the calling thread unless the OpenMP environment says otherwise.
    // libcholmod brings the OpenMP runtime (libgomp); looked up at run time, as
    // lunaster itself has no OpenMP code.
    // GOMP_parallel above runs them without a team; this covers a library that enters
    // libgomp another way.
    using SetLevels = void (*)(int);
    if (!openmp_from_environment())
      if (const auto set = reinterpret_cast<SetLevels>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"))) set(0);
    return true;
  }();
  (void)done;
}

int blas_threads() { return openblas_get_num_threads(); }

WideBlas::WideBlas(bool wide) {
  active_ = wide && kBlasThreads == 1 && !threads_from_environment() && parallel::size() == 1 &&
            std::thread::hardware_concurrency() >= 2;
  if (active_) openblas_set_num_threads(2);
}

WideBlas::~WideBlas() {
  if (!active_) return;
  openblas_set_num_threads(kBlasThreads);
  stop_blas_workers();
}

std::string blas_core() { return openblas_get_corename(); }

std::string blas_library() {
  void* symbol = dlsym(RTLD_DEFAULT, "dgemm_");
  Dl_info info{};
  if (!symbol || !dladdr(symbol, &info) || !info.dli_fname) return "";
  return info.dli_fname;
}

}  // namespace lunaster::engine
