// Electromagnetic validation cases (thesis "Electromagnetic Validation", figures 18-23): one
// charged particle in a uniform electric field only, a magnetic field only, and both; position
// and speed vs time against the closed form of charged_motion.hpp.
#include <algorithm>
#include <cmath>

#include "validate/case_support.hpp"
#include "validate/charged_motion.hpp"
#include "validate/plot_csv.hpp"

namespace mpdem::validate {

namespace {

CaseResult charged_case(const CaseContext& ctx, const std::string& name, const std::string& what) {
  Scene scene = load_case_scene(ctx);
  const Params& prm = scene.model.params;
  const double dt = prm.time.dt, end = prm.time.duration;
  const Particles& p0 = scene.particles;
  const std::int64_t id = p0.id[0];
  const Vec3 x0 = p0.x[0], v0 = p0.v[0];
  const double q = p0.charge[0], m = p0.mass[0];
  auto exact = [&](double t) {
    return charged_motion(x0, v0, q, m, prm.fields.electric, prm.fields.magnetic, prm.fields.gravity, t);
  };
  PlotCsv pos(fmt::format("{}: position vs time ({})", name, what), "time t [s]", "position [m]");
  for (const char* c : {"x", "y", "z"}) pos.add_series(c);
  PlotCsv spd(fmt::format("{}: speed vs time ({})", name, what), "time t [s]", "speed |v| [m/s]");
  spd.add_series("|v|");
  double worst_x = 0.0, worst_v = 0.0, extent = 0.0, vmax = 0.0;
  auto sample = [&](const Vec3& x, const Vec3& v, double t, bool write) {
    const ChargedState e = exact(t);
    worst_x = std::max(worst_x, norm(x - e.x));
    worst_v = std::max(worst_v, std::abs(norm(v) - norm(e.v)));
    extent = std::max(extent, norm(e.x - x0));
    vmax = std::max(vmax, norm(e.v));
    if (write) {
      pos.add_row(t, {x.x, e.x.x, x.y, e.x.y, x.z, e.x.z});
      spd.add_row(t, {norm(v), norm(e.v)});
    }
  };
  sample(x0, v0, 0.0, true);
  Simulation sim(Scene(scene), quiet_run());
  const auto steps = static_cast<std::size_t>(std::llround(end / dt));
  const std::size_t stride = stride_for(steps, 300);
  std::size_t k = 0;
  while (sim.time() < end - 0.5 * dt) {
    sim.advance(dt);
    const Particles& p = sim.particles();
    const std::size_t i = index_of_id(p, id);
    sample(p.x[i], p.v[i], sim.time(), ++k % stride == 0);
  }
  pos.write(ctx.output_dir / (name + ".csv"));
  spd.write(ctx.output_dir / (name + "_speed.csv"));
  CaseResult r;
  r.name = name;
  r.oracle = "closed-form motion in uniform E, B (+ g) of (39)-(42); error = max of max |x - x_exact| / extent of "
             "the motion and max ||v| - |v_exact|| / max |v_exact|";
  r.tolerance = 1e-3;
  r.error = std::max(worst_x / extent, worst_v / vmax);
  r.pass = r.error <= r.tolerance;
  r.note = fmt::format("position error {} m over an extent of {} m, speed error {} m/s", sci(worst_x), sci(extent),
                       sci(worst_v));
  r.plots = {name, name + "_speed"};
  return r;
}

CaseResult electric(const CaseContext& ctx) { return charged_case(ctx, "electric_field", "E only: parabola"); }
CaseResult magnetic(const CaseContext& ctx) {
  return charged_case(ctx, "magnetic_field", "B only: helix at constant speed");
}
CaseResult both(const CaseContext& ctx) {
  return charged_case(ctx, "electromagnetic_field", "E and B: gyration + E x B drift");
}

}  // namespace

std::vector<CaseSpec> electromagnetic_cases() {
  return {{"electric_field", "Figs. 18-19", false, electric},
          {"magnetic_field", "Figs. 20-21", false, magnetic},
          {"electromagnetic_field", "Figs. 22-23", true, both}};
}

}  // namespace mpdem::validate
