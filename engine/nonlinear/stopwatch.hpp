#pragma once
/// Adds the wall time of its scope to a counter of seconds (SolverStats).
#include <chrono>

namespace lunaster::engine {

class Stopwatch {
 public:
  explicit Stopwatch(double& seconds) : seconds_(seconds), t0_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace lunaster::engine
