#pragma once
// The clumps' share of an evaluation: the member spheres' forces, torques and heat flows summed
// onto their bodies, and the body forces (gravity, E, B, drag: interact/body_forces.hpp) applied
// to each body at its centre of mass with the body's mass and charge (the members take none).
#include "model/params.hpp"
#include "state/particles.hpp"

namespace mpdem {

// Sets bodies.force, torque (about the centre of mass) and heat from the members, in each body's
// template order (independent of the particle order and the thread count), plus the body forces;
// returns the power the dissipative body forces take from the bodies (W).
double sum_onto_bodies(Particles& p, const FieldParams& fields, bool thermal);
// W, -sum (F.v + T.w) over the fixed bodies (T.w only with rotation): the power of what holds them
// to their prescribed motion, as for fixed spheres.
double fixed_body_power(const Particles& p, bool rotation);

}  // namespace mpdem
