// TOML scene reader: maps every table and key of the scene file (docs/scene.md) onto Params,
// Materials and the particle/barrier sources, validating types and ranges as it goes, then
// (load_scene) reads the CSV sources into the particle and barrier arrays.
#include "scene/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <span>
#include <sstream>
#include <string_view>

#include <fmt/core.h>
#include <toml++/toml.h>

#include "io/barrier_csv.hpp"
#include "scene/barrier_motion_reader.hpp"
#include "scene/contact_reader.hpp"
#include "io/csv_log.hpp"
#include "scene/generate_spec_reader.hpp"
#include "scene/coarse_grain_reader.hpp"
#include "scene/inlet_reader.hpp"
#include "core/input_error.hpp"
#include "core/input_file.hpp"
#include "io/particle_csv_reader.hpp"
#include "io/stl_reader.hpp"
#include "io/toml_section.hpp"
#include "io/vtk_xml.hpp"
#include "model/derived_limits.hpp"
#include "model/material_variants.hpp"
#include "model/scene.hpp"
#include "generate/generated_particles.hpp"
#include "scene/bond_reader.hpp"
#include "scene/checks_reader.hpp"
#include "scene/clump_reader.hpp"
#include "scene/input_paths.hpp"
#include "scene/trapezoidal_keys.hpp"

namespace mpdem {

namespace {

void read_time(const TomlSection& root, TimeParams& t) {
  const auto s = root.table("time", {"duration", "integrator", "phi", "dt", "dt_min", "dt_max", "adaptive",
                                     "desired_iterations", "p", "max_iterations"});
  if (!s) throw InputError(root.file(), 0, "time.duration", "missing required key (the [time] table is required)");
  t.duration = s->require(s->number("duration", kPositive), "duration");
  t.dt = s->require(s->number("dt", kPositive), "dt");
  if (const auto name = s->string("integrator")) {
    if (*name == "trapezoidal") t.integrator = Integrator::Trapezoidal;
    else if (*name == "verlet") t.integrator = Integrator::Verlet;
    else s->fail("integrator", "expected \"trapezoidal\" or \"verlet\", got \"" + *name + "\"");
  }
  if (t.integrator == Integrator::Verlet) refuse_trapezoidal_keys(root, *s);
  s->get("phi", t.phi, kUnitInterval);
  t.dt_min = s->number("dt_min", kPositive).value_or(t.dt / 1000.0);
  t.dt_max = s->number("dt_max", kPositive).value_or(t.dt);
  if (t.dt_min > t.dt_max)
    s->fail(s->has("dt_min") ? "dt_min" : "dt_max", "expected dt_min <= dt_max, got dt_min = " + number_text(t.dt_min) +
                                                        " > dt_max = " + number_text(t.dt_max));
  if (t.dt < t.dt_min || t.dt > t.dt_max)
    s->fail("dt",
            "expected dt within [dt_min, dt_max] = [" + number_text(t.dt_min) + ", " + number_text(t.dt_max) + "]");
  s->get("adaptive", t.adaptive);
  // Steps are counted exactly (2^53) and the smallest step is one the run can divide by.
  const double smallest = t.adaptive ? t.dt_min : t.dt;  // s
  const char* key = t.adaptive && s->has("dt_min") ? "dt_min" : "dt";
  if (const std::string why = usable_problem(smallest, t.adaptive ? "dt_min" : "dt", "s"); !why.empty())
    s->fail(key, why + "; expected a step the run can divide by");
  if (const double steps = t.duration / smallest; !(steps <= 9007199254740992.0))
    s->fail(key, "the run would take up to " + fmt::format("{:.3g}", steps) + " steps (time.duration / " +
                     (t.adaptive ? "dt_min" : "dt") + " = " + number_text(t.duration) + " s / " +
                     number_text(smallest) + " s); expected at most 2^53 (about 9e15)");
  s->get("desired_iterations", t.desired_iterations, 1);
  s->get("p", t.p, kPositive);
  s->get("max_iterations", t.max_iterations, 1);
}

void read_tolerance(const TomlSection& root, ToleranceParams& t) {
  const auto s = root.table("tolerance", std::span<const std::string_view>(kToleranceKeys));
  if (!s) return;
  s->get("position", t.position, kPositive);
  s->get("velocity", t.velocity, kPositive);
  s->get("rotation", t.rotation, kPositive);
  s->get("angular_velocity", t.angular_velocity, kPositive);
  s->get("temperature", t.temperature, kPositive);
  s->get("position_floor", t.position_floor, kNonNegative);
  s->get("velocity_floor", t.velocity_floor, kNonNegative);
  s->get("rotation_floor", t.rotation_floor, kNonNegative);
  s->get("angular_velocity_floor", t.angular_velocity_floor, kNonNegative);
  s->get("temperature_floor", t.temperature_floor, kNonNegative);
}

void read_analysis_and_fields(const TomlSection& root, Params& p) {
  if (const auto s = root.table("analysis", {"rotation", "thermal"})) {
    s->get("rotation", p.analysis.rotation);
    s->get("thermal", p.analysis.thermal);
  }
  if (const auto s = root.table("gravity", {"vector"})) s->get("vector", p.fields.gravity);
  if (const auto s = root.table("fields", {"electric", "magnetic", "drag"})) {
    s->get("electric", p.fields.electric);
    s->get("magnetic", p.fields.magnetic);
    s->get("drag", p.fields.drag, kNonNegative);
  }
}

void read_contact_and_thermal(const TomlSection& root, const Model& model, Params& p) {
  read_contact(root, model, p.contact);
  if (const auto s = root.table("thermal", {"air_temperature", "air_velocity", "environment_temperature", "conduction",
                                            "convection", "radiation"})) {
    s->get("air_temperature", p.thermal.air_temperature, kPositive);
    s->get("air_velocity", p.thermal.air_velocity);
    s->get("environment_temperature", p.thermal.environment_temperature, kPositive);
    s->get("conduction", p.thermal.conduction);
    s->get("convection", p.thermal.convection);
    s->get("radiation", p.thermal.radiation);
  }
}

void read_materials(const TomlSection& root, Model& model) {
  for (const TomlSection& s : root.tables("material", {"name", "density", "young", "poisson", "conductivity",
                                                       "heat_capacity", "emissivity", "charge", "temperature"})) {
    Material m;
    m.name = s.require(s.string("name"), "name");
    if (m.name.empty()) s.fail("name", "expected a non-empty name");
    if (model.material_index(m.name) >= 0) s.fail("name", "duplicate material name '" + m.name + "'");
    s.get("density", m.density, kPositive);
    s.get("young", m.young, kPositive);
    s.get("poisson", m.poisson, kPoissonRange);
    s.get("conductivity", m.conductivity, kNonNegative);
    s.get("heat_capacity", m.heat_capacity, kPositive);
    s.get("emissivity", m.emissivity, kUnitInterval);
    s.get("charge", m.charge);
    s.get("temperature", m.temperature, kNonNegative);
    if (const std::string p = contact_moduli_problem(m.young, m.poisson); !p.empty()) s.fail("young", p);
    model.materials.push_back(m);
  }
}

void read_near_field(const TomlSection& root, const Model& model, NearFieldParams& nf) {
  const auto s = root.table("near_field",
                            {"empirical", "a1", "b1", "a2", "b2", "pair", "coulomb", "permittivity", "cutoff"});
  if (!s) return;
  s->get("a1", nf.a1);
  s->get("b1", nf.b1);
  s->get("a2", nf.a2);
  s->get("b2", nf.b2);
  for (const TomlSection& ps : s->tables("pair", {"material_a", "material_b", "a1", "b1", "a2", "b2"})) {
    // A pair's coefficients default to the global ones, so it overrides only what it names.
    NearFieldPair pair{ps.require(ps.string("material_a"), "material_a"),
                       ps.require(ps.string("material_b"), "material_b"),
                       nf.a1,
                       nf.b1,
                       nf.a2,
                       nf.b2};
    check_material(ps, "material_a", pair.material_a, model);
    check_material(ps, "material_b", pair.material_b, model);
    ps.get("a1", pair.a1);
    ps.get("b1", pair.b1);
    ps.get("a2", pair.a2);
    ps.get("b2", pair.b2);
    nf.pairs.push_back(pair);
  }
  // Giving coefficients switches the empirical law on unless `empirical` says otherwise.
  nf.empirical = nf.a1 != 0.0 || nf.a2 != 0.0 || !nf.pairs.empty();
  s->get("empirical", nf.empirical);
  s->get("coulomb", nf.coulomb);
  s->get("permittivity", nf.permittivity, kPositive);
  s->get("cutoff", nf.cutoff, kNonNegative);
  if ((nf.empirical || nf.coulomb) && nf.cutoff <= 0.0)
    s->fail("cutoff", "expected a cutoff > 0 when the empirical or Coulomb near field is on");
}

void read_sources(const TomlSection& root, const toml::table& doc, Scene& scene) {
  std::size_t entry = 0;
  for (const TomlSection& s : root.tables("particles", {"file", "generate", "material", "fixed", "clump"})) {
    if (scene.model.materials.empty())
      throw InputError(root.file(), s.line(), "material",
                       "at least one [[material]] is required when particles are given");
    ParticleSource src;
    src.line = s.line();
    if (s.has("file") && s.has("generate")) s.fail("generate", "give either file or generate, not both");
    if (s.has("generate")) {
      // The generator table is read from the raw TOML (arrays of radii and fractions).
      const toml::node* g = doc["particles"].as_array()->get(entry)->as_table()->get("generate");
      if (!g->is_table()) s.fail("generate", "expected a table, e.g. generate = { region = \"box\", ... }");
      src.generate = read_generate_spec(root.file(), *g->as_table(), "particles.generate", scene.dir, s.has("clump"));
      if (!src.generate->material.empty()) check_material(s, "generate", src.generate->material, scene.model);
    } else {
      src.file = existing_file(s, "file", scene.dir);
    }
    ++entry;
    s.get("material", src.material);
    if (!src.material.empty()) check_material(s, "material", src.material, scene.model);
    s.get("fixed", src.fixed);
    if (s.has("clump")) {
      src.clump = read_clump_mix(s, "clump", scene.model);
      if (!src.generate && !s.node("clump")->is_string())
        s.fail("clump", "expected a clump name: a body CSV takes one template (a table of fractions is for generate)");
    }
    scene.particle_sources.push_back(src);
  }
  for (const TomlSection& s :
       root.tables("barriers", {"file", "stl", "group", "material", "rigid", "motion", "thickness", "temperature",
                                "scale", "rotate_deg", "translate", "active", "motion_from"})) {
    BarrierSource src;
    src.origin = root.file();
    src.line = s.line();
    if (s.has("file") && s.has("stl")) s.fail("stl", "give either file or stl, not both");
    if (!s.has("file") && !s.has("stl")) s.fail("file", "missing required key (give file or stl)");
    if (s.has("file")) {
      src.file = existing_file(s, "file", scene.dir);
      for (std::string_view k : {"scale", "rotate_deg", "translate"})
        if (s.has(k)) s.fail(k, "applies to stl barriers only");
    } else {
      src.stl = existing_file(s, "stl", scene.dir);
    }
    s.get("group", src.group);
    // The group names columns of barrier_groups.csv; without `group` the file's name does.
    const std::string group = src.group.empty() ? (src.stl.empty() ? src.file : src.stl).stem().string() : src.group;
    if (!is_column_name(group))
      s.fail(src.group.empty() ? (src.stl.empty() ? "file" : "stl") : "group",
             "the barrier group name '" + group + "'" + (src.group.empty() ? " (the file's name)" : "") +
                 " names log columns: expected a non-empty name without ',', '\"' or line breaks" +
                 (src.group.empty() ? "; give `group`" : ""));
    s.get("material", src.material);
    if (!src.material.empty()) check_material(s, "material", src.material, scene.model);
    s.get("rigid", src.rigid);
    src.motion = read_barrier_motion(s, scene.model.params.time.duration);
    s.get("thickness", src.thickness, kNonNegative);
    src.temperature = s.number("temperature", kNonNegative);
    s.get("scale", src.scale, kPositive);
    s.get("rotate_deg", src.rotate_deg);
    s.get("translate", src.translate);
    scene.barrier_sources.push_back(src);
  }
}

void read_domain_neighbor_output(const TomlSection& root, Params& p) {
  if (const auto s = root.table("domain", {"min", "max", "on_exit", "periodic"})) {
    p.domain.bounded = true;
    p.domain.min = s->require(s->vec3("min"), "min");
    p.domain.max = s->require(s->vec3("max"), "max");
    for (int c = 0; c < 3; ++c) {
      if (!(p.domain.min[c] < p.domain.max[c]))
        s->fail("max", std::string("expected max > min in every component, got ") + "xyz"[c] + ": min " +
                           number_text(p.domain.min[c]) + " >= max " + number_text(p.domain.max[c]));
      // The extent is a periodic axis's period and what the brick grid divides (Derived limits).
      const std::string what = std::string("the extent max - min along ") + "xyz"[c];
      if (const std::string why = usable_problem(p.domain.max[c] - p.domain.min[c], what, "m"); !why.empty())
        s->fail("max", why + "; expected a finite extent > 0");
    }
    if (const auto e = s->string("on_exit")) {
      if (*e == "remove") p.domain.on_exit = ExitPolicy::Remove;
      else if (*e == "stop") p.domain.on_exit = ExitPolicy::Stop;
      else s->fail("on_exit", "expected \"remove\" or \"stop\", got \"" + *e + "\"");
    }
    p.domain.periodic_line = s->line_of("periodic");
    if (const auto axes = s->strings("periodic", 0, 3))
      for (const std::string& a : *axes) {
        const int c = a == "x" ? 0 : a == "y" ? 1 : a == "z" ? 2 : -1;
        if (c < 0) s->fail("periodic", "expected axis names \"x\", \"y\" or \"z\", got \"" + a + "\"");
        if (p.domain.periodic[static_cast<std::size_t>(c)]) s->fail("periodic", "axis \"" + a + "\" is listed twice");
        p.domain.periodic[static_cast<std::size_t>(c)] = true;
      }
  }
  if (const auto s = root.table("neighbor", {"skin"})) s->get("skin", p.neighbor.skin, kNonNegative);
  if (const auto s = root.table("parallel", {"balance_every", "balance_threshold", "balance_cost"})) {
    s->get("balance_every", p.parallel.balance_every, 0);
    s->get("balance_threshold", p.parallel.balance_threshold, kNonNegative);
    if (!(p.parallel.balance_threshold >= 1.0))
      s->fail("balance_threshold",
              "expected >= 1 (max / mean cost per rank), got " + number_text(p.parallel.balance_threshold));
    if (const auto c = s->string("balance_cost")) {
      if (*c == "work") p.parallel.balance_cost = BalanceCost::Work;
      else if (*c == "time") p.parallel.balance_cost = BalanceCost::Time;
      else s->fail("balance_cost", "expected \"work\" or \"time\", got \"" + *c + "\"");
    }
  }
  read_checks(root, p.checks);
  if (const auto s = root.table("output",
                                {"dir", "particles_every", "barriers_every", "particle_csv_every", "barrier_log_every",
                                 "log_every", "checkpoint_every", "progress_every", "format", "contacts_every",
                                 "barrier_loads", "body_csv_every", "bonds_every"})) {
    s->get("dir", p.output.dir);
    if (p.output.dir.empty()) s->fail("dir", "expected a non-empty folder name");
    for (const auto& part : std::filesystem::path(p.output.dir))  // each a name in the file system
      if (part.string().size() > 255 || p.output.dir.find('\0') != std::string::npos)
        s->fail("dir", "expected folder names of at most 255 bytes without NUL characters (a file system's limit)");
    if (const auto name = s->string("format")) {
      if (const auto f = vtk_format_from_name(*name)) p.output.format = *f;
      else s->fail("format", "expected \"ascii\", \"binary\" or \"compressed\", got \"" + *name + "\"");
    }
    s->get("particles_every", p.output.particles_every, kNonNegative);
    s->get("barriers_every", p.output.barriers_every, kNonNegative);
    s->get("particle_csv_every", p.output.particle_csv_every, kNonNegative);
    s->get("body_csv_every", p.output.body_csv_every, kNonNegative);
    s->get("bonds_every", p.output.bonds_every, kNonNegative);
    s->get("barrier_log_every", p.output.barrier_log_every, kNonNegative);
    s->get("log_every", p.output.log_every, 1);
    s->get("checkpoint_every", p.output.checkpoint_every, 0);
    s->get("progress_every", p.output.progress_every, kNonNegative);
    s->get("contacts_every", p.output.contacts_every, kNonNegative);
    if (const auto loads = s->string("barrier_loads")) {
      if (*loads == "mean") p.output.mean_barrier_loads = true;
      else if (*loads == "sample") p.output.mean_barrier_loads = false;
      else s->fail("barrier_loads", "expected \"mean\" or \"sample\", got \"" + *loads + "\"");
    }
  }
}

}  // namespace

Scene parse_scene_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (const std::string why = input_file_problem(file); !why.empty())
    throw InputError(name, 0, "", "scene file '" + name + "' " + why);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name, 0, "", "cannot open scene file '" + name + "'");
  std::stringstream text;
  text << in.rdbuf();
  return parse_scene_text(text.str(), file, name);
}

Scene parse_scene_text(const std::string& text, const std::filesystem::path& file, const std::string& name) {
  toml::table doc;
  try {
    doc = toml::parse(text, std::string_view(name));
  } catch (const toml::parse_error& e) {
    throw InputError(name, e.source().begin.line, "",
                     "TOML syntax error at column " + std::to_string(e.source().begin.column) + ": " +
                         std::string(e.description()));
  }

  Scene scene;
  scene.file = std::filesystem::absolute(file).lexically_normal();
  scene.dir = scene.file.parent_path();
  const TomlSection root(name, doc, "",
                         {"time",         "tolerance", "analysis",      "gravity",   "fields",   "near_field",
                          "contact",      "thermal",   "material",      "particles", "barriers", "domain",
                          "neighbor",     "output",    "checks",        "inlet",     "sink",     "parallel",
                          "coarse_grain", "clump",     "liquid_bridge", "bonds"});
  Params& p = scene.model.params;
  read_time(root, p.time);
  read_tolerance(root, p.tolerance);
  read_analysis_and_fields(root, p);
  read_materials(root, scene.model);
  read_clump_templates(root, scene.dir, scene.model);
  read_contact_and_thermal(root, scene.model, p);
  read_near_field(root, scene.model, p.near_field);
  read_bonds(root, scene.dir, scene.model);
  read_sources(root, doc, scene);
  read_inlets_and_sinks(root, doc, scene.model);
  read_domain_neighbor_output(root, p);
  read_coarse_grain(root, scene.model);
  return scene;
}

Scene load_scene(const std::filesystem::path& file) { return load_sources(parse_scene_file(file)); }

Scene load_scene_text(const std::string& text, const std::filesystem::path& file, const std::string& name) {
  return load_sources(parse_scene_text(text, file, name));
}

Scene load_sources(Scene scene) {
  for (ParticleSource& src : scene.particle_sources) {
    const int mat = src.material.empty() ? 0 : scene.model.material_index(src.material);
    src.first = scene.particles.size();
    const std::size_t first_body = scene.particles.bodies.size();
    if (src.generate && !src.clump.empty())
      generate_clump_bodies(*src.generate, scene.model, mat, src.clump, scene.particles);
    else if (src.generate) add_generated_particles(*src.generate, scene.model, mat, scene.particles);
    else if (!src.clump.empty())
      read_clump_bodies(src.file, scene.model, mat, src.clump.clumps.front(), scene.particles);
    else read_particle_csv(src.file, scene.model, mat, scene.particles);
    src.count = scene.particles.size() - src.first;
    // The entry's flag on top of a CSV `fixed` column or the generator's own.
    // A clump entry's flag fixes its bodies (their members follow them).
    if (src.fixed && src.clump.empty())
      std::fill(scene.particles.fixed.begin() + static_cast<std::ptrdiff_t>(src.first), scene.particles.fixed.end(), 1);
    if (src.fixed && !src.clump.empty()) {
      std::vector<std::uint8_t>& body_fixed = scene.particles.bodies.fixed;
      std::fill(body_fixed.begin() + static_cast<std::ptrdiff_t>(first_body), body_fixed.end(), 1);
    }
  }
  assign_member_ids(scene.particles, scene.file.string());
  for (BarrierSource& src : scene.barrier_sources) {
    src.first = scene.barriers.size();
    if (!src.stl.empty()) read_stl_barriers(src, scene.model, scene.barriers);
    else read_barrier_csv(src.file, src, scene.model, scene.barriers);
    src.count = scene.barriers.size() - src.first;
  }
  resolve_material_variants(scene.model, scene.particles, scene.barriers, scene.file.string());
  check_listed_bonds(scene);
  // neighbor.skin stays 0 when [neighbor] gives none: the engine derives it from the radii.
  return scene;
}

}  // namespace mpdem
