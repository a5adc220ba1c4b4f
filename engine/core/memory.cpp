/// The process's resident memory and the run's memory budget (see memory.hpp).
#include "engine/core/memory.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>

namespace lunaster::engine {
namespace {

std::atomic<std::size_t> budget_bytes{0};

}  // namespace

std::size_t resident_bytes() {
  const int fd = open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  char buffer[256];
  const ssize_t n = read(fd, buffer, sizeof buffer - 1);
  close(fd);
  if (n <= 0) return 0;
  buffer[n] = '\0';
  unsigned long long size = 0, resident = 0;
  if (std::sscanf(buffer, "%llu %llu", &size, &resident) != 2) return 0;
  return static_cast<std::size_t>(resident) * static_cast<std::size_t>(sysconf(_SC_PAGE_SIZE));
}

void set_memory_budget(std::size_t bytes) { budget_bytes.store(bytes, std::memory_order_relaxed); }

std::size_t memory_budget() { return budget_bytes.load(std::memory_order_relaxed); }

}  // namespace lunaster::engine
