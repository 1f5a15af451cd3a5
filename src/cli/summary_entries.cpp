// The scene summary's lines for the entries beyond particles and barriers (cli/scene_summary.hpp):
// inlets, sinks, coarse-grained fields and the outputs, so that `mpdem check` shows every part
// of the scene that acts during the run.
#include <fmt/core.h>

#include <string>

#include "cli/scene_summary.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"

namespace mpdem::cli {

namespace {

std::string vec_text(const Vec3& v) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x, v.y, v.z); }

std::string region_text(const RegionSpec& r) {
  if (r.shape == RegionShape::Cylinder)
    return fmt::format("cylinder base {} axis {} radius {:.6g} m", vec_text(r.base), vec_text(r.axis), r.radius);
  return fmt::format("box {} .. {} m", vec_text(r.min), vec_text(r.max));
}

// "every 0.01 s" or "off"
std::string every_text(double every, const char* unit) {
  return every > 0.0 ? fmt::format("every {:.6g} {}", every, unit) : std::string("off");
}

}  // namespace

void print_entries(const Scene& scene) {
  const Params& prm = scene.model.params;
  fmt::print("inlets: {}\n", prm.inlets.size());
  for (const InletSpec& in : prm.inlets) {
    Vec3 lo, hi;
    inlet_centre_box(in.volume, 0.0, lo, hi);
    const std::string rate = in.mass_rate > 0.0
                                 ? fmt::format("{:.6g} kg/s", in.mass_rate)
                                 : fmt::format("{:.6g} {}/s", in.count_rate, in.clump.empty() ? "particles" : "bodies");
    const std::string end = in.end ? fmt::format("{:.6g} s", *in.end) : std::string("the end");
    const std::string interval = in.interval > 0.0 ? fmt::format("{:.6g} s", in.interval)
                                                   : fmt::format("{:.6g} s (100 x dt)", 100.0 * prm.time.dt);
    std::string size = "radius " + in.radius.describe();
    if (!in.clump.empty()) {  // bodies: their templates and number fractions
      size = "clump";
      for (std::size_t k = 0; k < in.clump.clumps.size(); ++k)
        size += fmt::format("{} '{}' {:.6g}", k ? "," : "",
                            scene.model.clumps[static_cast<std::size_t>(in.clump.clumps[k])].name,
                            in.clump.fractions[k]);
    }
    fmt::print("  {:<16} {} within {} .. {} m, {} from t = {:.6g} s to {} every {}; {}; material '{}'; "
               "velocity {} m/s",
               in.name, in.volume.shape, vec_text(lo), vec_text(hi), rate, in.start, end, interval, size,
               in.material.empty() ? scene.model.materials.front().name : in.material, vec_text(in.velocity));
    if (in.velocity_spread > 0.0) fmt::print(" +- {:.6g} m/s", in.velocity_spread);
    fmt::print("\n");
  }
  fmt::print("sinks: {}\n", prm.sinks.size());
  for (const SinkSpec& s : prm.sinks) fmt::print("  {:<16} {}\n", s.name, region_text(s.region));
  fmt::print("coarse grain: {}\n", prm.coarse_grain.size());
  for (const CoarseGrainSpec& c : prm.coarse_grain) {
    const CgGrid& g = c.grid;
    const std::string where = c.profile
                                  ? fmt::format("profile along {} in {} bins over {:.6g} .. {:.6g} m", "xyz"[c.axis],
                                                g.cells[static_cast<std::size_t>(c.axis)], g.min[c.axis], g.max[c.axis])
                                  : fmt::format("grid {} x {} x {} over {} .. {} m", g.cells[0], g.cells[1], g.cells[2],
                                                vec_text(g.min), vec_text(g.max));
    fmt::print("  {:<16} {}, {} kernel of width {:.6g} m, {}{}\n", c.name, where,
               c.kernel == CgKernel::lucy ? "lucy" : "gaussian", c.width, every_text(c.every, "s"),
               c.average > 0.0 ? fmt::format(", averaged over {:.6g} s ({} samples)", c.average, c.samples) : "");
  }
  const OutputParams& o = prm.output;
  fmt::print("output: {}\n", output_dir_for(scene, RunOptions{}).string());
  fmt::print("  log every {} steps; particles (VTU) {}; particle CSV {}; barriers (VTU) {}; barrier log {}; "
             "contacts {}; checkpoint {}\n",
             o.log_every, every_text(o.particles_every, "s"), every_text(o.particle_csv_every, "s"),
             every_text(o.barriers_every, "s"), every_text(o.barrier_log_every, "s"), every_text(o.contacts_every, "s"),
             every_text(o.checkpoint_every, "steps"));
  if (!scene.model.clumps.empty()) fmt::print("  body CSV {}\n", every_text(o.body_csv_every, "s"));
  if (prm.bonds.enabled()) fmt::print("  bonds (VTU) {}; bonds_broken.csv\n", every_text(o.bonds_every, "s"));
}

}  // namespace mpdem::cli
