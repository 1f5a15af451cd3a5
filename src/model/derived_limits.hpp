#pragma once
// Load-time limits on what the run derives from inputs that are each in range: a radius,
// density or Young's modulus can still make the mass, the moment of inertia, the contact moduli
// or the time scales overflow or underflow (radius 1e308: mass inf; density 1e-320: mass 0;
// young 1e308: E* inf), which the run would only notice at its first step, far from the input.
// Each check returns "" when the values are usable, else what is wrong; the readers add the
// file, line and key.
#include <string>

#include "model/material.hpp"

namespace mpdem {

// Finite, > 0 and not subnormal: a value the run can divide by.
bool usable_positive(double v);

// "" when v is usable_positive, else "<what> overflows (inf <unit>)", "... underflows (0 m^3)",
// "... is not a number" or "... is negative".
std::string usable_problem(double v, const std::string& what, const char* unit);

// The contact moduli of two particles of one material, E* (51) and Mindlin's G*, as the
// time-step estimate and the contact table compute them, against a rigid barrier too, and the
// Hertz coefficients 2 E* and 8 G*. Any pair of materials that pass is usable as well.
std::string contact_moduli_problem(double young, double poisson);

// True when r^2, r^3 and r^5 are usable: a mass problem is then the density's, not the radius's.
bool radius_powers_usable(double radius);

// Mass 4/3 pi r^3 rho and moment of inertia 2/5 m r^2 (32), computed as Particles does.
std::string mass_problem(double radius, double density);

// Rayleigh time and the Hertz contact time of two equal particles at 1 m/s
// (physics/time_step_estimate.hpp).
std::string time_scale_problem(double radius, double density, double young, double poisson);

// Heat capacity of the particle, m c (the temperature rate divides by it).
std::string thermal_mass_problem(double radius, double density, double heat_capacity);

// The three above for a particle of `radius` of material `m` (the heat capacity with `thermal`).
std::string radius_problem(double radius, const Material& m, bool thermal);

}  // namespace mpdem
