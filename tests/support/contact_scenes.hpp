#pragma once
// Scene pieces for the contact-mechanics acceptance tests: triangulated barrier grids (flat
// squares, inclines, a plate with a square hole, an open box), material setup, the Hertz rest
// overlap, and small state measurements (momentum, angular momentum).
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

#include "model/scene.hpp"
#include "hertz_oracle.hpp"
#include "scene_builder.hpp"

namespace mpdem::test {

// Sets the scene's first material (used by add_particle for every later particle).
inline void set_material(Scene& s, double density, double young, double poisson) {
  Material& m = s.model.materials.front();
  m.density = density;  // kg/m^3
  m.young = young;      // Pa
  m.poisson = poisson;  // -
}

// Triangulates the parallelogram origin + a u + b v (a, b in [0, 1]) into nu x nv cells, two
// triangles per cell, every cell split along the same diagonal (so an interior vertex is shared by
// 6 triangles). Vertices are computed from their integer grid indices by one formula, so
// neighbouring cells share bit-identical coordinates (a conforming mesh). Normals point along
// u x v. `skip(i, j)` leaves cell (i, j) out (a hole). Returns the number of triangles added.
inline int add_grid(Barriers& b, const std::string& group, const Vec3& origin, const Vec3& u, const Vec3& v, int nu,
                    int nv, double young, double poisson, const std::function<bool(int, int)>& skip = nullptr,
                    double thickness = 0.0) {
  const int g = b.group_index(group);
  auto P = [&](int i, int j) { return origin + u * (static_cast<double>(i) / nu) + v * (static_cast<double>(j) / nv); };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int added = 0;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (skip && skip(i, j)) continue;
      const auto id = static_cast<std::int64_t>(b.size());
      b.add(id, P(i, j), P(i + 1, j), P(i + 1, j + 1), g, young, poisson, MotionLaw{}, thickness, nan);
      b.add(id + 1, P(i, j), P(i + 1, j + 1), P(i, j + 1), g, young, poisson, MotionLaw{}, thickness, nan);
      added += 2;
    }
  return added;
}

// Horizontal square of side `side` centred at c (normal +z), n x n cells.
inline int add_flat_square(Barriers& b, const std::string& group, const Vec3& c, double side, int n, double young,
                           double poisson) {
  const double h = 0.5 * side;
  return add_grid(b, group, c + Vec3{-h, -h, 0.0}, {side, 0.0, 0.0}, {0.0, side, 0.0}, n, n, young, poisson);
}

// Incline through the origin rising against +x: the downhill direction is
// (cos a, 0, -sin a), the upward normal (sin a, 0, cos a). Length L downhill, width W, n cells.
inline int add_incline(Barriers& b, const std::string& group, double angle, double L, double W, int n, double young,
                       double poisson) {
  const Vec3 down{std::cos(angle), 0.0, -std::sin(angle)};
  return add_grid(b, group, Vec3{0.0, -0.5 * W, 0.0}, down * L, {0.0, W, 0.0}, n, n, young, poisson);
}

// Horizontal plate in z = z0 with a centred square hole of side `hole` at the origin: a 3 x 3
// grid of cells of side `hole` without the centre cell (16 triangles).
inline int add_plate_with_hole(Barriers& b, const std::string& group, double z0, double hole, double young,
                               double poisson) {
  return add_grid(b, group, Vec3{-1.5 * hole, -1.5 * hole, z0}, {3.0 * hole, 0.0, 0.0}, {0.0, 3.0 * hole, 0.0}, 3, 3,
                  young, poisson, [](int i, int j) { return i == 1 && j == 1; });
}

// Open box [0, W] x [0, W] x [0, H]: a floor in group `bottom` (n x n cells, normal +z) and four
// walls in group `walls` (normals pointing inwards).
inline void add_open_box(Barriers& b, double W, double H, int n, double young, double poisson) {
  add_grid(b, "bottom", {0, 0, 0}, {W, 0, 0}, {0, W, 0}, n, n, young, poisson);
  add_grid(b, "walls", {0, 0, 0}, {0, 0, H}, {W, 0, 0}, 1, n, young, poisson);  // y = 0, normal +y
  add_grid(b, "walls", {0, W, 0}, {W, 0, 0}, {0, 0, H}, n, 1, young, poisson);  // y = W, normal -y
  add_grid(b, "walls", {0, 0, 0}, {0, W, 0}, {0, 0, H}, n, 1, young, poisson);  // x = 0, normal +x
  add_grid(b, "walls", {W, 0, 0}, {0, 0, H}, {0, W, 0}, 1, n, young, poisson);  // x = W, normal -x
}

// Overlap at which the Hertz force 4/3 E* sqrt(r*) delta^(3/2) equals F   [m]   ((49) inverted)
inline double hertz_rest_overlap(double F, double E_star, double r_star) {
  return std::pow(F / ((4.0 / 3.0) * E_star * std::sqrt(r_star)), 2.0 / 3.0);
}

// Total linear momentum sum m v   [kg m/s]
inline Vec3 momentum(const Particles& p) {
  Vec3 P{};
  for (std::size_t i = 0; i < p.size(); ++i) P += p.mass[i] * p.v[i];
  return P;
}

// Total angular momentum about the origin sum (x x m v + I w)   [kg m^2/s]
inline Vec3 angular_momentum(const Particles& p) {
  Vec3 L{};
  for (std::size_t i = 0; i < p.size(); ++i) L += cross(p.x[i], p.mass[i] * p.v[i]) + p.inertia[i] * p.w[i];
  return L;
}

// Index of the particle with user id `id` (particles are reordered spatially during a run).
inline std::size_t index_of(const Particles& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) return i;
  return p.size();
}

// Sum of Barriers::force over the elements of a group   [N]
inline Vec3 group_force(const Barriers& b, const std::string& group) {
  Vec3 F{};
  for (std::size_t e = 0; e < b.size(); ++e)
    if (b.group_names[static_cast<std::size_t>(b.group[e])] == group) F += b.force[e];
  return F;
}

}  // namespace mpdem::test
