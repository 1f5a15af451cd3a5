#pragma once
// RateHistory: each particle's start rates of the last accepted step (translational and angular
// acceleration), for the trapezoidal rule's predictor, which extrapolates them linearly to the
// end of the next step (docs/integrators.md, "Predictor"). The rates follow their particle by id:
// through the rebuilds' reordering, removals and insertions, migration to another rank
// (records()/set_records(), attached to the migrating particles) and checkpoints, so a run's
// results do not depend on when those happen nor on the number of ranks.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

// One particle's previous start rates (checkpointed byte for byte).
struct RateRecord {
  std::int64_t id = -1;
  Vec3 a;  // m/s^2, F/m
  Vec3 b;  // rad/s^2, M/I
};
static_assert(sizeof(RateRecord) == 56, "RateRecord is a checkpoint record: a change is a format change");

class RateHistory {
 public:
  // After an accepted step of length dt (s): its start rates a0, b0 [N] of the particles id [N]
  // (the step's order). Takes the vectors' storage (they are swapped with the history's own).
  void remember(std::span<const std::int64_t> id, std::vector<Vec3>& a0, std::vector<Vec3>& b0, double dt);
  // Lines the previous rates up with the particles id [N]: a_prev()[i], b_prev()[i] are particle
  // i's, or its current a0[i], b0[i] (no extrapolation) for a particle without history. False
  // (and nothing to read) when no step has been remembered.
  bool align(std::span<const std::int64_t> id, std::span<const Vec3> a0, std::span<const Vec3> b0);
  const Vec3* a_prev() const { return a_prev_; }
  const Vec3* b_prev() const { return b_prev_; }
  double dt() const { return dt_; }  // s, the remembered step's length (0: none)

  // Every remembered particle's record, by id (migration, checkpoints).
  std::vector<RateRecord> records() const;
  // Replaces the history by these records (any order; ids unique) of a step of length dt (s).
  void set_records(std::vector<RateRecord> records, double dt);

 private:
  std::vector<std::int64_t> id_;             // [N] the remembered step's particles, in its order
  std::vector<Vec3> a_, b_;                  // [N] m/s^2, rad/s^2: their start rates
  std::vector<RateRecord> carried_;          // by ascending id: records set from outside (set_records)
  std::vector<Vec3> aligned_a_, aligned_b_;  // [N] align()'s result when the order changed
  const Vec3* a_prev_ = nullptr;
  const Vec3* b_prev_ = nullptr;
  double dt_ = 0.0;  // s
};

}  // namespace mpdem
