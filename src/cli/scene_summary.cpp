#include "cli/scene_summary.hpp"

#include "model/body_members.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "check/bond_summary.hpp"
#include "check/clump_summary.hpp"
#include "check/cohesion_summary.hpp"
#include "contact/contact_table.hpp"
#include "model/body_members.hpp"
#include "physics/barrier_moduli.hpp"
#include "physics/time_step_estimate.hpp"
#include "sim/simulation.hpp"

namespace mpdem::cli {

namespace {
std::string speed_text(const TimeStepAdvice& a) {
  if (a.reference_speed > a.impact.speed)
    return fmt::format("{:.3g} m/s (the floor; expected impacts are slower)", a.reference_speed);
  return fmt::format("{:.3g} m/s (expected impact speed: {})", a.reference_speed, a.impact.origin());
}
std::string rayleigh_text(const TimeStepAdvice& a) {
  return a.hertz ? fmt::format("Rayleigh time {:.4g} s", a.rayleigh)
                 : std::string("Rayleigh time not used (no Hertz contact)");
}
// Which contact times: Hertz at the reference speed, linear pi sqrt(m*/k_n), or both.
std::string contact_text(const TimeStepAdvice& a) {
  if (!a.linear) return "Hertz contact time at " + speed_text(a);
  if (!a.hertz) return "linear-law contact time pi sqrt(m*/k_n)";
  return "contact time (Hertz at " + speed_text(a) + ", linear pi sqrt(m*/k_n))";
}
}  // namespace

TimeStepAdvice time_step_advice(const Scene& scene) {
  const Particles& p = scene.particles;
  const Barriers& b = scene.barriers;
  TimeStepAdvice a;
  a.impact = expected_impact_speed(scene);
  // A floor for scenes with little motion: slower impacts last longer.
  a.reference_speed = std::max(a.impact.speed, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  double rayleigh = inf, pp = inf, pb = inf;
  double stiffest_barrier = 0.0, stiffest_nu = 0.0;
  std::vector<int> barrier_materials;  // distinct, >= 0
  for (std::size_t e = 0; e < b.size(); ++e) {
    if (b.young[e] > stiffest_barrier) {
      stiffest_barrier = b.young[e];
      stiffest_nu = b.poisson[e];
    }
    if (b.material[e] >= 0 &&
        std::find(barrier_materials.begin(), barrier_materials.end(), b.material[e]) == barrier_materials.end())
      barrier_materials.push_back(b.material[e]);
  }
  ContactTable table;  // the laws the run's kernels will use
  table.build(scene.model);
  // One sphere of radius r (m) and mass (kg) of material k: its contact times with an equal
  // sphere and with the barriers, by the law of each pair, and its Rayleigh time if an elastic
  // law (Law::kElastic: one that uses the material's E) acts on it.
  bool any = false;
  const auto take = [&](double r, double mass, std::size_t k) {
    any = true;
    const Material& m = scene.model.materials[k];
    bool hertz = false;
    // Each law's own contact time (contact/laws/): an elastic law (Hertz-like) at the reference
    // speed with the materials' modulus, a law of constant stiffness at any speed.
    const PairLaw& law = table.particle_pair(k, k);
    with_law(law.law, [&]<class Law>(std::type_identity<Law>) {
      if constexpr (Law::kElastic) {
        hertz = true;
        const double Epp = effective_modulus(m.young, m.poisson, m.young, m.poisson);
        pp = std::min(pp, Law::contact_time(law, Epp, 0.5 * mass, 0.5 * r, a.reference_speed));
      } else {
        a.linear = true;
        pp = std::min(pp, Law::contact_time(law, 0.0, 0.5 * mass, 0.5 * r, a.reference_speed));
      }
    });
    if (stiffest_barrier > 0.0) {
      // A rigid barrier (E = +inf) is the stiffest; E* is then the particle's E/(1 - nu^2).
      const double Epb = barrier_effective_modulus(m.young, m.poisson, stiffest_barrier, stiffest_nu);
      const auto barrier_time = [&](const PairLaw& bl) {
        with_law(bl.law, [&]<class Law>(std::type_identity<Law>) {
          if constexpr (Law::kElastic) {
            hertz = true;
            pb = std::min(pb, Law::contact_time(bl, Epb, mass, r, a.reference_speed));
          } else {
            a.linear = true;
            pb = std::min(pb, Law::contact_time(bl, 0.0, mass, r, a.reference_speed));
          }
        });
      };
      if (barrier_materials.empty()) barrier_time(PairLaw{});  // the default law
      for (const int bm : barrier_materials) barrier_time(table.barrier_pair(k, static_cast<std::size_t>(bm)));
    }
    if (hertz) {
      a.hertz = true;
      rayleigh = std::min(rayleigh, rayleigh_time(r, m.density, m.young, m.poisson));
    }
    // A viscous liquid bridge: the lubrication force 6 pi mu r*^2 v_n / S_min is a dashpot of
    // c = 6 pi mu r* / min_gap (S_min = min_gap r*), whose relaxation time m*/c the step must resolve.
    const auto viscous = [&](const BridgeLaw& br, double r_star, double m_star) {
      if (br.model == BridgeModel::none || !(br.viscosity > 0.0)) return;
      const double c = 6.0 * std::numbers::pi * br.viscosity * r_star / br.min_gap;  // N s/m
      a.viscous = a.viscous > 0.0 ? std::min(a.viscous, m_star / c) : m_star / c;
    };
    viscous(table.particle_bridge(k, k), 0.5 * r, 0.5 * mass);
    for (const int bm : barrier_materials) viscous(table.barrier_bridge(k, static_cast<std::size_t>(bm)), r, mass);
  };
  for (std::size_t i = 0; i < p.size(); ++i) take(p.radius[i], p.mass[i], static_cast<std::size_t>(p.material[i]));
  // The inlets' smallest particles (a silo filled from empty has none at t = 0).
  for (const InletSpec& in : scene.model.params.inlets) {
    const int k = in.material.empty() ? 0 : scene.model.material_index(in.material);
    const double r = in.radius.smallest();
    if (k < 0 || static_cast<std::size_t>(k) >= scene.model.materials.size() || !(r > 0.0)) continue;
    take(r, sphere_mass(r, scene.model.materials[static_cast<std::size_t>(k)].density), static_cast<std::size_t>(k));
  }
  if (!any) return a;
  a.rayleigh = std::isfinite(rayleigh) ? rayleigh : 0.0;
  a.contact_pp = pp;
  a.contact_pb = std::isfinite(pb) ? pb : 0.0;
  a.recommended = std::min(std::isfinite(rayleigh) ? 0.2 * rayleigh : inf, std::min(pp, pb) / 50.0);
  if (a.viscous > 0.0) a.recommended = std::min(a.recommended, 0.5 * a.viscous);
  // A bond's normal spring, with the contacts' safety factor.
  a.bond = bond_summary(scene).time_step;
  if (a.bond > 0.0) a.recommended = std::min(a.recommended, a.bond / 50.0);
  return a;
}

void print_summary(const Scene& scene) {
  const Particles& p = scene.particles;
  const Barriers& b = scene.barriers;
  const Params& prm = scene.model.params;
  double mass = 0.0, rmin = std::numeric_limits<double>::infinity(), rmax = 0.0, q = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    mass += represented_mass(scene.model, p, i);  // a member: its share of the body's
    rmin = std::min(rmin, p.radius[i]);
    rmax = std::max(rmax, p.radius[i]);
    q += p.charge[i];
  }
  fmt::print("scene: {}\n", scene.file.string());
  if (p.size() == 0)
    fmt::print("particles: 0 at t = 0{}\n", prm.inlets.empty() ? "" : " (the inlets below insert them)");
  else
    fmt::print("particles: {}  total mass {:.6g} kg  radius {:.4g} .. {:.4g} m  total charge {:.4g} C\n", p.size(),
               mass, rmin, rmax, q);
  fmt::print("materials: {}\n", scene.model.materials.size());
  for (const Material& m : scene.model.materials)
    fmt::print("  {:<16} density {:.6g} kg/m^3  E {}  nu {:.4g}\n", m.name, m.density,
               is_rigid(m) ? std::string("rigid") : fmt::format("{:.6g} Pa", m.young), m.poisson);
  for (const std::string& line : clump_summary_lines(scene)) fmt::print("{}\n", line);
  for (const std::string& line : cohesion_summary_lines(scene)) fmt::print("{}\n", line);
  for (const std::string& line : bond_summary_lines(scene)) fmt::print("{}\n", line);
  fmt::print("barriers: {} triangles in {} groups\n", b.size(), b.group_names.size());
  for (std::size_t g = 0; g < b.group_names.size(); ++g) {
    std::size_t n = 0, rigid = 0;
    double area = 0.0;
    for (std::size_t e = 0; e < b.size(); ++e)
      if (b.group[e] == static_cast<int>(g)) {
        ++n;
        rigid += std::isinf(b.young[e]) ? 1 : 0;
        area += b.area[e];
      }
    fmt::print("  {:<16} {} triangles{}, area {:.6g} m^2\n", b.group_names[g], n,
               rigid == 0 ? "" : (rigid == n ? " (rigid)" : " (" + std::to_string(rigid) + " rigid)"), area);
  }
  print_entries(scene);
  // phi is the trapezoidal rule's alone (Verlet, the default, refuses the key).
  const std::string integrator = prm.time.integrator == Integrator::Verlet
                                     ? std::string("verlet")
                                     : fmt::format("trapezoidal  phi {}", prm.time.phi);
  fmt::print("integrator: {}  dt {:.4g} s  duration {:.6g} s  ({} steps)\n", integrator, prm.time.dt, prm.time.duration,
             fixed_step_count(prm.time.duration, prm.time.dt));
  const TimeStepAdvice a = time_step_advice(scene);
  fmt::print("time step: {}; {}: particle-particle {:.4g} s", rayleigh_text(a), contact_text(a), a.contact_pp);
  if (a.contact_pb > 0.0) fmt::print(", particle-barrier {:.4g} s", a.contact_pb);
  if (a.viscous > 0.0) fmt::print("; viscous bridges' relaxation time m*/c {:.4g} s", a.viscous);
  if (a.bond > 0.0) fmt::print("; bonds 2/omega {:.4g} s", a.bond);
  fmt::print("\nrecommended dt <= {:.4g} s ({}{}{})\n", a.recommended,
             a.hertz ? "min of 0.2 x Rayleigh time and contact time / 50" : "contact time / 50",
             a.viscous > 0.0 ? ", and 0.5 x the bridges' relaxation time" : "",
             a.bond > 0.0 ? ", and the bonds' time step / 50" : "");
}

bool warn_about_time_step(const Scene& scene) {
  const TimeStepAdvice a = time_step_advice(scene);
  if (!(a.recommended > 0.0 && scene.model.params.time.dt > a.recommended)) return false;
  fmt::print(stderr,
             "warning: time.dt = {:.4g} s exceeds the recommended {:.4g} s ({}{} {:.4g} s / 50{}); contacts{} may be "
             "under-resolved\n",
             scene.model.params.time.dt, a.recommended, a.hertz ? rayleigh_text(a) + " x 0.2, " : "", contact_text(a),
             std::min(a.contact_pp, a.contact_pb > 0 ? a.contact_pb : a.contact_pp),
             a.bond > 0.0 ? fmt::format(", bonds' time step {:.4g} s / 50", a.bond) : "",
             a.bond > 0.0 ? " or bonds" : "");
  return true;
}

std::size_t print_problems(const SceneProblems& problems, bool for_run) {
  std::size_t errors = 0;
  for (const SceneProblem& p : problems) {
    const bool error = for_run ? p.stops_run : p.severity == Severity::Error;
    errors += error ? 1 : 0;
    fmt::print(stderr, "{}: {}\n", error ? "error" : "warning", located_text(p));
  }
  return errors;
}

}  // namespace mpdem::cli
