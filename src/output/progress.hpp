#pragma once
// Progress on stderr: simulated time, percent done, steps/s, ETA and contacts (and bridges). On a terminal
// one line is redrawn in place a few times a second; otherwise (a log file, CI) a plain line
// is printed every `plain_every` seconds of wall time. Removed particles are reported here too,
// a few lines per such interval at most: a pour can remove thousands.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mpdem {

class Progress {
 public:
  // start_time (s) and start_steps: where this session starts (a resumed run: at its checkpoint),
  // so that steps/s and the ETA count this session's steps only.
  Progress(double duration, double plain_every_seconds, bool enabled, double start_time = 0.0,
           std::uint64_t start_steps = 0);
  // imbalance: several ranks, max / mean cost per rank (Interactions::imbalance; 0: not shown).
  // bridges: the liquid bridges held, shown after the contacts (a scene with cohesion; none: not shown).
  // bonds: the bonds intact and broken so far (a scene with [bonds]; none: not shown).
  void update(double sim_time, std::uint64_t steps, std::size_t contacts, std::size_t particles, double imbalance = 0.0,
              std::optional<std::uint64_t> bridges = std::nullopt,
              std::optional<std::array<std::uint64_t, 2>> bonds = std::nullopt);
  // A particle removed at the domain boundary at sim_time (s); removed_total counts the whole run.
  void removed(std::int64_t id, double sim_time, std::size_t removed_total);
  void finish(double sim_time, std::uint64_t steps);
  // The inlets' and sinks' totals (Simulation): a line at most once per `plain_every` interval of
  // wall time, and only when it says something new - a thousand removals a second get one line.
  bool summary_due() const;
  void summary(const std::string& line);  // prints it unless empty or the same as the last one

  static constexpr int kRemovalLines = 3;         // removals printed one by one per interval
  static constexpr std::size_t kRemovalIds = 10;  // ids listed in an interval's summary line

 private:
  using Clock = std::chrono::steady_clock;
  void print_line(const std::string& line);  // a whole line, clearing a progress line drawn in place
  void flush_removed();                      // the summary of the removals held back, if any

  double duration_;     // s, simulated
  double plain_every_;  // s, wall time
  bool enabled_;
  bool tty_;
  bool drawn_ = false;  // a progress line is on the terminal without its newline
  double start_time_;   // s, simulated time at the start of this session
  std::uint64_t start_steps_;
  Clock::time_point start_, last_;
  std::uint64_t last_steps_;
  Clock::time_point removal_window_;        // start of the interval the removal lines count in
  int removal_lines_ = 0;                   // removals printed one by one in it
  std::size_t held_ = 0;                    // removals in it beyond those
  std::vector<std::int64_t> held_ids_;      // ids of the first kRemovalIds of them
  double held_from_ = 0.0, held_to_ = 0.0;  // s, simulated time of the first and last of them
  std::size_t removed_total_ = 0;           // particles removed in the whole run so far
  Clock::time_point summary_at_;            // when the last summary line was printed
  std::string last_summary_;                // its text
};

}  // namespace mpdem
