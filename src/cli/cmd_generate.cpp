// `mpdem generate`: random non-overlapping particles -> particle CSV (docs/tools.md).
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/radius_options.hpp"
#include "cli/tool_commands.hpp"
#include "generate/region.hpp"
#include "core/input_error.hpp"
#include "generate/generator.hpp"

namespace mpdem::cli {

namespace {

struct GenerateArgs {
  std::filesystem::path output;
  std::string region = "box";
  std::vector<double> min, max, base, axis = {0, 0, 1}, velocity;
  double cylinder_radius = 0.0;
  std::filesystem::path mesh;
  std::size_t count = 0;
  double solid_fraction = 0.0;
  RadiusArgs radius;
  std::uint64_t seed = 1;
  double gap = 0.0, speed = 0.0;
  std::string material;
  std::size_t max_attempts = 100000;
  bool quiet = false;
};

[[noreturn]] void bad(const std::string& option, const std::string& msg) {
  throw InputError("mpdem generate", 0, option, msg);
}

Vec3 vec(const std::vector<double>& v, const std::string& option) {
  if (v.size() != 3) bad(option, "expected 3 numbers");
  return {v[0], v[1], v[2]};
}

GenerateSpec to_spec(const GenerateArgs& a) {
  GenerateSpec s;
  s.origin = "mpdem generate";
  if (a.region == "box") {
    s.region.shape = RegionShape::Box;
    if (a.min.empty() || a.max.empty()) bad("--min", "a box region needs --min and --max");
    s.region.min = vec(a.min, "--min");
    s.region.max = vec(a.max, "--max");
    const Vec3 e = s.region.max - s.region.min;  // m; max > min is the generator's check
    if (e.x > 0.0 && e.y > 0.0 && e.z > 0.0)
      if (const std::string p = box_size_problem(e); !p.empty()) bad("--max", p);
  } else if (a.region == "cylinder") {
    s.region.shape = RegionShape::Cylinder;
    if (a.base.empty() || !(a.cylinder_radius > 0))
      bad("--base", "a cylinder region needs --base, --axis and --cylinder-radius > 0");
    s.region.base = vec(a.base, "--base");
    s.region.axis = vec(a.axis, "--axis");
    s.region.radius = a.cylinder_radius;
    bool axis_at_fault = false;
    if (const std::string p = cylinder_size_problem(s.region.axis, s.region.radius, axis_at_fault); !p.empty())
      bad(axis_at_fault ? "--axis" : "--cylinder-radius", p);
  } else if (a.region == "mesh") {
    s.region.shape = RegionShape::Mesh;
    if (a.mesh.empty()) bad("--mesh", "a mesh region needs --mesh FILE (closed surface, .stl or barrier .csv)");
    s.region.mesh = a.mesh;
  } else {
    bad("--region", "expected box, cylinder or mesh, got '" + a.region + "'");
  }
  s.count = a.count;
  s.solid_fraction = a.solid_fraction;
  s.radius = to_distribution(a.radius, "mpdem generate");
  s.seed = a.seed;
  s.gap = a.gap;
  s.material = a.material;
  if (!a.velocity.empty()) s.velocity = vec(a.velocity, "--velocity");
  s.speed = a.speed;
  s.max_attempts = a.max_attempts;
  return s;
}

int run_generate(const GenerateArgs& a) {
  const GenerateSpec spec = to_spec(a);
  const auto t0 = std::chrono::steady_clock::now();
  const GenerateResult res = generate_particles(spec);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_generated_csv(a.output, spec, res.particles);
  if (!a.quiet)
    fmt::print("generated {} particles in {:.3g} m^3: solid fraction {:.4f}, {} attempts, {:.2f} s -> {}\n",
               res.particles.size(), res.region_volume, res.solid_fraction, res.attempts, secs, a.output.string());
  return 0;
}

}  // namespace

void add_generate_command(CLI::App& app, ToolAction& action) {
  auto a = std::make_shared<GenerateArgs>();
  auto* c = app.add_subcommand("generate", "random non-overlapping particles in a region -> particle CSV");
  // Required unless the `agglomerate` subcommand is given (checked in the callback).
  c->add_option("-o,--output", a->output, "particle CSV to write");
  // `mpdem generate agglomerate` is `mpdem agglomerate` (docs/tools.md).
  CLI::App* agglomerate = add_agglomerate_command(*c, action);
  c->add_option("--region", a->region, "box (default), cylinder or mesh");
  c->add_option("--min", a->min, "box: lower corner x y z (m)")->expected(3);
  c->add_option("--max", a->max, "box: upper corner x y z (m)")->expected(3);
  c->add_option("--base", a->base, "cylinder: centre of the base x y z (m)")->expected(3);
  c->add_option("--axis", a->axis, "cylinder: base centre -> top centre (m; default 0 0 1)")->expected(3);
  c->add_option("--cylinder-radius", a->cylinder_radius, "cylinder: radius (m)");
  c->add_option("--mesh", a->mesh, "mesh: closed surface (.stl or barrier .csv)")->check(CLI::ExistingFile);
  auto* count = c->add_option("--count,-n", a->count, "number of particles")->check(CLI::PositiveNumber);
  auto* frac = c->add_option("--solid-fraction,-f", a->solid_fraction, "target solid fraction in (0, 1)")
                   ->check(CLI::Range(0.0, 1.0));
  count->excludes(frac);
  frac->excludes(count);
  add_radius_options(*c, a->radius);
  c->add_option("--seed", a->seed, "random seed (default 1)");
  c->add_option("--gap", a->gap, "minimum surface gap between particles and to the boundary (m)")
      ->check(CLI::NonNegativeNumber);
  c->add_option("--material", a->material, "value of the CSV material column");
  auto* vel = c->add_option("--velocity", a->velocity, "initial velocity vx vy vz (m/s)")->expected(3);
  auto* spd =
      c->add_option("--speed", a->speed, "random directions with this speed (m/s)")->check(CLI::NonNegativeNumber);
  vel->excludes(spd);
  c->add_option("--max-attempts", a->max_attempts, "random positions tried per particle (default 100000)")
      ->check(CLI::PositiveNumber);
  c->add_flag("--quiet,-q", a->quiet, "print nothing on success");
  c->callback([a, agglomerate, &action] {
    if (agglomerate->parsed()) return;  // its own callback sets the action
    if (a->output.empty()) throw CLI::RequiredError("--output");
    if (a->count == 0 && a->solid_fraction == 0.0) throw CLI::ValidationError("give --count or --solid-fraction");
    action = [a] { return run_generate(*a); };
  });
}

}  // namespace mpdem::cli
