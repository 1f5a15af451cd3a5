// `mpdem agglomerate`: a dense random packing in a sphere or a closed surface, bonded by the gap
// rule -> particle CSV and bond CSV (docs/tools.md "mpdem agglomerate").
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/radius_options.hpp"
#include "cli/tool_commands.hpp"
#include "core/input_error.hpp"
#include "generate/agglomerate.hpp"

namespace mpdem::cli {

namespace {

namespace fs = std::filesystem;

const std::string kCommand = "mpdem agglomerate";

struct AgglomerateArgs {
  fs::path output;  // prefix: <output>_particles.csv and <output>_bonds.csv
  std::size_t count = 0;
  double sphere = 0.0;         // m
  std::vector<double> centre;  // m
  fs::path surface;
  double scale = 0.0;
  double fraction = 0.55;
  double tolerance = 1e-3;
  double gap = -1.0;  // m; < 0: the default
  bool gap_given = false;
  RadiusArgs radius;
  std::uint64_t seed = 1;
  std::size_t max_sweeps = 20000;
  std::string material;
  double density = 0.0;  // kg/m^3; 0: no column
  bool density_given = false;
  bool sphere_given = false, scale_given = false;
  bool largest_cluster = false;
  bool overwrite = false;
  bool quiet = false;
};

[[noreturn]] void bad(const std::string& option, const std::string& msg) { throw InputError(kCommand, 0, option, msg); }

// An output that exists is kept unless --overwrite says otherwise.
void check_output(const fs::path& file, bool overwrite) {
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  if (fs::is_directory(st)) bad("--output", "'" + file.string() + "' is a folder; expected a file name prefix");
  if (const fs::path dir = file.parent_path(); !dir.empty() && !fs::is_directory(dir, ec))
    bad("--output", "the folder '" + dir.string() + "' does not exist");
  if (fs::exists(st) && !overwrite)
    bad("--output", "'" + file.string() + "' exists; pass --overwrite to replace it, or choose another --output");
}

int run_agglomerate(const AgglomerateArgs& a) {
  if (a.output.empty() || a.output.filename().empty()) bad("--output", "expected a file name prefix, e.g. -o agg");
  const fs::path particles = a.output.string() + "_particles.csv", bonds = a.output.string() + "_bonds.csv";
  AgglomerateSpec s;
  s.origin = kCommand;
  s.radius = to_distribution(a.radius, kCommand);
  s.count = a.count;
  s.fraction = a.fraction;
  s.surface = a.surface;
  // A size given must be > 0: 0 stands for "not given" in the spec.
  if (a.sphere_given && !(a.sphere > 0.0 && std::isfinite(a.sphere)))
    bad("--sphere", "expected a finite radius > 0 (m)");
  if (a.scale_given && !(a.scale > 0.0 && std::isfinite(a.scale))) bad("--scale", "expected a finite scale > 0");
  if (!a.surface.empty() && a.sphere_given) bad("--sphere", "give --sphere R or --stl FILE, not both");
  if (a.surface.empty() && a.scale_given) bad("--scale", "--scale scales the --stl surface; a sphere takes --sphere R");
  s.scale = a.scale_given ? a.scale : (a.surface.empty() || a.count > 0 ? 0.0 : 1.0);
  if (!a.centre.empty()) {
    if (!a.surface.empty()) bad("--centre", "--centre places the sphere; a surface stays where its file puts it");
    s.centre = {a.centre[0], a.centre[1], a.centre[2]};
  }
  s.sphere_radius = a.sphere;
  s.tolerance = a.tolerance;
  if (a.gap_given && !(a.gap >= 0.0)) bad("--gap", "expected a gap >= 0 (m)");
  s.gap = a.gap_given ? a.gap : -1.0;
  s.seed = a.seed;
  s.max_sweeps = a.max_sweeps;
  s.largest_cluster_only = a.largest_cluster;
  if (a.density_given && !(a.density > 0.0 && std::isfinite(a.density)))
    bad("--density", "expected a finite density > 0 (kg/m^3)");
  if (a.material.find_first_of(",#\n\r") != std::string::npos)
    bad("--material", "a material name may not hold a comma, '#' or a line break");
  check_output(particles, a.overwrite);
  check_output(bonds, a.overwrite);

  const auto t0 = std::chrono::steady_clock::now();
  const Agglomerate g = make_agglomerate(s);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::string where = a.surface.empty() ? fmt::format("a sphere of radius {:.6g} m", g.sphere_radius)
                                              : fmt::format("{} scaled by {:.6g}", a.surface.string(), g.scale);
  const std::string comment = fmt::format(
      "mpdem agglomerate, seed {}, {} particles, radius {}, in {}, solid fraction {:.4f}, bonds at a surface "
      "gap below {} m{}",
      a.seed, g.x.size(), s.radius.describe(), where, g.kept_fraction, g.gap,
      a.largest_cluster ? fmt::format(", the largest bonded cluster of {} packed", g.x.size() + g.dropped) : "");
  write_agglomerate_particles(particles, g, a.material, a.density_given ? a.density : 0.0, comment);
  write_bond_csv(bonds, g.bonds);
  if (!a.quiet) {
    const double n = static_cast<double>(g.x.size());
    fmt::print("packed {} particles in {} ({:.6g} m^3): solid fraction {:.4f}, largest overlap {:.2e} of the smaller "
               "radius, {} sweeps, {:.2f} s\n",
               g.x.size() + g.dropped, where, g.container_volume, g.fraction, g.largest_overlap, g.sweeps, secs);
    if (a.largest_cluster)
      fmt::print("kept the largest bonded cluster: {} particles ({} dropped), solid fraction {:.4f}\n", g.x.size(),
                 g.dropped, g.kept_fraction);
    fmt::print("{} bonds (surface gap < {:.6g} m): {:.2f} per particle, {} particle(s) without a bond, largest bonded "
               "cluster {} of {}\n",
               g.bonds.size(), g.gap, 2.0 * static_cast<double>(g.bonds.size()) / n, g.unbonded, g.largest_cluster,
               g.x.size());
    fmt::print("-> {}, {}\n", particles.string(), bonds.string());
  }
  return 0;
}

}  // namespace

CLI::App* add_agglomerate_command(CLI::App& app, ToolAction& action) {
  auto a = std::make_shared<AgglomerateArgs>();
  auto* c = app.add_subcommand("agglomerate", "dense random packing in a sphere or closed surface, bonded by the gap "
                                              "rule -> particle CSV and bond CSV");
  c->add_option("-o,--output", a->output, "file name prefix: writes PREFIX_particles.csv and PREFIX_bonds.csv")
      ->required();
  c->add_option("-n,--count", a->count, "number of particles (the container's size then follows)");
  auto* sphere = c->add_option("--sphere", a->sphere, "container: a sphere of this radius (m)");
  c->add_option("--centre", a->centre, "the sphere's centre x y z (m; default 0 0 0)")->expected(3);
  c->add_option("--stl", a->surface, "container: a closed surface (.stl, or a barrier .csv)")->check(CLI::ExistingFile);
  auto* scale = c->add_option("--scale", a->scale,
                              "the surface's coordinates times this (default 1, or set by --count)");
  c->add_option("-f,--fraction", a->fraction, "solid fraction (default 0.55)");
  add_radius_options(*c, a->radius);
  c->add_option("--tolerance", a->tolerance, "largest overlap over the smaller radius of the pair (default 1e-3)");
  auto* gap = c->add_option("--gap", a->gap,
                            "bond when the surface gap is below this (m; default 1 % of the mean "
                            "radius)");
  c->add_option("--seed", a->seed, "random seed (default 1)");
  c->add_option("--max-sweeps", a->max_sweeps, "overlap-removal sweeps before giving up (default 20000)");
  c->add_option("--material", a->material, "value of the particle CSV's material column");
  auto* density = c->add_option("--density", a->density, "value of the particle CSV's density column (kg/m^3)");
  c->add_flag("--largest-cluster", a->largest_cluster,
              "keep only the largest bonded cluster (drops particles without a bond and smaller clusters)");
  c->add_flag("--overwrite", a->overwrite, "replace existing output files");
  c->add_flag("--quiet,-q", a->quiet, "print nothing on success");
  c->callback([a, gap, density, sphere, scale, &action] {
    a->sphere_given = sphere->count() > 0;
    a->scale_given = scale->count() > 0;
    a->gap_given = gap->count() > 0;
    a->density_given = density->count() > 0;
    action = [a] { return run_agglomerate(*a); };
  });
  return c;
}

}  // namespace mpdem::cli
