// Mechanical validation cases (thesis chapter "Code Validation", mechanical validation,
// figures 2-14): normal elastic contact of two and three particles, a particle hitting a barrier
// and the seam of two adjacent barrier triangles, a particle passing through a hole, and the
// five-particle chain for five Young's moduli. Each drives its scene in
// examples/validation/<case>/ and compares it with an independent reference.
#include <algorithm>
#include <cmath>
#include <limits>

#include "validate/case_support.hpp"
#include "validate/line_comparison.hpp"
#include "validate/plot_csv.hpp"

namespace mpdem::validate {

namespace {

constexpr double kSpeedTolerance = 0.01;  // -, of the impact speed: velocity curves agree within 1%

const char* kLineOracle =
    "RK4 integration of the undamped Hertz law (49), E* (51), r* (52), from the same initial state at dt/20; "
    "error = max over time of |v_sim - v_ref| / impact speed";

// Velocity along the line of the listed spheres (by position along the line) vs time.
void write_speed_plot(const CaseContext& ctx, const std::string& stem, const std::string& title, const LineSamples& s,
                      const std::vector<std::size_t>& which, const std::string& axis_name) {
  PlotCsv plot(title, "time t [s]", fmt::format("velocity v_{} [m/s]", axis_name));
  for (std::size_t k : which) plot.add_series(fmt::format("particle {}", s.ids[k]), true, "Hertz reference (RK4)");
  const std::size_t stride = stride_for(s.t.size(), 600);
  for (std::size_t j = 0; j < s.t.size(); j += stride) {
    std::vector<double> row;
    for (std::size_t k : which) {
      row.push_back(s.v_sim[k][j]);
      row.push_back(s.v_ref[k][j]);
    }
    plot.add_row(s.t[j], row);
  }
  plot.write(ctx.output_dir / (stem + ".csv"));
}

CaseResult line_case(const CaseContext& ctx, const std::string& name, const std::string& axis_name, const Vec3& axis,
                     bool wall) {
  Scene scene = load_case_scene(ctx);
  std::optional<LineWall> w;
  if (wall) {
    const Barriers& b = scene.barriers;
    w = LineWall{dot(b.p0[0], axis), b.young[0], b.poisson[0]};
  }
  const LineSamples s = run_on_line(scene, axis, w);
  std::vector<std::size_t> all(s.ids.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  write_speed_plot(ctx, name, name + ": velocity vs time, engine vs Hertz reference", s, all, axis_name);
  CaseResult r;
  r.name = name;
  r.oracle = kLineOracle;
  r.tolerance = kSpeedTolerance;
  r.error = std::max(s.speed_error(), s.lateral / s.impact_speed);
  r.pass = r.error <= r.tolerance;
  double max_ov = 0.0;
  for (const auto& ov : s.ov_sim) max_ov = std::max(max_ov, *std::max_element(ov.begin(), ov.end()));
  if (wall) max_ov = std::max(max_ov, *std::max_element(s.wall_ov_sim.begin(), s.wall_ov_sim.end()));
  r.note = fmt::format("impact speed {} m/s, max overlap {} m, off-line speed {} m/s, {} evaluations",
                       sci(s.impact_speed), sci(max_ov), sci(s.lateral), s.evaluations);
  r.plots = {name};
  return r;
}

CaseResult two_particles(const CaseContext& ctx) {
  return line_case(ctx, "two_particle_contact", "x", {1, 0, 0}, false);
}

CaseResult three_particles(const CaseContext& ctx) {
  return line_case(ctx, "three_particle_contact", "x", {1, 0, 0}, false);
}

CaseResult particle_barrier(const CaseContext& ctx) { return line_case(ctx, "particle_barrier", "z", {0, 0, 1}, true); }

CaseResult adjacent_barriers(const CaseContext& ctx) {
  CaseResult r = line_case(ctx, "adjacent_barriers", "z", {0, 0, 1}, true);
  r.oracle = std::string("impact on the shared edge of two coplanar triangles must act as ONE plane contact: ") +
             kLineOracle + " (a doubled contact would shorten the contact time by 2^(-2/5))";
  return r;
}

// Free fall through a hole: z(t) = z0 + vz0 t + g_z t^2 / 2 and no particle-barrier contact.
CaseResult hole(const CaseContext& ctx) {
  Scene scene = load_case_scene(ctx);
  const double dt = scene.model.params.time.dt, end = scene.model.params.time.duration;
  const double gz = scene.model.params.fields.gravity.z;
  const double plate_z = scene.barriers.p0[0].z;  // m, the plate is horizontal
  const std::int64_t id = scene.particles.id[0];
  const Vec3 x0 = scene.particles.x[0], v0 = scene.particles.v[0];
  Simulation sim(std::move(scene), quiet_run());
  PlotCsv plot("hole: height vs time of a sphere falling through a square hole", "time t [s]", "height z [m]");
  plot.add_series("particle centre", true, "free fall");
  plot.add_hline(plate_z, "plate (barrier surface)");
  std::size_t contacts = 0;
  double worst = 0.0, lateral = 0.0;
  auto exact = [&](double t) { return x0.z + v0.z * t + 0.5 * gz * t * t; };
  plot.add_row(0.0, {x0.z, x0.z});
  int k = 0;
  while (sim.time() < end - 0.5 * dt) {
    sim.advance(dt);
    const Particles& p = sim.particles();
    const std::size_t i = index_of_id(p, id);
    contacts += sim.interactions().stats().contacts_pb;
    worst = std::max(worst, std::abs(p.x[i].z - exact(sim.time())));
    lateral = std::max(lateral, std::hypot(p.x[i].x - x0.x, p.x[i].y - x0.y));
    if (++k % 5 == 0) plot.add_row(sim.time(), {p.x[i].z, exact(sim.time())});
  }
  const double drop = std::abs(exact(sim.time()) - x0.z);
  plot.write(ctx.output_dir / "hole.csv");
  CaseResult r;
  r.name = "hole";
  r.oracle = "free fall z0 + v0 t + g t^2/2 with no particle-barrier contact; error = max |z - z_exact| / drop "
             "height (1 if any contact or lateral drift)";
  r.tolerance = 1e-6;
  r.error = worst / drop;
  if (contacts > 0 || lateral > 0.0) r.error = 1.0;
  r.pass = r.error <= r.tolerance;
  r.note = fmt::format("drop {} m through the plate at z = {} m, contacts {}, lateral drift {} m", sci(drop),
                       sci(plate_z), contacts, sci(lateral));
  r.plots = {"hole"};
  return r;
}

// Five-particle chain for each [[material]] of the scene (E1..E5): first and last particle speed
// vs time, and the wave travel time vs E.
CaseResult chain(const CaseContext& ctx) {
  const Scene base = load_case_scene(ctx);
  CaseResult r;
  r.name = "five_particle_chain";
  r.oracle = std::string("per E: ") + kLineOracle +
             "; travel time (first contact -> last separation) vs the reference's: error = max of both "
             "relative errors over E1..E5";
  r.tolerance = kSpeedTolerance;
  const double E1 = base.model.materials.front().young;
  std::vector<double> Es, t_sim, t_ref;
  double worst_speed = 0.0, worst_travel = 0.0;
  for (std::size_t m = 0; m < base.model.materials.size(); ++m) {
    const Material& mat = base.model.materials[m];
    Scene s = base;
    // Every sphere of material m (its E and nu; the masses stay those of the loaded scene).
    for (int& mi : s.particles.material) mi = static_cast<int>(m);
    // Contact time ~ E^(-2/5): keep the same steps per contact for every modulus.
    const double scale = std::pow(mat.young / E1, -0.4);
    s.model.params.time.dt *= scale;
    s.model.params.time.dt_min = s.model.params.time.dt_max = s.model.params.time.dt;
    s.model.params.time.duration *= scale;
    const LineSamples ls = run_on_line(s, {1, 0, 0}, std::nullopt);
    const std::size_t last = ls.ids.size() - 1;
    const double ts = last_fall(ls.t, ls.ov_sim[last - 1]) - first_rise(ls.t, ls.ov_sim[0]);
    const double tr = last_fall(ls.t, ls.ov_ref[last - 1]) - first_rise(ls.t, ls.ov_ref[0]);
    Es.push_back(mat.young);
    t_sim.push_back(ts);
    t_ref.push_back(tr);
    worst_speed = std::max(worst_speed, ls.speed_error());
    worst_travel = std::max(worst_travel, std::abs(ts / tr - 1.0));
    if (!(ts > 0.0) || !(tr > 0.0)) worst_travel = std::numeric_limits<double>::infinity();
    const std::string stem = fmt::format("five_particle_chain_{}", mat.name);
    write_speed_plot(ctx, stem,
                     fmt::format("five-particle chain, case {} (E = {:.0e} Pa): first and last particle velocity",
                                 mat.name, mat.young),
                     ls, {0, last}, "x");
    r.plots.push_back(stem);
  }
  PlotCsv travel("five-particle chain: wave travel time vs Young's modulus", "Young's modulus E [Pa]",
                 "travel time first contact -> last separation [s]");
  travel.set_x_column("E");
  travel.set_log_x();
  travel.set_log_y();
  travel.add_series("travel time", true, "Hertz reference (RK4)");
  for (std::size_t k = 0; k < Es.size(); ++k) travel.add_row(Es[k], {t_sim[k], t_ref[k]});
  travel.write(ctx.output_dir / "five_particle_chain_travel_time.csv");
  r.plots.push_back("five_particle_chain_travel_time");
  r.error = std::max(worst_speed, worst_travel);
  r.pass = r.error <= r.tolerance;
  r.note = fmt::format("max speed error {}, max travel-time error {}, travel time ~ E^{:.4f} (Hertz: -0.4)",
                       sci(worst_speed), sci(worst_travel), log_log_slope(Es, t_sim));
  return r;
}

}  // namespace

std::vector<CaseSpec> mechanical_cases() {
  return {{"two_particle_contact", "Fig. 2", true, two_particles},
          {"three_particle_contact", "Fig. 3", true, three_particles},
          {"particle_barrier", "Fig. 4", true, particle_barrier},
          {"adjacent_barriers", "Fig. 5", true, adjacent_barriers},
          {"hole", "Fig. 6", true, hole},
          {"five_particle_chain", "Figs. 7-13", false, chain}};
}

}  // namespace mpdem::validate
