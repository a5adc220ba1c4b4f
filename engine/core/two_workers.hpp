#pragma once
/// Two workers for loops whose items are independent (the target machine has 2 cores).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <thread>

namespace lunaster::engine {

/// `work(0, failed_at)` runs here, `work(1, failed_at)` on a helper thread. Each reports the
/// position of the item it failed on (or SIZE_MAX) and its exception; the one of the earlier
/// item is re-thrown, so the error is the one a single pass in item order would raise.
template <class Work>
void run_two_workers(Work&& work) {
  std::exception_ptr failure[2];
  std::size_t failed_at[2] = {SIZE_MAX, SIZE_MAX};
  auto guarded = [&](int w) {
    try {
      work(w, failed_at[w]);
    } catch (...) {
      failure[w] = std::current_exception();
    }
  };
  std::thread helper(guarded, 1);
  guarded(0);
  helper.join();
  const int first = failed_at[1] < failed_at[0] ? 1 : 0;
  if (failure[first]) std::rethrow_exception(failure[first]);
  if (failure[1 - first]) std::rethrow_exception(failure[1 - first]);
}

}  // namespace lunaster::engine
