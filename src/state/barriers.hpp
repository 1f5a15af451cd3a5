#pragma once
// Barrier elements: planar triangles as structure-of-arrays (physics.md section 7).
// Rest geometry is constant; each element moves rigidly by its motion law: translation u(t) and,
// optionally, a rotation R(theta(t)) about an axis through origin + u(t) (state/rotation_law.hpp):
//   x(t) = u(t) + R (x0 - origin) + origin.
// Loads (force, moment about the centre, pressure) are accumulated by the contact loop.
// An element with an activity window (MotionLaw::active_at) takes part only inside it: its
// state `active` follows the time of move_to, so it is derivable from time alone.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"
#include "state/motion_law.hpp"

namespace mpdem {

struct Barriers {
  // --- constant geometry and properties [M] ---
  std::vector<std::int64_t> id;          // user id
  std::vector<Vec3> p0, p1, p2;          // m, vertices at rest (counter-clockwise seen from the normal side)
  std::vector<Vec3> normal;              // -, unit normal at rest (p1 - p0) x (p2 - p0) / |...|
  std::vector<double> area;              // m^2
  std::vector<int> group;                // index into group_names
  std::vector<int> material;             // index into Model::materials (-1 until the scene assigns one)
  std::vector<double> young;             // Pa, the material's (model/material_variants.hpp); +inf: rigid
  std::vector<double> poisson;           // -, the material's
  std::vector<double> thickness;         // m, fictitious thickness t_b (110)
  std::vector<double> temperature;       // K, fixed temperature; NaN = thermally insulated
  std::vector<MotionLaw> motion;         // rigid motion law
  std::vector<std::string> group_names;  // group index -> name
  // --- rotation: the distinct rotation laws [L] and which one each element follows ---
  std::vector<std::int32_t> rotation_of;  // [M] index into rotations, -1: translation only
  std::vector<RotationLaw> rotations;     // [L] distinct laws (by value)
  // --- state at the current time [M] ---
  std::vector<Vec3> offset;    // m, u(t)
  std::vector<Vec3> velocity;  // m/s, u'(t)
  // --- rotation state at the current time [L] ---
  std::vector<double> angle;  // rad, theta(t)
  std::vector<Mat3> turn;     // -, R(theta(t))
  std::vector<Vec3> spin;     // rad/s, omega(t) axis
  double time = 0.0;          // s, of the state (move_to)
  // --- activity at the current time [M] ---
  std::vector<std::uint8_t> active;  // -, 1: takes part (always 1 for elements without a window)
  std::size_t timed_elements = 0;    // elements with an activity window (MotionLaw::timed)
  // --- loads from particles, accumulated per evaluation [M] ---
  std::vector<Vec3> force;       // N
  std::vector<Vec3> moment;      // N m, about the element's current centre
  std::vector<double> pressure;  // Pa, |normal component of force| / area

  std::size_t size() const { return id.size(); }
  bool rotating() const { return !rotations.empty(); }  // some element has a rotation law
  bool timed() const { return timed_elements > 0; }     // some element has an activity window
  // Appends a triangle; normal and area are derived. Returns false for a degenerate one.
  bool add(std::int64_t bid, const Vec3& a, const Vec3& b, const Vec3& c, int grp, double E, double nu,
           const MotionLaw& law, double t_b, double temp);
  int group_index(const std::string& name);  // finds or creates a group
  // Sets the translation and rotation state of every element at time t.
  void move_to(double t);
  // Sets only the rotation state at time t (the translation stays).
  void turn_to(double t);

  // Current position of the point `rest` (m, rest coordinates) carried by element e.
  Vec3 place(std::size_t e, const Vec3& rest) const {
    const std::int32_t l = rotation_of[e];
    if (l < 0) return rest + offset[e];
    const Vec3& o = rotations[static_cast<std::size_t>(l)].origin;
    return mat_apply(turn[static_cast<std::size_t>(l)], rest - o) + o + offset[e];
  }
  Vec3 vertex(std::size_t e, int k) const;   // current position of vertex k (0..2)
  Vec3 centre(std::size_t e) const;          // current centroid
  Vec3 current_normal(std::size_t e) const;  // -, unit
  Vec3 pivot(std::size_t e) const;           // m, current axis point origin + u(t) (rotating elements)
  // m/s, velocity of element e's surface at the current point `x`: u' + omega x (x - pivot).
  Vec3 surface_velocity(std::size_t e, const Vec3& x) const {
    const std::int32_t l = rotation_of[e];
    if (l < 0) return velocity[e];
    return velocity[e] + cross(spin[static_cast<std::size_t>(l)], x - pivot(e));
  }
  // m/s, the fastest point of any active element: |u'| + |omega| x its vertices' largest distance
  // from the axis (an inactive one is in no list; switching on forces a rebuild).
  double max_point_speed() const;
  // N m, moment of the particles' forces on element e about its rotation axis (along the unit
  // axis; 0 without rotation), from the last evaluation's loads.
  double axis_torque(std::size_t e) const;
  // W, power element e's prescribed motion puts into the particles: -(sum of F . v_surface).
  double drive_power(std::size_t e) const;
};

}  // namespace mpdem
