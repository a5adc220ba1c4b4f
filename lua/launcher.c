/* lunaster: the program users run. It starts the engine, lunaster-engine from the same
 * directory, in its own place (exec: same process, same arguments, same standard streams),
 * with glibc's allocator settings in its environment (allocator_settings.h).
 *
 * Why a separate file: glibc reads those settings only when a process starts, so the engine
 * used to start itself a second time. By then the dynamic loader had mapped and relocated its
 * 70 libraries (MPI, MUMPS, HDF5 and theirs), only to throw them away: 0.04 s of a 0.1 s
 * empty deck on a 2-core VM. This launcher needs the C library alone, so the engine's
 * libraries are loaded once.
 *
 * The settings are not added when GLIBC_TUNABLES is already set (by the user, who may set it
 * empty to keep glibc's defaults, or by a lunaster that started this one: `verify`'s runs,
 * mpirun's ranks), under valgrind (run `valgrind --trace-children=yes lunaster ...`, or
 * valgrind on lunaster-engine directly) or in a sanitizer build. */
#define _GNU_SOURCE
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "allocator_settings.h"

int main(int argc, char** argv) {
  (void)argc;
  /* /proc/self/exe names the file itself, a symbolic link to it resolved. */
  char engine[PATH_MAX];
  const size_t room = sizeof(engine) - sizeof(LUNASTER_ENGINE_NAME) - 1;
  const ssize_t n = readlink("/proc/self/exe", engine, room);
  char* slash = n > 0 && (size_t)n < room ? memrchr(engine, '/', (size_t)n) : NULL;
  if (!slash) {
    fprintf(stderr, "lunaster: cannot find the directory of this program (/proc/self/exe): %s\n",
            n < 0 ? strerror(errno) : "path too long");
    return 127;
  }
  memcpy(slash + 1, LUNASTER_ENGINE_NAME, sizeof(LUNASTER_ENGINE_NAME));
#if LUNASTER_ALLOCATOR_SETTINGS
  const char* preload = getenv("LD_PRELOAD");
  if (!getenv("GLIBC_TUNABLES") && !(preload && strstr(preload, "vgpreload")))
    setenv("GLIBC_TUNABLES", LUNASTER_ALLOCATOR_TUNABLES, 1);
#endif
  execv(engine, argv);
  fprintf(stderr, "lunaster: cannot start the engine %s: %s (it is built beside this program)\n", engine,
          strerror(errno));
  return 127;
}
