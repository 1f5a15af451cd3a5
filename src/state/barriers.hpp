#pragma once
// Barrier elements: planar triangles as structure-of-arrays (physics.md section 7).
// Rest geometry is constant; each element translates rigidly by its motion law u(t).
// Loads (force, moment about the centre, pressure) are accumulated by the contact loop.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "state/motion_law.hpp"

namespace mpdem {

struct Barriers {
  // --- constant geometry and properties [M] ---
  std::vector<std::int64_t> id;          // user id
  std::vector<Vec3> p0, p1, p2;          // m, vertices at rest (counter-clockwise seen from the normal side)
  std::vector<Vec3> normal;              // -, unit normal (p1 - p0) x (p2 - p0) / |...|
  std::vector<double> area;              // m^2
  std::vector<int> group;                // index into group_names
  std::vector<int> material;             // index into Model::materials (-1 until the scene assigns one)
  std::vector<double> young;             // Pa, the material's (model/material_variants.hpp); +inf: rigid
  std::vector<double> poisson;           // -, the material's
  std::vector<double> thickness;         // m, fictitious thickness t_b (110)
  std::vector<double> temperature;       // K, fixed temperature; NaN = thermally insulated
  std::vector<MotionLaw> motion;         // rigid motion law
  std::vector<std::string> group_names;  // group index -> name
  // --- state at the current time [M] ---
  std::vector<Vec3> offset;    // m, u(t)
  std::vector<Vec3> velocity;  // m/s, u'(t)
  // --- loads from particles, accumulated per evaluation [M] ---
  std::vector<Vec3> force;       // N
  std::vector<Vec3> moment;      // N m, about the element's current centre
  std::vector<double> pressure;  // Pa, |normal component of force| / area

  std::size_t size() const { return id.size(); }
  // Appends a triangle; normal and area are derived. Returns false for a degenerate one.
  bool add(std::int64_t bid, const Vec3& a, const Vec3& b, const Vec3& c, int grp, double E, double nu,
           const MotionLaw& law, double t_b, double temp);
  int group_index(const std::string& name);  // finds or creates a group
  // Sets offset and velocity of every element at time t.
  void move_to(double t);
  Vec3 vertex(std::size_t e, int k) const;  // current position of vertex k (0..2)
  Vec3 centre(std::size_t e) const;         // current centroid
};

}  // namespace mpdem
