// [[inlet]] and [[sink]] entries of the scene file (docs/scene.md "[[inlet]]", "[[sink]]").
#include "scene/inlet_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "generate/region.hpp"
#include "scene/clump_reader.hpp"
#include "scene/contact_reader.hpp"
#include "io/csv_log.hpp"
#include "scene/generate_spec_reader.hpp"
#include "core/input_error.hpp"
#include "model/derived_limits.hpp"
#include "state/particles.hpp"

namespace mpdem {

namespace {

// Keys of every region shape: a key of another shape than the entry's is an error.
constexpr std::string_view kRegionKeys[] = {"min",         "max",    "base",  "axis",  "cylinder_radius", "centre",
                                            "disc_radius", "corner", "edge1", "edge2", "direction",       "depth"};

void reject_other_shapes(const TomlSection& s, const std::string& shape, std::initializer_list<std::string_view> used) {
  for (std::string_view k : kRegionKeys)
    if (s.has(k) && std::find(used.begin(), used.end(), k) == used.end())
      s.fail(k, "does not apply to region \"" + shape + "\"");
}

// m, the largest radius the distribution can draw; 0 when it is unbounded (a log-normal tail).
double largest_radius(const RadiusDistribution& d) {
  switch (d.law) {
    case RadiusLaw::Constant: return d.value;
    case RadiusLaw::Uniform:
    case RadiusLaw::Normal:
    case RadiusLaw::LogNormal: return d.max;
    case RadiusLaw::Discrete: return *std::max_element(d.radii.begin(), d.radii.end());
  }
  return 0.0;
}

Vec3 unit(const TomlSection& s, std::string_view k) {
  const Vec3 d = s.require(s.vec3(k), k);
  const double len = norm(d);
  if (!(len > 0.0) || !std::isfinite(len)) s.fail(k, "expected a non-zero direction [x, y, z] of finite length");
  return d / len;
}

// The face inlets' slab thickness: `depth`, else two diameters of the largest particle (room to
// place the largest one at different distances from the face).
double face_depth(const TomlSection& s, double r_max) {
  if (const auto d = s.number("depth", kPositive)) return *d;
  if (!(r_max > 0.0)) s.fail("depth", "missing required key: the radius distribution is unbounded, give the depth (m)");
  return 4.0 * r_max;
}

InsertionVolume read_volume(const TomlSection& s, double r_max) {
  InsertionVolume vol;
  vol.shape = s.require(s.string("region"), "region");
  if (vol.shape == "box") {
    reject_other_shapes(s, vol.shape, {"min", "max"});
    vol.region = read_box_region(s);
  } else if (vol.shape == "cylinder") {
    reject_other_shapes(s, vol.shape, {"base", "axis", "cylinder_radius"});
    vol.region = read_cylinder_region(s);
  } else if (vol.shape == "disc") {
    // The disc extruded by depth along its normal `direction`: a cylinder.
    reject_other_shapes(s, vol.shape, {"centre", "disc_radius", "direction", "depth"});
    vol.region.shape = RegionShape::Cylinder;
    vol.region.base = s.require(s.vec3("centre"), "centre");
    vol.region.radius = s.require(s.number("disc_radius", kPositive), "disc_radius");
    vol.region.axis = unit(s, "direction") * face_depth(s, r_max);
    check_cylinder_sizes(s, vol.region.axis, vol.region.radius, "depth", "disc_radius");
  } else if (vol.shape == "rect") {
    // The rectangle corner + [0, 1] edge1 + [0, 1] edge2 extruded by depth along its normal, on
    // the side `direction` points to: a box in the frame (edge1, edge2, normal).
    reject_other_shapes(s, vol.shape, {"corner", "edge1", "edge2", "direction", "depth"});
    const Vec3 e1 = s.require(s.vec3("edge1"), "edge1"), e2 = s.require(s.vec3("edge2"), "edge2");
    const double l1 = norm(e1), l2 = norm(e2);
    if (!(l1 > 0.0) || !std::isfinite(l1))
      s.fail("edge1", "expected a non-zero edge vector [x, y, z] (m) of finite length");
    if (!(l2 > 0.0) || !std::isfinite(l2))
      s.fail("edge2", "expected a non-zero edge vector [x, y, z] (m) of finite length");
    if (std::abs(dot(e1, e2)) > 1e-9 * l1 * l2)
      s.fail("edge2", "expected an edge perpendicular to edge1 (a rectangle)");
    Vec3 n = cross(e1, e2) / (l1 * l2);
    const double side = dot(n, unit(s, "direction"));
    if (!(std::abs(side) > 1e-6)) s.fail("direction", "expected a direction out of the rectangle's plane");
    if (side < 0.0) n = -n;
    vol.origin = s.require(s.vec3("corner"), "corner");
    vol.u = e1 / l1;
    vol.v = cross(n, vol.u);  // e2's direction, right-handed with n
    vol.w = n;
    vol.region.shape = RegionShape::Box;
    vol.region.min = {};
    vol.region.max = {l1, l2, face_depth(s, r_max)};
    check_box_sizes(s, vol.region.max, "depth");
    if (dot(vol.v, e2) < 0.0) vol.origin += e2;  // the box spans the given rectangle either way
  } else {
    s.fail("region", "expected \"box\", \"cylinder\", \"disc\" or \"rect\", got \"" + vol.shape + "\"");
  }
  return vol;
}

// kg, the mean mass of the particles the distribution draws, from a fixed sample (an estimate).
double mean_mass(const RadiusDistribution& d, double density) {
  Rng rng(1);
  double sum = 0.0;
  constexpr int kDraws = 1000;
  for (int k = 0; k < kDraws; ++k) sum += sphere_mass(d.sample(rng), density);
  return sum / kDraws;
}

// What the run derives from an inlet's values (docs/scene.md "Derived limits"): the particles it
// may draw against their material, the count of insertion times, and the particles due at one.
void check_derived_limits(const TomlSection& s, const InletSpec& in, const Model& model) {
  const int mat = in.material.empty() ? 0 : model.material_index(in.material);
  const Material& m = model.materials.at(static_cast<std::size_t>(mat));
  if (const std::string why = clump_mix_mass_problem(in.clump, model, mat); !why.empty()) s.fail("clump", why);
  for (const double r : in.radius.bounding_radii(true))
    if (const std::string p = radius_problem(r, m, model.params.analysis.thermal); !p.empty())
      s.fail("radius", "material '" + m.name + "': " + p);
  const TimeParams& t = model.params.time;
  const double interval = in.interval_or_default(t.dt);                              // s
  const double span = std::min(in.end.value_or(t.duration), t.duration) - in.start;  // s
  constexpr double kMaxInsertionTimes = 9007199254740992.0;  // 2^53: insertion times are counted exactly
  if (span / interval > kMaxInsertionTimes)
    s.fail("interval", "the run holds " + number_text(span / interval) +
                           " insertion times ((end - start) / interval = " + number_text(span) + " s / " +
                           number_text(interval) +
                           " s); expected at most 2^53 (about 9e15), so that they are counted exactly");
  // All the insertion times a step passes are inserted at once (sim/inlets.cpp).
  constexpr double kMaxBatch = 5e7;  // particles: beyond this a rate is surely a unit mistake (the generator's cap)
  const double window = std::max(interval, t.dt);  // s
  const bool by_mass = in.mass_rate > 0.0, bodies = !in.clump.empty();
  const double mean = bodies ? in.clump.mean_mass(model.clumps, m.density) : mean_mass(in.radius, m.density);  // kg
  const double due = by_mass ? in.mass_rate * window / mean : in.count_rate * window;
  const std::string what = bodies ? "bodies" : "particles";
  if (!(due <= kMaxBatch))
    s.fail(by_mass ? "mass_rate" : "count_rate",
           "about " + number_text(due) + " " + what + " are due at one insertion (the rate times max(interval, " +
               "time.dt), here " + number_text(window) + " s" +
               (by_mass ? std::string(", at the mean ") + (bodies ? "body" : "particle") + " mass" : "") +
               "); expected at most 5e7 (check the units)");
}

// `name`, unique among inlets and sinks; `fallback` when absent.
std::string read_name(const TomlSection& s, const std::string& fallback, const Model& model) {
  std::string name = s.string("name").value_or(fallback);
  if (!is_column_name(name))
    s.fail("name", "expected a non-empty name without ',', '\"' or line breaks (it names log columns)");
  const auto taken = [&](const auto& list) {
    return std::any_of(list.begin(), list.end(), [&](const auto& e) { return e.name == name; });
  };
  if (taken(model.params.inlets) || taken(model.params.sinks))
    s.fail("name", "the name '" + name + "' is given to another inlet or sink");
  return name;
}

InletSpec read_inlet(const TomlSection& s, const toml::table& raw, const Model& model) {
  InletSpec in;
  in.line = s.line();
  in.name = read_name(s, "inlet" + std::to_string(model.params.inlets.size() + 1), model);
  if (s.has("clump")) {
    in.clump = read_clump_mix(s, "clump", model);
    if (s.has("radius"))
      s.fail("radius", "does not apply with clump: the clump templates fix the bodies' size and shape");
    in.radius.law = RadiusLaw::Discrete;
    in.radius.radii = in.clump.member_radii(model.clumps);
    in.radius.fractions.assign(in.radius.radii.size(), 1.0);
  } else {
    in.radius = read_radius(s, raw);
  }
  // m, the largest particle's radius, or the bodies' largest bounding sphere's (any orientation fits).
  const double r_max = in.clump.empty() ? largest_radius(in.radius) : in.clump.reach(model.clumps);
  in.volume = read_volume(s, r_max);
  if (r_max > 0.0 && !Region(in.volume.region, s.file(), s.line()).has_room(r_max))
    s.fail(in.clump.empty() ? "radius" : "clump",
           in.clump.empty() ? "the largest particle (radius " + number_text(r_max) + " m) does not fit in the region"
                            : "the largest body's bounding sphere (radius " + number_text(r_max) +
                                  " m, the reach of its members from its centre of mass) does not fit in the region");
  if (s.has("mass_rate") == s.has("count_rate"))
    s.fail(s.has("mass_rate") ? "count_rate" : "mass_rate",
           "give exactly one of mass_rate (kg/s) and count_rate (1/s)");
  s.get("mass_rate", in.mass_rate, kPositive);
  s.get("count_rate", in.count_rate, kPositive);
  s.get("start", in.start, kNonNegative);
  in.end = s.number("end", kNonNegative);
  if (in.end && !(*in.end > in.start))
    s.fail("end", "expected end > start = " + number_text(in.start) + " s, got " + number_text(*in.end));
  s.get("interval", in.interval, kPositive);
  s.get("material", in.material);
  if (!in.material.empty()) check_material(s, "material", in.material, model);
  s.get("velocity", in.velocity);
  s.get("velocity_spread", in.velocity_spread, kNonNegative);
  if (const auto v = s.integer("seed", 0, std::numeric_limits<std::int64_t>::max()))
    in.seed = static_cast<std::uint64_t>(*v);
  if (const auto m = s.integer("max_attempts", 1, kMaxAttempts)) in.max_attempts = static_cast<std::size_t>(*m);
  check_derived_limits(s, in, model);
  return in;
}

SinkSpec read_sink(const TomlSection& s, const Model& model) {
  SinkSpec out;
  out.line = s.line();
  out.name = read_name(s, "sink" + std::to_string(model.params.sinks.size() + 1), model);
  const std::string shape = s.require(s.string("region"), "region");
  if (shape == "box") {
    reject_other_shapes(s, shape, {"min", "max"});
    out.region = read_box_region(s);
  } else if (shape == "cylinder") {
    reject_other_shapes(s, shape, {"base", "axis", "cylinder_radius"});
    out.region = read_cylinder_region(s);
  } else {
    s.fail("region", "expected \"box\" or \"cylinder\", got \"" + shape + "\"");
  }
  return out;
}

}  // namespace

void read_inlets_and_sinks(const TomlSection& root, const toml::table& doc, Model& model) {
  const std::vector<TomlSection> inlets = root.tables(
      "inlet", {"name",     "region",          "min",        "max",          "base",  "axis",      "cylinder_radius",
                "centre",   "disc_radius",     "corner",     "edge1",        "edge2", "direction", "depth",
                "radius",   "mass_rate",       "count_rate", "start",        "end",   "interval",  "material",
                "velocity", "velocity_spread", "seed",       "max_attempts", "clump"});
  if (!inlets.empty() && model.materials.empty())
    throw InputError(root.file(), inlets.front().line(), "inlet.material",
                     "at least one [[material]] is required when an [[inlet]] is given");
  for (std::size_t k = 0; k < inlets.size(); ++k) {
    // The radius distribution table is read from the raw TOML (arrays of radii and fractions).
    const toml::table& raw = *doc["inlet"].as_array()->get(k)->as_table();
    model.params.inlets.push_back(read_inlet(inlets[k], raw, model));
  }
  for (const TomlSection& s :
       root.tables("sink", {"name", "region", "min", "max", "base", "axis", "cylinder_radius", "centre", "disc_radius",
                            "corner", "edge1", "edge2", "direction", "depth"}))
    model.params.sinks.push_back(read_sink(s, model));
}

}  // namespace mpdem
