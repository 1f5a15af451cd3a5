#pragma once
// Builds scenes in code for tests: parameters with test-friendly defaults, one material, and
// particles added one by one.
#include "model/particle_defaults.hpp"
#include "model/scene.hpp"

namespace mpdem::test {

// The trapezoidal rule, as before Verlet became the default: a test that means Verlet says so.
inline Scene make_scene(double dt, double duration) {
  Scene s;
  s.model.params.time.integrator = Integrator::Trapezoidal;
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

// Gives particle i a material of its own, a copy of its present one, and returns it for editing
// (use it at once: adding materials moves them).
inline Material& own_material(Scene& s, std::size_t i) {
  Material m = s.model.materials[static_cast<std::size_t>(s.particles.material[i])];
  m.name = "own" + std::to_string(s.model.materials.size());
  s.model.materials.push_back(m);
  s.particles.material[i] = static_cast<int>(s.model.materials.size()) - 1;
  return s.model.materials.back();
}

// Gives particle i a material of its own: a copy of the scene's first material with E and nu.
inline void give_own_material(Scene& s, std::size_t i, double young, double poisson) {
  Material m = s.model.materials.front();
  m.name = "own" + std::to_string(s.model.materials.size());
  m.young = young;
  m.poisson = poisson;
  s.model.materials.push_back(m);
  s.particles.material[i] = static_cast<int>(s.model.materials.size()) - 1;
}

}  // namespace mpdem::test
