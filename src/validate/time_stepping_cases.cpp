// Time-stepping validation cases (thesis "Post-analysis" and "Auto-adaptative time-stepping",
// figures 24-26): the error of the trapezoidal rule against the time step on a smooth closed-form
// problem (second order expected), and an adaptive run of a collision sequence against a fine
// fixed-step reference.
#include <algorithm>
#include <cmath>

#include "validate/case_support.hpp"
#include "validate/charged_motion.hpp"
#include "validate/plot_csv.hpp"

namespace mpdem::validate {

namespace {

// Gyration in B over the scene's duration with dt, dt/2, dt/4, dt/8: end-position error against
// the closed form, relative to the Larmor radius. The generalised trapezoidal rule with phi = 0.5
// is second order (physics.md section 9), so the log-log slope must be 2.
CaseResult step_convergence(const CaseContext& ctx) {
  const Scene base = load_case_scene(ctx);
  const Params& prm = base.model.params;
  const Particles& p0 = base.particles;
  const double q = p0.charge[0], m = p0.mass[0], end = prm.time.duration;
  const Vec3 x0 = p0.x[0], v0 = p0.v[0];
  const double r_larmor = m * std::hypot(v0.x, v0.y) / std::abs(q * prm.fields.magnetic.z);  // m
  std::vector<double> dts, errs;
  for (int level = 0; level < 4; ++level) {
    Scene s = base;
    const double dt = prm.time.dt / std::pow(2.0, level);
    s.model.params.time.dt = s.model.params.time.dt_min = s.model.params.time.dt_max = dt;
    Simulation sim(std::move(s), quiet_run());
    const auto steps = std::llround(end / dt);
    for (long long k = 0; k < steps; ++k) sim.advance(dt);
    dts.push_back(dt);
    const ChargedState e = charged_motion(x0, v0, q, m, prm.fields.electric, prm.fields.magnetic, prm.fields.gravity,
                                          sim.time());
    errs.push_back(norm(sim.particles().x[0] - e.x) / r_larmor);
  }
  const double slope = log_log_slope(dts, errs);
  PlotCsv plot("step_convergence: end-position error of one gyration vs time step (trapezoidal, phi = 0.5)",
               "time step dt [s]", "|x - x_exact| / Larmor radius [-]");
  plot.set_x_column("dt");
  plot.set_log_x();
  plot.set_log_y();
  plot.add_series("error", true, "second order, C dt^2");
  for (std::size_t k = 0; k < dts.size(); ++k)  // second-order line through the finest step
    plot.add_row(dts[k], {errs[k], errs.back() * std::pow(dts[k] / dts.back(), 2.0)});
  plot.write(ctx.output_dir / "step_convergence.csv");
  CaseResult r;
  r.name = "step_convergence";
  r.oracle = "gyration in B (closed form) at dt, dt/2, dt/4, dt/8: error = |log-log slope of the end-position "
             "error - 2| (second-order rule)";
  r.tolerance = 0.1;
  r.error = std::abs(slope - 2.0);
  r.pass = r.error <= r.tolerance && errs.back() < errs.front();
  r.note = fmt::format("slope {:.4f}; errors {} ... {} of the Larmor radius {} m", slope, sci(errs.front()),
                       sci(errs.back()), sci(r_larmor));
  r.plots = {"step_convergence"};
  return r;
}

struct Track {
  std::vector<double> t, z, vz;  // s, m, m/s
};

// Linear interpolation of a track at time t (t within the track).
double at(const std::vector<double>& t, const std::vector<double>& y, double x) {
  const auto it = std::lower_bound(t.begin(), t.end(), x);
  if (it == t.begin()) return y.front();
  if (it == t.end()) return y.back();
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  return y[k - 1] + (y[k] - y[k - 1]) * (x - t[k - 1]) / (t[k] - t[k - 1]);
}

// Sphere bouncing on a floor: the adaptive run (the scene as given) against the same scene at a
// fixed step of dt_max / 200 (~130 steps per collision: its own error, ~(pi/130)^2/12 = 5e-5 of
// the rebound speed, is far below the tolerance).
CaseResult adaptive_step(const CaseContext& ctx) {
  const Scene base = load_case_scene(ctx);
  const double end = base.model.params.time.duration;
  const std::int64_t id = base.particles.id[0];
  const double h0 = base.particles.x[0].z - base.particles.radius[0];                          // m, drop height
  const double v_impact = std::sqrt(2.0 * std::abs(base.model.params.fields.gravity.z) * h0);  // m/s

  Track ada, ref;
  std::uint64_t ada_evals = 0, ref_evals = 0, redone = 0;
  std::vector<double> steps;  // s, accepted adaptive steps
  {
    Scene s = base;
    Simulation sim(std::move(s), quiet_run());
    ada.t.push_back(0.0);
    ada.z.push_back(sim.particles().x[0].z);
    ada.vz.push_back(sim.particles().v[0].z);
    steps.push_back(std::nan(""));
    while (sim.time() < end - 1e-15) {
      const double t0 = sim.time();
      sim.advance_adaptive(end - sim.time());
      const std::size_t i = index_of_id(sim.particles(), id);
      ada.t.push_back(sim.time());
      ada.z.push_back(sim.particles().x[i].z);
      ada.vz.push_back(sim.particles().v[i].z);
      steps.push_back(sim.time() - t0);
    }
    ada_evals = sim.evaluations();
    redone = sim.redone_steps();
  }
  const double dt_ref = base.model.params.time.dt_max / 200.0;
  {
    Scene s = base;
    s.model.params.time.adaptive = false;
    s.model.params.time.dt = s.model.params.time.dt_min = s.model.params.time.dt_max = dt_ref;
    Simulation sim(std::move(s), quiet_run());
    ref.t.push_back(0.0);
    ref.z.push_back(sim.particles().x[0].z);
    ref.vz.push_back(sim.particles().v[0].z);
    const auto n = std::llround(end / dt_ref);
    for (long long k = 0; k < n; ++k) {
      sim.advance(std::min(dt_ref, end - sim.time()));
      ref.t.push_back(sim.time());
      ref.z.push_back(sim.particles().x[0].z);
      ref.vz.push_back(sim.particles().v[0].z);
    }
    ref_evals = sim.evaluations();
  }
  double worst_z = 0.0;
  PlotCsv plot("adaptive_step: sphere bouncing on a floor, mpdem with adaptive steps vs a fine fixed step",
               "time t [s]", "height z [m]");
  plot.add_series("height z", true, fmt::format("fixed-step reference, dt = {} s", sci(dt_ref)));
  PlotCsv dt_plot("adaptive_step: accepted step size", "time t [s]", "time step dt [s]");
  dt_plot.set_log_y();
  dt_plot.add_series("adaptive dt", false);
  for (std::size_t k = 0; k < ada.t.size(); ++k) {
    const double zr = at(ref.t, ref.z, ada.t[k]);
    worst_z = std::max(worst_z, std::abs(ada.z[k] - zr));
    plot.add_row(ada.t[k], {ada.z[k], zr});
    if (k > 0) dt_plot.add_row(ada.t[k], {steps[k]});
  }
  plot.write(ctx.output_dir / "adaptive_step.csv");
  dt_plot.write(ctx.output_dir / "adaptive_step_dt.csv");
  const double v_err = std::abs(ada.vz.back() - ref.vz.back()) / v_impact;
  CaseResult r;
  r.name = "adaptive_step";
  r.oracle = fmt::format("fixed-step reference at dt_max/200 = {} s; error = max of max |z - z_ref| / drop height "
                         "and |v_end - v_ref,end| / impact speed; must also cost fewer evaluations",
                         sci(dt_ref));
  r.tolerance = 0.01;
  r.error = std::max(worst_z / h0, v_err);
  r.pass = r.error <= r.tolerance && ada_evals < ref_evals;
  r.note = fmt::format("{} adaptive steps ({} redone), {} evaluations vs {} fixed-step; z error {}, v error {}",
                       ada.t.size() - 1, redone, ada_evals, ref_evals, sci(worst_z / h0), sci(v_err));
  r.plots = {"adaptive_step", "adaptive_step_dt"};
  return r;
}

}  // namespace

std::vector<CaseSpec> time_stepping_cases() {
  return {{"step_convergence", "Fig. 24", true, step_convergence},
          {"adaptive_step", "Figs. 25-26", true, adaptive_step}};
}

}  // namespace mpdem::validate
