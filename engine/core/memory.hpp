#pragma once
/// Page-level advice for large arrays; the process's resident memory and the run's budget.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lunaster::engine {

/// Asks the kernel for transparent huge pages under the 2 MB-aligned part of
/// [p, p + bytes), before it is first written: one page fault per 2 MB instead of 512.
/// Only advice: a kernel that offers no huge pages leaves the memory as it was. For arrays
/// of several MB that are filled once (a matrix's entries, a factor).
inline void advise_huge_pages(const void* p, std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t begin = (start + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t end = (start + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

/// v.reserve(n), a new allocation advised as huge pages before it is written (for vectors
/// of several MB built once per pairing or factorisation).
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  v.reserve(n);
  advise_huge_pages(v.data(), sizeof(T) * n);
}

/// v.resize(n), its new allocation (if any) on huge pages as above.
template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t n) {
  reserve_on_huge_pages(v, n);
  v.resize(n);
}

/// Resident set size of this process in bytes (/proc/self/statm), 0 if unknown.
std::size_t resident_bytes();

/// The resident memory this process may reach, in bytes: the deck's memory budget
/// (`memory_limit` in its header or .export, `--memory-limit`), set by the runner while the
/// deck runs (lua/budget.hpp), 0 when there is none. Choices made from the memory available
/// (MUMPS's GESTION_MEMOIRE='AUTO') keep within it.
void set_memory_budget(std::size_t bytes);
std::size_t memory_budget();

}  // namespace lunaster::engine
