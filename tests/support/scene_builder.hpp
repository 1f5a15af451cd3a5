#pragma once
// Builds scenes in code for tests: parameters with test-friendly defaults, one material, and
// particles added one by one.
#include "model/particle_defaults.hpp"
#include "model/scene.hpp"

namespace mpdem::test {

inline Scene make_scene(double dt, double duration) {
  Scene s;
  s.model.params.time.dt = dt;
  s.model.params.time.dt_min = dt;
  s.model.params.time.dt_max = dt;
  s.model.params.time.duration = duration;
  Material m;
  m.name = "default";
  s.model.materials.push_back(m);
  return s;
}

// Adds a sphere with the scene's first material; returns its index.
inline std::size_t add_particle(Scene& s, std::int64_t id, double radius, const Vec3& x, const Vec3& v = {},
                                const Vec3& w = {}) {
  const Material& m = s.model.materials.front();
  Particles& p = s.particles;
  p.add(id, 0, radius, m.density, x, v);
  const std::size_t i = p.size() - 1;
  p.w[i] = w;
  take_material_properties(p, i, m);
  return i;
}

}  // namespace mpdem::test
