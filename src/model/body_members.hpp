#pragma once
// Where the member spheres of the rigid bodies are and how they move: a member k of body b sits
// at x_b + R(q_b) d_k (d_k its centre in the template's principal frame) and moves with the body,
// v = v_b + w_b x R d_k, with the body's angular velocity, orientation and temperature. Used when
// the bodies are loaded and after every integrator update of the bodies.
#include <vector>

#include "model/clump_template.hpp"
#include "model/scene.hpp"
#include "state/particles.hpp"

namespace mpdem {

// A new body: its id, state and properties as a scene gives them.
struct BodyInit {
  std::int64_t id = 0;
  Vec3 x;             // m, centre of mass
  Vec3 v, w;          // m/s, rad/s (world)
  Quat q;             // the template's frame as written -> world
  double T = 293.15;  // K
  double charge = 0;  // C
  bool fixed = false;
};

// Appends a body of template `clump` and material `material` to p.bodies and its members to p:
// free spheres (fixed = 0: a fixed body's members move with it) whose mass is the body's (the
// damping mass of their contacts, docs/physics.md "Clumps") and whose charge is the body's shared
// in proportion to their volumes (the near field between members of different bodies); ids 0
// (assign_member_ids gives them theirs). The body's principal frame is init.q to_input.
void add_body(const Model& model, int material, int clump, const BodyInit& init, Particles& p);

// kg, the mass particle i stands for in sums over the particles (coarse-grained fields, thermal
// energy, totals): a free sphere's own; a member's share (ClumpTemplate::share) of its body's mass.
// A member's Particles::mass is its body's whole mass, the damping mass of its contacts.
double represented_mass(const Model& model, const Particles& p, std::size_t i);
// m/s, the velocity particle i stands for in such sums: a member's is its body's.
Vec3 represented_velocity(const Particles& p, std::size_t i);

// Sets position, velocity, angular velocity, orientation and temperature of every member.
void place_members(const std::vector<ClumpTemplate>& clumps, Particles& p);
// Sets velocity and angular velocity only (positions unchanged: the second half kick).
void move_members(const std::vector<ClumpTemplate>& clumps, Particles& p);

}  // namespace mpdem
