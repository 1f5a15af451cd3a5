#pragma once
// Runs a scene whose spheres move along one line (head-on impacts, chains, a sphere hitting a
// flat barrier) through the engine, step by step, beside the HertzLine reference started from the
// same initial state, and samples both.
#include <optional>
#include <vector>

#include "model/scene.hpp"
#include "validate/hertz_line.hpp"

namespace mpdem::validate {

struct LineSamples {
  std::vector<std::int64_t> ids;                    // particle ids, in order along the line
  std::vector<double> t;                            // s, sample times (every step, from 0)
  std::vector<std::vector<double>> v_sim, v_ref;    // m/s, [sphere][sample], velocity along the line
  std::vector<std::vector<double>> ov_sim, ov_ref;  // m, [pair k, k+1][sample], overlap (> 0 touching)
  std::vector<double> wall_ov_sim;                  // m, [sample], overlap of the first sphere with the wall
  double impact_speed = 0.0;                        // m/s, largest initial closing speed
  double lateral = 0.0;                             // m/s, largest velocity component off the line
  std::uint64_t evaluations = 0;
  // max over samples and spheres of |v_sim - v_ref| / impact_speed
  double speed_error() const;
};

// Runs `scene` for its [time] duration with fixed steps of its dt. `axis`: unit vector of the
// line; `wall`: the flat barrier the first sphere hits (its surface coordinate along the axis).
LineSamples run_on_line(Scene& scene, const Vec3& axis, std::optional<LineWall> wall);

}  // namespace mpdem::validate
