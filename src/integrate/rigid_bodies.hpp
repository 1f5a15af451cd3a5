#pragma once
// Velocity Verlet for the clumps' rigid bodies (docs/physics.md section 18): the
// centre of mass kicks and drifts like a sphere; the rotation kicks the world angular momentum
// L = R I R^T w by the torque and rotates freely in between (physics/rigid_rotation.hpp), so that
// a torque-free body keeps L to round-off and its energy within O(dt^2) without drift. A fixed
// body keeps v and w and moves with them. After each update the members are set from their bodies
// (model/body_members.hpp).
#include <vector>

#include "model/clump_template.hpp"
#include "model/material.hpp"
#include "state/particles.hpp"

namespace mpdem {

// First half kick (dt/2), drift and free rotation over dt, then the members placed. `rotation`:
// [analysis] rotation (off: the bodies do not turn, w stays 0).
void bodies_kick_drift(Particles& p, const std::vector<ClumpTemplate>& clumps, double dt, bool rotation);
// Second half kick (dt/2) of v and w, then the members' velocities set.
void bodies_kick(Particles& p, const std::vector<ClumpTemplate>& clumps, double dt, bool rotation);
// Explicit Euler of the bodies' temperatures (heat capacity M c of the body's material), then the
// members' temperatures set.
void bodies_heat(Particles& p, const std::vector<Material>& materials, double dt);

}  // namespace mpdem
