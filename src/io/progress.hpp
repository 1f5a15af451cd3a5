#pragma once
// Progress on stderr: simulated time, percent done, steps/s, ETA and contacts. On a terminal
// one line is redrawn in place a few times a second; otherwise (a log file, CI) a plain line
// is printed every `plain_every` seconds of wall time.
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace mpdem {

class Progress {
 public:
  Progress(double duration, double plain_every_seconds, bool enabled);
  void update(double sim_time, std::uint64_t steps, std::size_t contacts, std::size_t particles);
  void finish(double sim_time, std::uint64_t steps);

 private:
  using Clock = std::chrono::steady_clock;
  double duration_;
  double plain_every_;
  bool enabled_;
  bool tty_;
  Clock::time_point start_, last_;
  std::uint64_t last_steps_ = 0;
};

}  // namespace mpdem
