// Inline generator table of the scene file (docs/scene.md "Generated particles").
#include "scene/generate_spec_reader.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "core/input_file.hpp"
#include "generate/region.hpp"
#include "io/toml_section.hpp"

namespace mpdem {

namespace {

// Array of positive numbers (radii, fractions) from a raw TOML node.
std::vector<double> numbers(const TomlSection& s, const toml::table& t, std::string_view k, Range r) {
  std::vector<double> out;
  const toml::node* n = t.get(k);
  if (!n) return out;
  const auto* a = n->as_array();
  if (!a) s.fail(k, "expected an array of numbers");
  for (const toml::node& e : *a) {
    double v = 0.0;
    if (const auto* i = e.as_integer()) v = static_cast<double>(i->get());
    else if (const auto* f = e.as_floating_point()) v = f->get();
    else s.fail(k, "expected an array of numbers, element " + std::to_string(out.size() + 1) + " is not a number");
    if (!std::isfinite(v) || !r.contains(v))
      s.fail(k,
             "expected numbers " + r.text() + ", element " + std::to_string(out.size() + 1) + " is " + number_text(v));
    out.push_back(v);
  }
  return out;
}

}  // namespace

RadiusDistribution read_radius(const TomlSection& g, const toml::table& t) {
  RadiusDistribution d;
  const toml::node* n = t.get("radius");
  if (!n) g.fail("radius", "missing required key (a radius in m, or a distribution table)");
  if (!n->is_table()) {  // a plain number: constant radius
    d.value = *g.number("radius", kPositive);
    return d;
  }
  const toml::table& rt = *n->as_table();
  const auto s = g.table("radius",
                         {"distribution", "value", "min", "max", "mean", "std", "radii", "fractions", "fractions_of"});
  const std::string law = s->require(s->string("distribution"), "distribution");
  if (!parse_radius_law(law, d.law))
    s->fail("distribution",
            "expected \"constant\", \"uniform\", \"normal\", \"lognormal\" or \"discrete\", got \"" + law + "\"");
  // Keys each law uses; any other key of the table is a mistake worth reporting.
  std::vector<std::string_view> used;
  switch (d.law) {
    case RadiusLaw::Constant: used = {"value"}; break;
    case RadiusLaw::Uniform: used = {"min", "max"}; break;
    case RadiusLaw::Normal:
    case RadiusLaw::LogNormal: used = {"mean", "std", "min", "max"}; break;
    case RadiusLaw::Discrete: used = {"radii", "fractions", "fractions_of"}; break;
  }
  for (auto&& [k, v] : rt) {
    bool ok = k.str() == "distribution";
    for (std::string_view u : used) ok = ok || k.str() == u;
    if (!ok) s->fail(k.str(), "does not apply to distribution \"" + law + "\"");
  }
  switch (d.law) {
    case RadiusLaw::Constant: d.value = s->require(s->number("value", kPositive), "value"); break;
    case RadiusLaw::Uniform:
      d.min = s->require(s->number("min", kPositive), "min");
      d.max = s->require(s->number("max", kPositive), "max");
      break;
    case RadiusLaw::Normal:
    case RadiusLaw::LogNormal:
      d.mean = s->require(s->number("mean", kPositive), "mean");
      d.std = s->require(s->number("std", kPositive), "std");
      // Normal: [mean - 3 std, mean + 3 std] unless given; log-normal: untruncated unless given.
      d.min = s->number("min", kPositive).value_or(d.law == RadiusLaw::Normal ? d.mean - 3.0 * d.std : 0.0);
      d.max = s->number("max", kPositive).value_or(d.law == RadiusLaw::Normal ? d.mean + 3.0 * d.std : 0.0);
      break;
    case RadiusLaw::Discrete: {
      d.radii = numbers(*s, rt, "radii", kPositive);
      d.fractions = numbers(*s, rt, "fractions", kNonNegative);
      if (d.radii.empty()) s->fail("radii", "missing required key (an array of radii in m)");
      if (d.fractions.empty()) d.fractions.assign(d.radii.size(), 1.0);  // equal numbers
      if (const auto of = s->string("fractions_of")) {
        if (*of == "mass") d.mass_fractions = true;
        else if (*of != "number") s->fail("fractions_of", "expected \"number\" or \"mass\", got \"" + *of + "\"");
      }
      break;
    }
  }
  std::string key;
  if (const std::string p = d.problem(&key); !p.empty()) s->fail(key, p);
  return d;
}

void check_box_sizes(const TomlSection& g, const Vec3& extent, std::string_view key) {
  if (const std::string p = box_size_problem(extent); !p.empty()) g.fail(key, p);
}

void check_cylinder_sizes(const TomlSection& g, const Vec3& axis, double radius, std::string_view axis_key,
                          std::string_view radius_key) {
  bool axis_at_fault = false;
  if (const std::string p = cylinder_size_problem(axis, radius, axis_at_fault); !p.empty())
    g.fail(axis_at_fault ? axis_key : radius_key, p);
}

RegionSpec read_box_region(const TomlSection& g) {
  RegionSpec r{.shape = RegionShape::Box,
               .min = g.require(g.vec3("min"), "min"),
               .max = g.require(g.vec3("max"), "max"),
               .mesh = {}};
  for (int c = 0; c < 3; ++c)
    if (!(r.min[c] < r.max[c]))
      g.fail("max", std::string("expected max > min in every component, got ") + "xyz"[c] + ": min " +
                        number_text(r.min[c]) + " >= max " + number_text(r.max[c]));
  check_box_sizes(g, r.max - r.min, "max");
  return r;
}

RegionSpec read_cylinder_region(const TomlSection& g) {
  const Vec3 axis = g.require(g.vec3("axis"), "axis");
  if (!(norm(axis) > 0.0)) g.fail("axis", "expected a non-zero vector (base centre -> top centre)");
  RegionSpec r{.shape = RegionShape::Cylinder,
               .base = g.require(g.vec3("base"), "base"),
               .axis = axis,
               .radius = g.require(g.number("cylinder_radius", kPositive), "cylinder_radius"),
               .mesh = {}};
  check_cylinder_sizes(g, r.axis, r.radius, "axis", "cylinder_radius");
  return r;
}

GenerateSpec read_generate_spec(const std::string& file, const toml::table& table, const std::string& path,
                                const std::filesystem::path& dir, bool clump) {
  const TomlSection g(file, table, path,
                      {"region", "min", "max", "base", "axis", "cylinder_radius", "mesh", "count", "solid_fraction",
                       "radius", "seed", "gap", "material", "velocity", "speed", "max_attempts", "fixed", "placement"});
  GenerateSpec spec;
  spec.origin = file;
  spec.line = g.line();
  const std::string region = g.require(g.string("region"), "region");
  std::vector<std::string_view> region_keys;
  if (region == "box") {
    spec.region = read_box_region(g);
    region_keys = {"min", "max"};
  } else if (region == "cylinder") {
    spec.region = read_cylinder_region(g);
    region_keys = {"base", "axis", "cylinder_radius"};
  } else if (region == "mesh") {
    spec.region.shape = RegionShape::Mesh;
    const std::string name = g.require(g.string("mesh"), "mesh");
    spec.region.mesh = (dir / std::filesystem::path(name)).lexically_normal();
    if (name.empty()) g.fail("mesh", "expected a file name, got an empty string");
    if (const std::string why = input_file_problem(spec.region.mesh); !why.empty())
      g.fail("mesh", "file '" + spec.region.mesh.string() + "' " + why);
    region_keys = {"mesh"};
  } else {
    g.fail("region", "expected \"box\", \"cylinder\" or \"mesh\", got \"" + region + "\"");
  }
  for (std::string_view k : {"min", "max", "base", "axis", "cylinder_radius", "mesh"}) {
    bool used = false;
    for (std::string_view u : region_keys) used = used || u == k;
    if (!used && g.has(k)) g.fail(k, "does not apply to region \"" + region + "\"");
  }

  if (g.has("count") == g.has("solid_fraction"))
    g.fail(g.has("count") ? "solid_fraction" : "count", "give exactly one of count and solid_fraction");
  if (const auto n = g.integer("count", 1, std::numeric_limits<std::int64_t>::max()))
    spec.count = static_cast<std::size_t>(*n);
  if (const auto f = g.number("solid_fraction", Range{0.0, 1.0, false, false})) spec.solid_fraction = *f;
  if (!clump) spec.radius = read_radius(g, table);
  else if (g.has("radius"))
    g.fail("radius", "does not apply with clump: the clump template fixes the bodies' size and shape");
  if (const auto p = g.string("placement")) {
    if (!clump) g.fail("placement", "applies only with clump (how bodies are kept apart)");
    if (*p == "members") spec.placement = BodyPlacement::Members;
    else if (*p != "bounding") g.fail("placement", "expected \"bounding\" or \"members\", got \"" + *p + "\"");
  }
  if (const auto s = g.integer("seed", 0, std::numeric_limits<std::int64_t>::max()))
    spec.seed = static_cast<std::uint64_t>(*s);
  g.get("gap", spec.gap, kNonNegative);
  g.get("material", spec.material);
  if (g.has("velocity") && g.has("speed")) g.fail("speed", "give either velocity or speed, not both");
  spec.velocity = g.vec3("velocity");
  g.get("speed", spec.speed, kNonNegative);
  g.get("fixed", spec.fixed);
  if (const auto m = g.integer("max_attempts", 1, kMaxAttempts)) spec.max_attempts = static_cast<std::size_t>(*m);
  return spec;
}

}  // namespace mpdem
