// Thermal validation cases (thesis "Thermal validation", figures 15-17): two touching particles
// with a temperature gradient exchanging heat by conduction, and single particles cooling in air
// at several wind speeds by convection.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "validate/case_support.hpp"
#include "validate/plot_csv.hpp"

namespace mpdem::validate {

namespace {

constexpr double kPi = std::numbers::pi;

// The material of particle i
const Material& material_of(const Scene& s, std::size_t i) {
  return s.model.materials[static_cast<std::size_t>(s.particles.material[i])];
}
// Heat capacity m c of particle i   [J/K]
double capacity(const Scene& s, std::size_t i) { return s.particles.mass[i] * material_of(s, i).heat_capacity; }

// Two touching spheres: T1 - T2 = (T1 - T2)(0) exp(-G (1/C1 + 1/C2) t), G = K A / d with the lens
// area A (89), the harmonic-mean conductivity K and the centre distance d (90), towards the
// capacity-weighted mean.
CaseResult thermal_contact(const CaseContext& ctx) {
  Scene scene = load_case_scene(ctx);
  const double dt = scene.model.params.time.dt, end = scene.model.params.time.duration;
  const Particles& p0 = scene.particles;
  const std::int64_t id1 = p0.id[0], id2 = p0.id[1];
  const double R1 = p0.radius[0], R2 = p0.radius[1], d = norm(p0.x[0] - p0.x[1]);
  const double xc = (d * d + R1 * R1 - R2 * R2) / (2.0 * d);
  const double A = kPi * (R1 * R1 - xc * xc);  // m^2, (89)
  const double k1 = material_of(scene, 0).conductivity, k2 = material_of(scene, 1).conductivity;
  const double K = 2.0 * k1 * k2 / (k1 + k2);
  const double C1 = capacity(scene, 0), C2 = capacity(scene, 1);
  const double lambda = K * A / d * (1.0 / C1 + 1.0 / C2);  // 1/s
  const double T10 = p0.T[0], T20 = p0.T[1], Tm = (C1 * T10 + C2 * T20) / (C1 + C2);
  auto exact = [&](double T0, double t) { return Tm + (T0 - Tm) * std::exp(-lambda * t); };

  Simulation sim(Scene(scene), quiet_run());
  PlotCsv plot("thermal_contact: two touching particles with a temperature gradient", "time t [s]",
               "temperature T [K]");
  plot.add_series(fmt::format("particle {}", id1));
  plot.add_series(fmt::format("particle {}", id2));
  plot.add_row(0.0, {T10, T10, T20, T20});
  double worst = 0.0;
  while (sim.time() < end - 0.5 * dt) {
    sim.advance(dt);
    const Particles& p = sim.particles();
    const std::size_t i = index_of_id(p, id1), j = index_of_id(p, id2);
    const double t = sim.time();
    worst = std::max({worst, std::abs(p.T[i] - exact(T10, t)), std::abs(p.T[j] - exact(T20, t))});
    plot.add_row(t, {p.T[i], exact(T10, t), p.T[j], exact(T20, t)});
  }
  plot.write(ctx.output_dir / "thermal_contact.csv");
  CaseResult r;
  r.name = "thermal_contact";
  r.oracle = "T_i = T_m + (T_i0 - T_m) exp(-K A/d (1/C1 + 1/C2) t), lens area (89), conduction (90); "
             "error = max |T - T_exact| / |T1 - T2|(0)";
  r.tolerance = 1e-3;
  r.error = worst / std::abs(T10 - T20);
  r.pass = r.error <= r.tolerance;
  r.note = fmt::format("lambda = {} 1/s, lambda dt = {}, weighted mean {:.3f} K", sci(lambda), sci(lambda * dt), Tm);
  r.plots = {"thermal_contact"};
  return r;
}

// h(v) of (93), written out here independently of the engine; v clamped to the fit's [0, 20] m/s
double h_fit(double v) {
  v = std::clamp(v, 0.0, 20.0);
  return 12.15335 - 1.1630 * v + 11.630 * std::sqrt(v);
}

// Particles moving through still air: T - T_air = (T0 - T_air) exp(-t / tau), tau = m c / (h A_s).
CaseResult wind_cooling(const CaseContext& ctx) {
  Scene scene = load_case_scene(ctx);
  const double dt = scene.model.params.time.dt, end = scene.model.params.time.duration;
  const ThermalParams& th = scene.model.params.thermal;
  const Particles& p0 = scene.particles;
  const std::size_t n = p0.size();
  std::vector<std::int64_t> ids(n);
  std::vector<double> tau(n), T0(n), speed(n);
  for (std::size_t i = 0; i < n; ++i) {
    ids[i] = p0.id[i];
    speed[i] = norm(p0.v[i] - th.air_velocity);
    tau[i] = capacity(scene, i) / (h_fit(speed[i]) * 4.0 * kPi * p0.radius[i] * p0.radius[i]);
    T0[i] = p0.T[i];
  }
  const double Tair = th.air_temperature;
  auto exact = [&](std::size_t i, double t) { return Tair + (T0[i] - Tair) * std::exp(-t / tau[i]); };
  Simulation sim(Scene(scene), quiet_run());
  PlotCsv plot("wind_cooling: particles cooling in air at several wind speeds", "time t [s]", "temperature T [K]");
  for (std::size_t i = 0; i < n; ++i) plot.add_series(fmt::format("{:g} m/s", speed[i]));
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::abs(T0[i] - Tair));
  auto row = [&](double t) {
    std::vector<double> v;
    for (std::size_t i = 0; i < n; ++i) {
      const double T = sim.particles().T[index_of_id(sim.particles(), ids[i])];
      worst = std::max(worst, std::abs(T - exact(i, t)));
      v.push_back(T);
      v.push_back(exact(i, t));
    }
    return v;
  };
  plot.add_row(0.0, row(0.0));
  int k = 0;
  while (sim.time() < end - 0.5 * dt) {
    sim.advance(dt);
    const std::vector<double> v = row(sim.time());
    if (++k % 5 == 0) plot.add_row(sim.time(), v);
  }
  plot.write(ctx.output_dir / "wind_cooling.csv");
  std::string taus;
  for (std::size_t i = 0; i < n; ++i) taus += fmt::format("{}{:g} m/s: {:.3g} s", i ? ", " : "", speed[i], tau[i]);
  CaseResult r;
  r.name = "wind_cooling";
  r.oracle = "lumped cooling T_air + (T0 - T_air) exp(-t/tau), tau = m c / (h(v) 4 pi R^2), h of (93); "
             "error = max |T - T_exact| / (T0 - T_air)";
  r.tolerance = 1e-3;
  r.error = worst / scale;
  r.pass = r.error <= r.tolerance;
  r.note = "tau per wind speed: " + taus;
  r.plots = {"wind_cooling"};
  return r;
}

}  // namespace

std::vector<CaseSpec> thermal_cases() {
  return {{"thermal_contact", "Figs. 15-16", true, thermal_contact}, {"wind_cooling", "Fig. 17", true, wind_cooling}};
}

}  // namespace mpdem::validate
