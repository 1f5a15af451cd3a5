#pragma once
// ScopedTimer: adds the wall time of its scope (s) to a total when it ends, so the parts of a
// step are timed by the blocks that do them instead of clock reads between statements.
#include <omp.h>

#include <chrono>
#include <optional>

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

// In a parallel region every thread of the team runs the scope, and only the first one times it
// (waits at the scope's barriers included): the pass is counted once. Outside a region: the scope.
class TeamTimer {
 public:
  explicit TeamTimer(double& total) {
    if (omp_get_thread_num() == 0) timer_.emplace(total);
  }

 private:
  std::optional<ScopedTimer> timer_;
};

}  // namespace mpdem
