#pragma once
// Particles as structure-of-arrays: one contiguous array per quantity, index i is one sphere.
// Per-particle constants (set at load, reordered with the particles) come first, then the mutable
// state the integrators advance, then the accumulators the interactions fill each evaluation.
// Material constants (density, E, nu, heat capacity, conductivity, emissivity) are not here: they
// are looked up through `material` in Model::materials. Ids are stable user ids; the array index
// may change when particles are reordered or removed.
//
// Ghost particles (periodic images now, MPI halo copies later) are appended after the owned
// particles in every array: indices [size(), size_with_ghosts()). Only the neighbour search
// creates them (parallel/periodic_images.hpp) and only the interactions read them; everything
// else - integration, checks, output, checkpoints - loops over the owned particles [0, size()).
#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"
#include "state/bodies.hpp"

namespace mpdem {

// A solid sphere of radius r (m) and density rho (kg/m^3): mass 4/3 pi r^3 rho (kg) and moment
// of inertia 2/5 m r^2 (kg m^2, (32)).
inline double sphere_mass(double r, double rho) { return 4.0 / 3.0 * std::numbers::pi * r * r * r * rho; }
inline double sphere_inertia(double mass, double r) { return 0.4 * mass * r * r; }

struct Particles {
  // --- constant properties [N] ---
  std::vector<std::int64_t> id;  // user id, unique
  std::vector<int> material;     // index into Model::materials
  std::vector<double> radius;    // m
  std::vector<double> mass;      // kg, 4/3 pi R^3 rho (rho of the material at load)
  std::vector<double> inertia;   // kg m^2, 2/5 m R^2   (32)
  std::vector<double> charge;    // C
  // -, 1: prescribed motion (v and w constant, x advanced by v dt; forces do not act), 0: free
  std::vector<std::uint8_t> fixed;
  // Clumps (state/bodies.hpp): the id of the body this sphere is a member of (kNoBody: a free
  // sphere), and its index among the body's members (template order; 0 for a free sphere).
  std::vector<std::int64_t> body;
  std::vector<std::uint32_t> member;
  // --- state [N] ---
  std::vector<Vec3> x;    // m, centre
  std::vector<Vec3> v;    // m/s, velocity
  std::vector<Vec3> w;    // rad/s, angular velocity
  std::vector<Quat> q;    // orientation (unit quaternion, body -> world)
  std::vector<double> T;  // K, temperature
  // -, periodic image counter per axis: the unwrapped centre is x + image * period (section 11)
  std::vector<std::array<std::int32_t, 3>> image;
  // --- accumulators, overwritten by every interaction evaluation [N] ---
  std::vector<Vec3> force;   // N, total force
  std::vector<Vec3> torque;  // N m, total torque about the centre
  std::vector<double> heat;  // W, total heat flow into the particle

  // The rigid bodies the member spheres belong to (empty in a scene of spheres only).
  Bodies bodies;

  // Ghosts appended after the owned particles (see above); 0 outside the interactions' rebuilds.
  std::size_t n_ghost = 0;

  std::size_t size() const { return id.size() - n_ghost; }  // owned particles
  std::size_t size_with_ghosts() const { return id.size(); }
  // Removes the ghosts (before particles are added, removed, reordered or written).
  void drop_ghosts();
  // resize, add, permute and compact act on the owned particles and refuse while ghosts exist.
  void resize(std::size_t n);
  void reserve(std::size_t n);  // capacity for n particles, so add() does not over-allocate
  // Appends one particle; mass and inertia are computed from its radius and the density rho.
  void add(std::int64_t pid, int mat, double r, double rho, const Vec3& pos, const Vec3& vel);
  // Sets mass and inertia of particle i from its radius and the density rho (kg/m^3).
  void update_mass(std::size_t i, double rho);
  // Reorders every array: new index k holds old particle order[k].
  void permute(const std::vector<std::uint32_t>& order);
  // Reorders every array by ascending id (outputs that must not depend on the particle order).
  void sort_by_id();
  // Keeps particles whose keep[i] is true, in order.
  void compact(const std::vector<char>& keep);
  // True when some owned particle is fixed: the integrators take their masked paths only then.
  bool any_fixed() const;
  // True when the scene has clumps: the integrators and interactions take their body paths.
  bool has_bodies() const { return !bodies.empty(); }

  // f(name, array) for every per-particle array: the one list that resizing, reordering,
  // removal, checkpoints (one section per array, by name) and later MPI packing use, so that an
  // array added here cannot be forgotten by any of them.
  template <class F>
  void for_each_array(F&& f) {
    f("id", id);
    f("material", material);
    f("radius", radius);
    f("mass", mass);
    f("inertia", inertia);
    f("charge", charge);
    f("fixed", fixed);
    f("body", body);
    f("member", member);
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
};

}  // namespace mpdem
