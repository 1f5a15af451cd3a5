#pragma once
// ScopedTimer: adds the wall time of its scope (s) to a total when it ends, so the parts of a
// step are timed by the blocks that do them instead of clock reads between statements.
#include <chrono>

namespace mpdem {

class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(total), start_(Clock::now()) {}
  ~ScopedTimer() { total_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  using Clock = std::chrono::steady_clock;
  double& total_;  // s
  Clock::time_point start_;
};

}  // namespace mpdem
