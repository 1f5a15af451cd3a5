// The physics beds of `mpdem bench` (docs/benchmark.md "Physics beds").
#include "cli/bench_beds.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/random.hpp"
#include "model/body_members.hpp"
#include "physics/clump_mass.hpp"
#include "scene/clump_reader.hpp"

namespace mpdem::cli {

namespace {

// The --cohesion and --bonds values, chosen for the beds' 2 mm spheres (2500 kg/m^3, E = 1e7 Pa,
// weight m g = 1.03e-4 N): each cohesive contact holds one to four times a sphere's weight, so the
// bed is cohesive but stays as it settled; the bonds are ~1000x stronger than a settled bed loads them.
constexpr double kSurfaceEnergy = 0.05;    // J/m^2, JKR w: pull-off 1.5 pi w r* = 1.15 m g (r* = 0.5 mm)
constexpr double kCohesionDensity = 5e4;   // J/m^3, SJKR k: overlap at zero load 0.9 um, pull there 1.4 m g
constexpr double kSurfaceTension = 0.072;  // N/m, water: Willett's force at touching 2 pi R gamma cos = 4.1 m g
constexpr double kContactAngle = 20.0;     // deg
constexpr double kLiquidFraction = 1e-3;   // -, V = phi (V_i + V_j) / 2: rupture gap 0.19 mm
constexpr double kViscosity = 1e-3;        // Pa s, water
constexpr double kBondYoung = 1e7;         // Pa, E_b: the spheres' E
constexpr double kBondRadiusRatio = 0.5;   // -, R_b = 0.5 min(R_i, R_j)
constexpr double kBondStrength = 1e6;      // Pa, tensile and shear strength
constexpr double kBondDamping = 0.05;      // -, of each bond spring's critical damping
constexpr double kBondGap = 1e-5;          // m, bonds between spheres closer than this at t = 0

}  // namespace

std::string bench_bed_name(const BenchArgs& a) {
  std::string name;
  const auto part = [&](const std::string& s) { name += (name.empty() ? "" : "+") + s; };
  if (a.clumps) part("clumps");
  if (a.cohesion != "none") part(a.cohesion);
  if (a.bonds) part("bonds");
  return name.empty() ? "plain" : name;
}

// At every sphere of the data file a tetrahedral clump of four spheres of radius 0.55 r (r the
// file's smallest radius) with centres 0.26 r from its centre along the diagonals of a cube
// (inscribed in the sphere r: no overlaps at the start), turned by a rotation drawn from its id,
// at rest.
void add_clump_bed(const LammpsData& d, Scene& s) {
  double r = std::numeric_limits<double>::infinity();
  for (const LammpsAtom& at : d.atoms) r = std::min(r, 0.5 * at.diameter);
  const double a = 0.26 * r, rm = 0.55 * r;  // m
  ClumpTemplate t;
  t.name = "tetra";
  t.shape = clump_mass_properties({{{a, a, a}, rm}, {{a, -a, -a}, rm}, {{-a, a, -a}, rm}, {{-a, -a, a}, rm}});
  s.model.clumps.push_back(t);
  s.particles.reserve(4 * d.atoms.size());
  for (const LammpsAtom& at : d.atoms) {
    Rng rng(static_cast<std::uint64_t>(at.id));
    BodyInit init;
    init.id = at.id;
    init.x = at.x;
    init.q = quat_normalized({rng.normal(), rng.normal(), rng.normal(), rng.normal()});  // uniform on SO(3)
    init.T = s.model.materials.front().temperature;
    add_body(s.model, 0, 0, init, s.particles);
  }
  assign_member_ids(s.particles, "bench");
}

void add_bed_physics(const BenchArgs& a, Params& prm) {
  ContactParams& c = prm.contact;
  if (a.cohesion == "jkr" || a.cohesion == "sjkr") {  // on the walls too
    for (ContactLawParams* law : {&c.particle_particle, &c.particle_barrier}) {
      law->cohesion = a.cohesion;
      if (a.cohesion == "jkr") law->law_keys["surface_energy"] = kSurfaceEnergy;
      else law->law_keys["cohesion_energy_density"] = kCohesionDensity;
    }
  } else if (a.cohesion == "bridges") {  // between the spheres and with the walls
    LiquidBridgeKeys k;
    k.surface_tension = kSurfaceTension;
    k.contact_angle = kContactAngle * std::numbers::pi / 180.0;
    k.liquid_fraction = kLiquidFraction;
    k.viscosity = kViscosity;
    c.liquid_bridge.defaults = k;
  }
  if (a.bonds) {
    BondKeys k;
    k.young = kBondYoung;
    k.radius_ratio = kBondRadiusRatio;
    k.tensile_strength = kBondStrength;
    k.shear_strength = kBondStrength;
    k.damping = kBondDamping;
    k.gap = kBondGap;
    prm.bonds.defaults = k;
  }
}

std::string bed_physics_summary(const BenchArgs& a) {
  std::string s;
  if (a.cohesion == "jkr") s = fmt::format("JKR adhesion, surface energy {:g} J/m^2 (walls too)", kSurfaceEnergy);
  if (a.cohesion == "sjkr")
    s = fmt::format("SJKR adhesion, cohesion energy density {:g} J/m^3 (walls too)", kCohesionDensity);
  if (a.cohesion == "bridges")
    s = fmt::format("liquid bridges (Willett): surface tension {:g} N/m, contact angle {:g} deg, liquid fraction "
                    "{:g}, viscosity {:g} Pa s (walls too)",
                    kSurfaceTension, kContactAngle, kLiquidFraction, kViscosity);
  if (a.bonds)
    s += fmt::format("{}parallel bonds within a gap of {:g} m: E_b = {:g} Pa, radius ratio {:g}, strengths {:g} Pa, "
                     "damping {:g}",
                     s.empty() ? "" : "; ", kBondGap, kBondYoung, kBondRadiusRatio, kBondStrength, kBondDamping);
  return s;
}

}  // namespace mpdem::cli
