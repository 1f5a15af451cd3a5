#include "model/derived_limits.hpp"

#include <cmath>

#include "core/value_range.hpp"
#include "physics/hertz.hpp"
#include "physics/tangential.hpp"
#include "physics/time_step_estimate.hpp"
#include "state/particles.hpp"

namespace mpdem {

bool usable_positive(double v) { return std::isnormal(v) && v > 0.0; }

std::string usable_problem(double v, const std::string& what, const char* unit) {
  if (usable_positive(v)) return "";
  const char* how = std::isnan(v) ? "is not a number" : (std::isinf(v) ? "overflows" : "underflows");
  if (std::isfinite(v) && v < 0.0) how = "is negative";
  return what + " " + how + " (" + number_text(v) + " " + unit + ")";
}

std::string contact_moduli_problem(double young, double poisson) {
  const double E = young, nu = poisson;
  const double G = shear_modulus(E, nu);
  // E* as the time-step estimate computes it, and as the contact table does (a sum of
  // compliances); G* is a sum of compliances in both.
  const double E_pp = effective_modulus(E, nu, E, nu);
  const double G_pp = effective_shear_modulus(G, nu, G, nu);
  const double E_table = 1.0 / (2.0 * (1.0 - nu * nu) / E);
  const double E_rigid = effective_modulus_rigid(E, nu);
  const double G_rigid = effective_shear_modulus_rigid(G, nu);
  std::string p = usable_problem(G, "the shear modulus G = E / (2 (1 + nu))", "Pa");
  if (p.empty()) p = usable_problem(E_pp, "the contact modulus E* of two particles of this material (51)", "Pa");
  if (p.empty()) p = usable_problem(E_table, "the contact modulus E* = 1 / (2 (1 - nu^2) / E)", "Pa");
  if (p.empty()) p = usable_problem(G_pp, "the contact shear modulus G* of two particles of this material", "Pa");
  if (p.empty()) p = usable_problem(E_rigid, "the contact modulus E / (1 - nu^2) against a rigid barrier", "Pa");
  if (p.empty()) p = usable_problem(G_rigid, "the contact shear modulus G / (2 - nu) against a rigid barrier", "Pa");
  // The rigid barrier's moduli are the larger ones.
  if (p.empty()) p = usable_problem(2.0 * E_rigid, "the Hertz normal coefficient 2 E*", "Pa");
  if (p.empty()) p = usable_problem(8.0 * G_rigid, "the Hertz tangential coefficient 8 G*", "Pa");
  if (p.empty()) return "";
  return p + " with young = " + number_text(E) + " Pa and poisson = " + number_text(nu) +
         "; expected a Young's modulus whose contact moduli are finite and > 0 (about 1e-160 to 1e154 Pa)";
}

bool radius_powers_usable(double radius) {
  const double r2 = radius * radius;
  return usable_positive(r2) && usable_positive(r2 * radius) && usable_positive(r2 * r2 * radius);
}

std::string mass_problem(double radius, double density) {
  const double r = radius;
  const double mass = sphere_mass(r, density);  // as Particles::update_mass
  const double inertia = sphere_inertia(mass, r);
  std::string p = usable_problem(mass, "the mass 4/3 pi r^3 rho", "kg");
  if (p.empty()) p = usable_problem(inertia, "the moment of inertia 2/5 m r^2", "kg m^2");
  if (p.empty()) return "";
  return p + " for radius " + number_text(r) + " m and density " + number_text(density) +
         " kg/m^3; expected a finite value > 0 that the run can divide by";
}

std::string time_scale_problem(double radius, double density, double young, double poisson) {
  const double r = radius;
  const double mass = sphere_mass(r, density);
  const double E_pp = effective_modulus(young, poisson, young, poisson);
  std::string p = usable_problem(rayleigh_time(r, density, young, poisson), "the Rayleigh time", "s");
  if (p.empty())
    p = usable_problem(hertz_contact_time(0.5 * mass, E_pp, 0.5 * r, 1.0),
                       "the Hertz contact time of two such particles at 1 m/s", "s");
  if (p.empty()) return "";
  return p + " for radius " + number_text(r) + " m, density " + number_text(density) + " kg/m^3, young " +
         number_text(young) + " Pa; expected finite time scales > 0";
}

std::string thermal_mass_problem(double radius, double density, double heat_capacity) {
  const double r = radius;
  const double mass = sphere_mass(r, density);
  const std::string p = usable_problem(mass * heat_capacity, "the heat capacity m c of the particle", "J/K");
  if (p.empty()) return "";
  return p + " for radius " + number_text(r) + " m, density " + number_text(density) + " kg/m^3, heat_capacity " +
         number_text(heat_capacity) + " J/(kg K); expected a finite value > 0 that the run can divide by";
}

std::string radius_problem(double radius, const Material& m, bool thermal) {
  std::string p = mass_problem(radius, m.density);
  if (p.empty()) p = time_scale_problem(radius, m.density, m.young, m.poisson);
  if (p.empty() && thermal) p = thermal_mass_problem(radius, m.density, m.heat_capacity);
  return p;
}

}  // namespace mpdem
