#pragma once
// A dense granular scene for the neighbour-search engine tests: spheres on a jittered lattice in an open box of
// two-triangle rectangles, with gravity and a frictional contact law (the rectangles and the law also on their own).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>

#include "model/scene.hpp"
#include "scene_builder.hpp"

namespace mpdem::test {

// Rectangle a-b-c-d as two triangles of one group (barriers work from both sides).
inline void add_rect(Scene& s, std::int64_t& next, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const Material& m = s.model.materials.front();
  const int g = s.barriers.group_index("box");
  s.barriers.add(next++, a, b, c, g, m.young, m.poisson, MotionLaw{}, 0.0, kNaN);
  s.barriers.add(next++, a, c, d, g, m.young, m.poisson, MotionLaw{}, 0.0, kNaN);
}

// Open box [0, L]^2 x [0, H]: floor and four walls.
inline void add_box(Scene& s, double L, double H) {
  std::int64_t next = 1;
  add_rect(s, next, {0, 0, 0}, {L, 0, 0}, {L, L, 0}, {0, L, 0});
  add_rect(s, next, {0, 0, 0}, {0, L, 0}, {0, L, H}, {0, 0, H});
  add_rect(s, next, {L, 0, 0}, {L, 0, H}, {L, L, H}, {L, L, 0});
  add_rect(s, next, {0, 0, 0}, {0, 0, H}, {L, 0, H}, {L, 0, 0});
  add_rect(s, next, {0, L, 0}, {L, L, 0}, {L, L, H}, {0, L, H});
}

// Restitution 0.5 and friction mu (static = dynamic, no rolling) for particle pairs and against barriers.
inline void set_contact_law(Scene& s, double mu) {
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->restitution = 0.5;
    c->mu_static = mu;
    c->mu_dynamic = mu;
    c->mu_rolling = 0.0;
  }
}

// A dense granular scene: particles on a jittered cubic lattice of spacing `a` (radii in
// [r0, r0 (1 + spread)]), random velocities up to v0 and spins, in an open box with gravity.
// Spacing near 2 r0 (overlaps below the engine's 5 % check) makes contacts and springs form at once.
inline Scene dense_scene(int nx, int ny, int nz, double r0, double spread, double a, double v0, unsigned seed,
                         double dt) {
  Scene s = make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  set_contact_law(s, 0.5);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> ur(0.0, 1.0);
  std::int64_t id = 100;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double r = r0 * (1.0 + spread * ur(rng));
        const Vec3 x{a * (i + 0.5) + 0.01 * a * u(rng), a * (j + 0.5) + 0.01 * a * u(rng), a * (k + 0.5)};
        const Vec3 v{v0 * u(rng), v0 * u(rng), v0 * u(rng)};
        const Vec3 w{v0 / r0 * u(rng), v0 / r0 * u(rng), v0 / r0 * u(rng)};
        add_particle(s, id, r, x, v, w);
        id += 3;  // ids are not indices
      }
  add_box(s, a * std::max(nx, ny), a * (nz + 2));
  return s;
}

}  // namespace mpdem::test
