// Bonded agglomerates (docs/tools.md "mpdem agglomerate").
#include "generate/agglomerate.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/value_range.hpp"
#include "generate/bond_pairs.hpp"
#include "generate/dense_packing.hpp"
#include "generate/generator.hpp"
#include "generate/region.hpp"
#include "geometry/mesh_transform.hpp"

namespace mpdem {

namespace {

constexpr double kMaxFraction = 0.74;          // -, densest packing of equal spheres (pi / sqrt 18)
constexpr std::size_t kMaxCount = 10'000'000;  // beyond this a request is surely a unit mistake

double ball_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

// Bonded clusters (union-find): each particle's cluster label (the lowest index in it), how
// many particles have no bond, and the label of the largest cluster (the lowest label of a tie).
struct Clusters {
  std::vector<std::size_t> label;                           // -, particle index, shape [n]
  std::size_t unbonded = 0, largest = 0, largest_size = 0;  // particles, label, particles
};

Clusters clusters(std::size_t n, const std::vector<std::array<std::size_t, 2>>& bonds) {
  Clusters c;
  // Per particle, shape [n]: union-find parent (index), cluster size (particles, counted at the
  // roots), bonds.
  std::vector<std::size_t> parent(n), size(n, 0), degree(n, 0);
  for (std::size_t i = 0; i < n; ++i) parent[i] = i;
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [i, j] : bonds) {
    ++degree[i];
    ++degree[j];
    const std::size_t a = root(i), b = root(j);
    parent[std::max(a, b)] = std::min(a, b);  // the root stays the lowest index
  }
  c.label.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.label[i] = root(i);
    if (++size[c.label[i]] > c.largest_size || (size[c.label[i]] == c.largest_size && c.label[i] < c.largest)) {
      c.largest_size = size[c.label[i]];
      c.largest = c.label[i];
    }
  }
  c.unbonded = static_cast<std::size_t>(std::count(degree.begin(), degree.end(), 0));
  return c;
}

// Keeps the particles of cluster `keep` only, renumbered in their order; their bonds follow.
void keep_cluster(Agglomerate& a, const Clusters& c, std::size_t keep) {
  std::vector<std::size_t> index(a.x.size());  // new index of each kept particle
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.x.size(); ++i)
    if (c.label[i] == keep) {
      index[i] = n;
      a.x[n] = a.x[i];
      a.radius[n] = a.radius[i];
      ++n;
    }
  a.dropped = a.x.size() - n;
  a.x.resize(n);
  a.radius.resize(n);
  std::size_t m = 0;
  for (const auto& [i, j] : a.bonds)  // a renumbering in order keeps the list sorted
    if (c.label[i] == keep) a.bonds[m++] = {index[i], index[j]};
  a.bonds.resize(m);
}

// Every option's range, and which of count and container size sets the other.
void check_spec(const AgglomerateSpec& spec) {
  const auto fail = [&](const std::string& option, const std::string& msg) {
    throw InputError(spec.origin, 0, option, msg);
  };
  if (const std::string p = spec.radius.problem(); !p.empty()) fail("--distribution", p);
  if (!(spec.fraction > 0.0 && spec.fraction <= kMaxFraction))
    fail("--fraction", "expected a solid fraction in (0, 0.74], got " + number_text(spec.fraction));
  if (!(spec.tolerance > 0.0 && spec.tolerance < 1.0))
    fail("--tolerance", "expected an overlap tolerance in (0, 1), got " + number_text(spec.tolerance));
  if (!std::isfinite(spec.gap)) fail("--gap", "expected a finite gap >= 0, got " + number_text(spec.gap));
  if (spec.max_sweeps == 0) fail("--max-sweeps", "expected at least 1 sweep");
  if (spec.count > kMaxCount) fail("--count", "expected at most 1e7 particles, got " + std::to_string(spec.count));
  const bool sphere = spec.surface.empty();
  const std::string size_option = sphere ? "--sphere" : "--scale";
  const double size = sphere ? spec.sphere_radius : spec.scale;  // 0: not given
  if (spec.count > 0 && size != 0.0)
    fail("--count", "give --count or the container's size (" + size_option +
                        "), not both: with the solid fraction, either sets the other");
  if (spec.count == 0 && sphere && size == 0.0)
    fail("--sphere", "give the sphere's radius --sphere R (m) or a --count");
  if (size != 0.0 && !(std::isfinite(size) && size > 0.0))
    fail(size_option, "expected a finite value > 0, got " + number_text(size));
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(spec.centre[a])) fail("--centre", "expected finite coordinates");
}

}  // namespace

Agglomerate make_agglomerate(const AgglomerateSpec& spec) {
  check_spec(spec);
  const bool sphere = spec.surface.empty();
  // The option that sets the container's size, blamed when the particles do not fit in it.
  const std::string size_option = spec.count > 0 ? "--count" : sphere ? "--sphere" : "--scale";
  const auto fail = [&](const std::string& option, const std::string& msg) {
    throw InputError(spec.origin, 0, option, msg);
  };

  Agglomerate out;
  Rng rng(spec.seed);
  GenerateSpec draw;  // the radii are drawn as `mpdem generate` draws them
  draw.radius = spec.radius;
  draw.count = spec.count;
  draw.solid_fraction = spec.fraction;
  draw.origin = spec.origin;

  TriangleMesh mesh;
  double unit_volume = 0.0;  // m^3, the surface's solid at scale 1
  if (!sphere) {
    try {
      mesh = read_region_mesh(spec.surface);  // InputError for a bad file
      unit_volume = MeshSolid(mesh).volume();
    } catch (const std::invalid_argument& e) {
      throw InputError(spec.surface.string(), 0, "", e.what());
    }
  }
  // The container's volume: given, or the drawn radii's volume over the fraction.
  double volume = sphere ? ball_volume(spec.sphere_radius) : unit_volume * std::pow(spec.scale, 3);
  if (spec.count > 0) {
    out.radius = draw_radii(draw, 0.0, rng);
    double v = 0.0;
    for (const double r : out.radius) v += ball_volume(r);
    volume = v / spec.fraction;
  } else {
    if (!(std::isfinite(volume) && volume > 0.0))
      fail(size_option, "the container's volume " + number_text(volume) + " m^3 is not finite and > 0");
    // At least F V / (the largest sphere's volume) draws: refused before drawing them.
    if (spec.fraction * volume / ball_volume(spec.radius.largest()) > static_cast<double>(kMaxCount))
      fail(size_option, "the container holds more than 1e7 particles at this solid fraction; check units");
    out.radius = draw_radii(draw, volume, rng);
    if (out.radius.empty()) fail(size_option, "the container holds less than one particle at this solid fraction");
  }

  std::unique_ptr<PackingContainer> box;
  if (sphere) {
    out.sphere_radius = spec.count > 0 ? std::cbrt(volume / ball_volume(1.0)) : spec.sphere_radius;
    box = std::make_unique<PackingContainer>(spec.centre, out.sphere_radius);
  } else {
    out.scale = spec.count > 0 ? std::cbrt(volume / unit_volume) : spec.scale;
    transform_mesh(mesh, out.scale, Vec3{}, Vec3{});
    try {
      box = std::make_unique<PackingContainer>(std::make_shared<const MeshSolid>(mesh));
    } catch (const std::invalid_argument& e) {
      throw InputError(spec.surface.string(), 0, "", e.what());
    }
  }
  out.container_volume = box->volume();
  double solid = 0.0, r_max = 0.0, r_sum = 0.0;  // m^3, m, m
  for (const double r : out.radius) {
    solid += ball_volume(r);
    r_max = std::max(r_max, r);
    r_sum += r;
  }
  out.fraction = solid / out.container_volume;
  const Vec3 extent = box->hi() - box->lo();
  if (2.0 * r_max >= std::min({extent.x, extent.y, extent.z}))
    fail(size_option, "the largest particle (radius " + number_text(r_max) + " m) does not fit in the container");

  PackingOptions po;
  po.tolerance = spec.tolerance;
  po.max_sweeps = spec.max_sweeps;
  po.seed = spec.seed ^ 0x9E3779B97F4A7C15ull;  // centres from their own stream
  DensePacking pack;
  try {
    pack = pack_dense(out.radius, *box, po);
  } catch (const std::invalid_argument& e) {
    fail(size_option, e.what());
  }
  out.largest_overlap = pack.largest_overlap;
  out.largest_protrusion = pack.largest_protrusion;
  out.sweeps = pack.sweeps;
  if (!pack.converged)
    fail("--fraction", "the overlaps did not fall below the tolerance " + number_text(spec.tolerance) + " within " +
                           std::to_string(spec.max_sweeps) + " sweeps at solid fraction " +
                           fmt::format("{:.4f}", out.fraction) + " (largest overlap " +
                           fmt::format("{:.3g}", pack.largest_overlap) + " of the smaller radius, largest protrusion " +
                           fmt::format("{:.3g}", pack.largest_protrusion) +
                           " of the radius): lower --fraction (random close packing of equal spheres is about 0.64, "
                           "less in a small container), or raise --tolerance or --max-sweeps");
  out.x = std::move(pack.x);

  out.gap = spec.gap >= 0.0 ? spec.gap : r_sum / (100.0 * static_cast<double>(out.radius.size()));
  out.bonds = gap_pairs(out.x, out.radius, out.gap);
  Clusters c = clusters(out.x.size(), out.bonds);
  out.kept_fraction = out.fraction;
  if (spec.largest_cluster_only && c.largest_size < out.x.size()) {
    keep_cluster(out, c, c.largest);
    double kept = 0.0;  // m^3
    for (const double r : out.radius) kept += ball_volume(r);
    out.kept_fraction = kept / out.container_volume;
    c = clusters(out.x.size(), out.bonds);
  }
  out.unbonded = c.unbonded;
  out.largest_cluster = c.largest_size;
  return out;
}

}  // namespace mpdem
