#pragma once
// Sinks: the regions of a scene's [[sink]] entries (docs/scene.md "[[sink]]") where particles are
// taken out of the run. After every step each particle whose centre lies in a sink (closed box
// or cylinder; the first sink in scene order that holds it; a clump body whole, by its centre of
// mass) is marked for removal; the caller
// removes them all at once (Simulation: removed.csv, the energy balance, contact history kept
// for the others). Each sink counts what it removed, and its mass flow rate over the last
// logging interval. Its totals are checkpointed (section "sinks").
#include <cstdint>
#include <string>
#include <vector>

#include "generate/region.hpp"
#include "core/binary_stream.hpp"
#include "model/scene.hpp"
#include "parallel/communicator.hpp"

namespace mpdem {

class Sinks {
 public:
  explicit Sinks(const Model& model);

  // Sets keep[i] = 0 (keep: [N], 1 = stays) for every free sphere with its centre in a sink and
  // every member of a clump body with its centre of mass in one, counts them to that sink (a
  // body's mass once), and returns how many were marked. On several ranks (comm; collective) the
  // counts and the returned number are those of all ranks, so every rank holds the same totals.
  std::size_t mark(Particles& p, std::vector<char>& keep, const Communicator* comm = nullptr);

  // Global log: per sink "<name>.removed" (-), "<name>.removed_mass" (kg), "<name>.mass_rate"
  // (kg/s, removed mass since the previous row / time since it; 0 in the first row).
  static std::vector<std::string> log_columns(const Params& prm);
  // Appends one value per column for a row at time t (s), which starts the next rate interval.
  void log_values(double t, std::vector<double>& out);
  std::string summary() const;  // one line for stderr, "" when nothing was removed
  void save(BinaryWriter& w) const;
  void restore(BinaryReader& r);

  struct State {                // of one sink (checkpointed byte for byte)
    std::uint64_t removed = 0;  // particles removed
    double removed_mass = 0.0;  // kg
    double logged_mass = 0.0;   // kg, removed_mass at the last log row
    double logged_time = 0.0;   // s, time of the last log row
  };
  const std::vector<State>& states() const { return state_; }

 private:
  const Model& model_;
  std::vector<Region> regions_;  // [sinks]
  std::vector<State> state_;     // [sinks]
};

}  // namespace mpdem
