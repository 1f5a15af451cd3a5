#pragma once
// Rigid clumps of spheres (multisphere bodies) as structure-of-arrays: index b is one body. Its
// member spheres are ordinary particles (state/particles.hpp) tagged with the body's id and their
// place in the body's template (Particles::body, Particles::member), so that the neighbour search,
// the contact and field kernels and the outputs see spheres only; what makes them one body is here:
// the interactions sum the members' forces, torques and heat flows onto the body
// (interact/body_sums.hpp), the integrators advance the body (integrate/rigid_bodies.hpp) and set
// the members' state from it. The template (model/clump_template.hpp) gives each member's centre in
// the body's principal frame.
//
// Bodies are owned, never ghosts; they are not reordered: the member index below maps each body's
// members to the particles' current indices and is rebuilt when the particles change order.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"

namespace mpdem {

struct Particles;

inline constexpr std::int64_t kNoBody = -1;  // Particles::body of a free sphere

struct Bodies {
  // --- constant properties [B] ---
  std::vector<std::int64_t> id;  // user id of the body (the CSV's), unique among bodies
  std::vector<int> clump;        // index into Model::clumps (its template)
  std::vector<int> material;     // index into Model::materials (density, heat capacity)
  std::vector<double> mass;      // kg
  std::vector<Vec3> inertia;     // kg m^2, principal moments I1, I2, I3 (body-frame axes)
  std::vector<double> charge;    // C, the body's charge (E and B act on it at the centre of mass)
  // -, 1: prescribed motion (v and w constant; forces do not act), 0: free
  std::vector<std::uint8_t> fixed;
  // --- state [B] ---
  std::vector<Vec3> x;    // m, centre of mass
  std::vector<Vec3> v;    // m/s, velocity of the centre of mass
  std::vector<Vec3> w;    // rad/s, angular velocity (world frame)
  std::vector<Quat> q;    // orientation: principal (body) frame -> world, unit quaternion
  std::vector<double> T;  // K, temperature (one per body)
  // -, periodic image counter per axis: the unwrapped centre is x + image * period; the members'
  // counters are their body's (parallel/periodic_images.hpp wraps a body and its members together)
  std::vector<std::array<std::int32_t, 3>> image;
  // --- accumulators, set by every interaction evaluation [B] ---
  std::vector<Vec3> force;   // N, sum of the members' forces and the body forces
  std::vector<Vec3> torque;  // N m, about the centre of mass
  std::vector<double> heat;  // W, sum of the members' heat flows

  // --- member index, derived from the particles (index_members) ---
  std::vector<std::uint32_t> first;  // [B + 1] body b's members are index[first[b] .. first[b + 1])
  std::vector<std::uint32_t> index;  // [members] particle index of each member, in template order
  // [N particles] 1 for a member sphere or a fixed free sphere: the sphere integrators leave its
  // velocity alone (a member's comes from its body)
  std::vector<std::uint8_t> held;
  // [N particles] the index of the body a member sphere belongs to (0 for a free sphere): loops in
  // particle order reach the (fewer, smaller) body arrays instead of scattering over the particles'
  std::vector<std::uint32_t> owner;
  bool stale = true;  // the particles changed order or number since index_members
  // Scratch of the member loops (not state): R(q) per body [B]; per member slot [members] its
  // force (N), torque about the body's centre (N m) and heat flow (W).
  std::vector<Mat3> rotation;
  std::vector<Vec3> slot_force, slot_torque;
  std::vector<double> slot_heat;

  std::size_t size() const { return id.size(); }
  bool empty() const { return id.empty(); }
  void resize(std::size_t n);
  // f(name, array) for every per-body array (resizing, checkpoints: one section per array).
  template <class F>
  void for_each_array(F&& f) {
    f("id", id);
    f("clump", clump);
    f("material", material);
    f("mass", mass);
    f("inertia", inertia);
    f("charge", charge);
    f("fixed", fixed);
    f("x", x);
    f("v", v);
    f("w", w);
    f("q", q);
    f("T", T);
    f("image", image);
    f("force", force);
    f("torque", torque);
    f("heat", heat);
  }
  // Reorders the bodies by ascending id (outputs that must not depend on the rank count).
  void sort_by_id();
  // Rebuilds first/index/held from the owned particles (Particles::body, Particles::member) when
  // stale. Throws std::logic_error when a body's members are not all present exactly once.
  void index_members(const Particles& p);
  // Keeps the bodies whose keep[b] is true, in order (a rank's own bodies, docs/parallel.md; those
  // a sink left, their members removed by the caller); the member index is then stale.
  void compact(const std::vector<char>& keep);
  // Index of the body with id `body_id`, or -1.
  std::ptrdiff_t find(std::int64_t body_id) const;

 private:
  std::vector<std::int64_t> sorted_ids_;  // ids ascending, with their indices in by_id_
  std::vector<std::uint32_t> by_id_;
};

}  // namespace mpdem
