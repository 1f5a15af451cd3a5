// run_on_line: engine vs HertzLine reference (line_comparison.hpp).
#include "validate/line_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "validate/case_support.hpp"

namespace mpdem::validate {

double LineSamples::speed_error() const {
  double e = 0.0;
  for (std::size_t i = 0; i < v_sim.size(); ++i)
    for (std::size_t k = 0; k < t.size(); ++k) e = std::max(e, std::abs(v_sim[i][k] - v_ref[i][k]));
  return e / impact_speed;
}

LineSamples run_on_line(Scene& scene, const Vec3& axis, std::optional<LineWall> wall) {
  const Particles& p0 = scene.particles;
  std::vector<std::size_t> order(p0.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return dot(p0.x[a], axis) < dot(p0.x[b], axis); });

  LineSamples s;
  std::vector<LineSphere> spheres;
  for (std::size_t i : order) {
    s.ids.push_back(p0.id[i]);
    const Material& m = scene.model.materials[static_cast<std::size_t>(p0.material[i])];
    spheres.push_back({dot(p0.x[i], axis), dot(p0.v[i], axis), p0.mass[i], p0.radius[i], m.young, m.poisson});
  }
  for (std::size_t a = 0; a < spheres.size(); ++a) {
    if (wall) s.impact_speed = std::max(s.impact_speed, std::abs(spheres[a].v));
    for (std::size_t b = a + 1; b < spheres.size(); ++b)
      s.impact_speed = std::max(s.impact_speed, std::abs(spheres[a].v - spheres[b].v));
  }
  const double dt = scene.model.params.time.dt, end = scene.model.params.time.duration;
  HertzLine ref(spheres, wall, dt / 20.0);  // RK4 at 1/20 of the engine's step: error << engine's

  const std::size_t n = spheres.size();
  s.v_sim.assign(n, {});
  s.v_ref.assign(n, {});
  s.ov_sim.assign(n - 1, {});
  s.ov_ref.assign(n - 1, {});
  Simulation sim(Scene(scene), quiet_run());
  Particles& p = sim.particles();
  auto sample = [&] {
    s.t.push_back(sim.time());
    std::vector<std::size_t> idx(n);
    for (std::size_t k = 0; k < n; ++k) idx[k] = index_of_id(p, s.ids[k]);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& v = p.v[idx[k]];
      s.v_sim[k].push_back(dot(v, axis));
      s.v_ref[k].push_back(ref.spheres()[k].v);
      s.lateral = std::max(s.lateral, norm(v - dot(v, axis) * axis));
    }
    for (std::size_t k = 0; k + 1 < n; ++k) {
      s.ov_sim[k].push_back(p.radius[idx[k]] + p.radius[idx[k + 1]] - norm(p.x[idx[k + 1]] - p.x[idx[k]]));
      s.ov_ref[k].push_back(ref.overlap(k));
    }
    if (wall) s.wall_ov_sim.push_back(p.radius[idx[0]] - (dot(p.x[idx[0]], axis) - wall->x));
  };
  sample();
  while (sim.time() < end - 0.5 * dt) {
    sim.advance(dt);
    ref.advance_to(sim.time());
    sample();
  }
  s.evaluations = sim.evaluations();
  return s;
}

}  // namespace mpdem::validate
