#pragma once
// Where the member spheres of the rigid bodies are and how they move: a member k of body b sits
// at x_b + R(q_b) d_k (d_k its centre in the template's principal frame) and moves with the body,
// v = v_b + w_b x R d_k, with the body's angular velocity, orientation and temperature. Used when
// the bodies are loaded and after every integrator update of the bodies.
#include <vector>

#include "model/clump_template.hpp"
#include "state/particles.hpp"

namespace mpdem {

// Sets position, velocity, angular velocity, orientation and temperature of every member.
void place_members(const std::vector<ClumpTemplate>& clumps, Particles& p);
// Sets velocity and angular velocity only (positions unchanged: the second half kick).
void move_members(const std::vector<ClumpTemplate>& clumps, Particles& p);

}  // namespace mpdem
