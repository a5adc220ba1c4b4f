/* glibc's allocator settings for lunaster's memory (arrays of megabytes, written once):
 * transparent huge pages under the heap and the allocator's own mappings (hugetlb=1: one page
 * fault per 2 MB instead of 512, where the kernel offers huge pages on request), and freed
 * blocks of up to 32 MB kept for reuse rather than unmapped and faulted in again. Each page
 * fault costs a trap into the kernel, and on a virtual machine a hypervisor exit too: the
 * glued 2D k = 16 deck went from 16,770 to 3,464 page faults, its wall time from 0.51 to
 * 0.41 s (medians of 9, tests/bench/README.md). glibc reads them only when a process starts,
 * so they are set in the environment of the engine's start: by the launcher (launcher.c), or
 * by the engine itself when it is started directly (main.cpp). Shared by both; plain C. */
#ifndef LUNASTER_ALLOCATOR_SETTINGS_H
#define LUNASTER_ALLOCATOR_SETTINGS_H

#define LUNASTER_ALLOCATOR_TUNABLES \
  "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=134217728"

/* The engine's file name, beside the launcher. */
#define LUNASTER_ENGINE_NAME "lunaster-engine"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
/* A sanitizer brings its own allocator: no settings. */
#define LUNASTER_ALLOCATOR_SETTINGS 0
#else
#define LUNASTER_ALLOCATOR_SETTINGS 1
#endif

#endif
