#include "io/progress.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

namespace mpdem {

Progress::Progress(double duration, double plain_every_seconds, bool enabled)
    : duration_(duration), plain_every_(plain_every_seconds), enabled_(enabled), tty_(isatty(fileno(stderr)) != 0),
      start_(Clock::now()), last_(start_) {}

void Progress::update(double sim_time, std::uint64_t steps, std::size_t contacts, std::size_t particles) {
  if (!enabled_) return;
  const auto now = Clock::now();
  const double since_last = std::chrono::duration<double>(now - last_).count();
  if (since_last < (tty_ ? 0.25 : plain_every_)) return;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = static_cast<double>(steps - last_steps_) / since_last;
  const double frac = duration_ > 0.0 ? sim_time / duration_ : 1.0;
  const double eta = frac > 0.0 ? elapsed * (1.0 - frac) / frac : 0.0;
  const std::string line = fmt::format(
      "t = {:.6g} s  {:5.1f}%  {:.4g} steps/s  ETA {:.0f} s  contacts {}  particles {}", sim_time, 100.0 * frac, rate,
      eta, contacts, particles);
  if (tty_) fmt::print(stderr, "\r{}\x1b[K", line);
  else fmt::print(stderr, "{}\n", line);
  std::fflush(stderr);
  last_ = now;
  last_steps_ = steps;
}

void Progress::finish(double sim_time, std::uint64_t steps) {
  if (!enabled_) return;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (tty_) fmt::print(stderr, "\n");
  fmt::print(stderr, "done: t = {:.6g} s, {} steps in {:.2f} s ({:.4g} steps/s)\n", sim_time, steps, elapsed,
             elapsed > 0 ? static_cast<double>(steps) / elapsed : 0.0);
}

}  // namespace mpdem
