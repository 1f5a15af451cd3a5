#pragma once
// Small helpers shared by the validation oracles: loading a case's scene, finding particles by
// id (the engine reorders them spatially), thinning long series for the plots, and reading the
// crossing times of a sampled overlap.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "model/scene.hpp"
#include "sim/simulation.hpp"
#include "validate/validation_case.hpp"
#include "scene/scene_reader.hpp"

namespace mpdem::validate {

inline Scene load_case_scene(const CaseContext& ctx) { return load_scene(ctx.case_dir / "scene.toml"); }

// In-process run: no files, no progress line.
inline RunOptions quiet_run() { return RunOptions{{}, false, false}; }

// Index of the particle with user id `id`; throws when absent.
std::size_t index_of_id(const Particles& p, std::int64_t id);

// Every how many samples to keep so that about `target` rows remain (>= 1).
inline std::size_t stride_for(std::size_t samples, std::size_t target) {
  return samples > target ? (samples + target - 1) / target : 1;
}

// Time of the first sample pair where y goes from <= 0 to > 0, linearly interpolated; -1 if none.
double first_rise(const std::vector<double>& t, const std::vector<double>& y);
// Time of the last sample pair where y goes from > 0 to <= 0, linearly interpolated; -1 if none.
double last_fall(const std::vector<double>& t, const std::vector<double>& y);

// Least-squares slope of log(y) over log(x).
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

inline std::string sci(double v) { return fmt::format("{:.3g}", v); }

}  // namespace mpdem::validate
