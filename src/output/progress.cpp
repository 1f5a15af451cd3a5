#include "output/progress.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

namespace mpdem {

Progress::Progress(double duration, double plain_every_seconds, bool enabled, double start_time,
                   std::uint64_t start_steps)
    : duration_(duration), plain_every_(plain_every_seconds), enabled_(enabled), tty_(isatty(fileno(stderr)) != 0),
      start_time_(start_time), start_steps_(start_steps), start_(Clock::now()), last_(start_), last_steps_(start_steps),
      removal_window_(start_), summary_at_(start_) {}

void Progress::print_line(const std::string& line) {
  if (drawn_) fmt::print(stderr, "\r\x1b[K");
  fmt::print(stderr, "{}\n", line);
  std::fflush(stderr);
  drawn_ = false;
}

void Progress::update(double sim_time, std::uint64_t steps, std::size_t contacts, std::size_t particles,
                      double imbalance, std::optional<std::uint64_t> bridges,
                      std::optional<std::array<std::uint64_t, 2>> bonds) {
  if (!enabled_) return;
  const auto now = Clock::now();
  if ((removal_lines_ > 0 || held_ > 0) &&
      std::chrono::duration<double>(now - removal_window_).count() >= plain_every_) {
    flush_removed();
    removal_lines_ = 0;  // the next removal starts a new interval
  }
  const double since_last = std::chrono::duration<double>(now - last_).count();
  if (since_last < (tty_ ? 0.25 : plain_every_)) return;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = static_cast<double>(steps - last_steps_) / since_last;
  const double frac = duration_ > 0.0 ? sim_time / duration_ : 1.0;
  // The ETA extrapolates this session's pace over what is left of the run.
  const double span = duration_ - start_time_;
  const double done = span > 0.0 ? (sim_time - start_time_) / span : 1.0;
  const double eta = done > 0.0 ? elapsed * (1.0 - done) / done : 0.0;
  std::string line = fmt::format("t = {:.6g} s  {:5.1f}%  {:.4g} steps/s  ETA {:.0f} s  contacts {}", sim_time,
                                 100.0 * frac, rate, eta, contacts);
  if (bridges) line += fmt::format("  bridges {}", *bridges);
  if (bonds) line += fmt::format("  bonds {} ({} broken)", (*bonds)[0], (*bonds)[1]);
  line += fmt::format("  particles {}", particles);
  if (imbalance > 0.0) line += fmt::format("  imbalance {:.2f}", imbalance);
  if (tty_) {
    fmt::print(stderr, "\r{}\x1b[K", line);
    drawn_ = true;
  } else {
    fmt::print(stderr, "{}\n", line);
  }
  std::fflush(stderr);
  last_ = now;
  last_steps_ = steps;
}

void Progress::removed(std::int64_t id, double sim_time, std::size_t removed_total) {
  removed_total_ = removed_total;
  if (!enabled_) return;
  if (removal_lines_ == 0 && held_ == 0) removal_window_ = Clock::now();
  if (removal_lines_ < kRemovalLines) {
    ++removal_lines_;
    print_line(fmt::format("removed particle id {} at t = {:.9g} s (left the domain)", id, sim_time));
    return;
  }
  if (held_ == 0) held_from_ = sim_time;
  held_to_ = sim_time;
  if (held_ids_.size() < kRemovalIds) held_ids_.push_back(id);
  ++held_;
}

void Progress::flush_removed() {
  if (held_ == 0) return;
  std::string ids;
  for (std::size_t k = 0; k < held_ids_.size(); ++k) ids += (k ? ", " : "") + std::to_string(held_ids_[k]);
  if (held_ > held_ids_.size()) ids += ", ...";
  print_line(fmt::format("removed {} more particle{} at t = {:.9g} .. {:.9g} s (ids {}); {} removed so far", held_,
                         held_ == 1 ? "" : "s", held_from_, held_to_, ids, removed_total_));
  held_ = 0;
  held_ids_.clear();
}

bool Progress::summary_due() const {
  return enabled_ && std::chrono::duration<double>(Clock::now() - summary_at_).count() >= plain_every_;
}

void Progress::summary(const std::string& line) {
  summary_at_ = Clock::now();
  if (!enabled_ || line.empty() || line == last_summary_) return;
  print_line(line);
  last_summary_ = line;
}

void Progress::finish(double sim_time, std::uint64_t steps) {
  if (!enabled_) return;
  flush_removed();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (drawn_) fmt::print(stderr, "\n");
  drawn_ = false;
  // This session's steps only: a resumed run did the others in an earlier process.
  const std::uint64_t session = steps - start_steps_;
  const std::string resumed = start_steps_ > 0 ? fmt::format(", resumed at step {}", start_steps_) : "";
  fmt::print(stderr, "done: t = {:.6g} s, {} steps in {:.2f} s ({:.4g} steps/s){}\n", sim_time, session, elapsed,
             elapsed > 0 ? static_cast<double>(session) / elapsed : 0.0, resumed);
}

}  // namespace mpdem
