// Particle generator by random sequential addition (docs/tools.md "mpdem generate").
#include "generate/generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>

#include "core/input_error.hpp"
#include "core/value_range.hpp"
#include "generate/region.hpp"

namespace mpdem {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxParticles = 50'000'000;  // beyond this a request is surely a unit mistake
constexpr std::size_t kMaxCells = 1u << 24;        // cap on the dense grid (64 MiB of heads)

double sphere_volume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

// Dense cell grid over the region's bounding box with linked lists of placed spheres. Cells are
// at least as wide as the largest possible contact distance, so the 27 cells around a centre
// hold every sphere it could overlap.
class PlacementGrid {
 public:
  PlacementGrid(const Vec3& lo, const Vec3& hi, double reach, std::size_t n) : lo_(lo) {
    h_ = reach;
    const Vec3 e = hi - lo;
    for (;;) {
      double cells = 1.0;  // counted in double: a region far larger than the spheres overflows an int
      for (int a = 0; a < 3; ++a) cells *= std::max(1.0, std::ceil(e[a] / h_));
      if (cells <= static_cast<double>(kMaxCells)) {
        for (int a = 0; a < 3; ++a) dim_[a] = static_cast<int>(std::max(1.0, std::ceil(e[a] / h_)));
        head_.assign(static_cast<std::size_t>(cells), -1);
        break;
      }
      h_ *= 1.26;  // coarser cells: more spheres per cell, bounded memory
    }
    next_.reserve(n);
  }

  // True when a sphere (c, r) keeps `gap` from every placed sphere.
  bool free(const Vec3& c, double r, double gap, const std::vector<GeneratedParticle>& placed) const {
    int ci[3];
    for (int a = 0; a < 3; ++a) ci[a] = index(c[a], a);
    for (int i = std::max(0, ci[0] - 1); i <= std::min(dim_[0] - 1, ci[0] + 1); ++i)
      for (int j = std::max(0, ci[1] - 1); j <= std::min(dim_[1] - 1, ci[1] + 1); ++j)
        for (int k = std::max(0, ci[2] - 1); k <= std::min(dim_[2] - 1, ci[2] + 1); ++k)
          for (int p = head_[flat(i, j, k)]; p >= 0; p = next_[p]) {
            const double d = r + placed[p].radius + gap;
            if (norm2(placed[p].x - c) < d * d) return false;
          }
    return true;
  }
  void insert(const Vec3& c, int id) {
    const std::size_t f = flat(index(c.x, 0), index(c.y, 1), index(c.z, 2));
    next_.push_back(head_[f]);
    head_[f] = id;
  }

 private:
  int index(double v, int a) const {
    return std::clamp(static_cast<int>(std::floor((v - lo_[a]) / h_)), 0, dim_[a] - 1);
  }
  std::size_t flat(int i, int j, int k) const { return (static_cast<std::size_t>(i) * dim_[1] + j) * dim_[2] + k; }
  Vec3 lo_;
  double h_ = 1.0;  // m, cell size
  int dim_[3] = {1, 1, 1};
  std::vector<int> head_, next_;  // first sphere per cell, next sphere in the same cell
};

}  // namespace

std::vector<double> draw_radii(const GenerateSpec& spec, double region_volume, Rng& rng) {
  const auto fail = [&](const std::string& msg) { throw InputError(spec.origin, spec.line, "generate", msg); };
  std::vector<double> radii;
  if (spec.count > 0) {
    if (spec.count > kMaxParticles) fail("count " + std::to_string(spec.count) + " is above the limit of 5e7");
    radii.reserve(spec.count);
    for (std::size_t k = 0; k < spec.count; ++k) radii.push_back(spec.radius.sample(rng));
    return radii;
  }
  const double target = spec.solid_fraction * region_volume;
  // At least target / (the largest sphere's volume) draws: refused before drawing them.
  double largest = 0.0;  // m
  for (const double r : spec.radius.bounding_radii(true)) largest = std::max(largest, r);
  if (largest > 0.0 && target / sphere_volume(largest) > static_cast<double>(kMaxParticles))
    fail("the solid fraction needs more than 5e7 particles of this size; check units");
  double sum = 0.0;
  while (sum < target) {
    const double r = spec.radius.sample(rng);
    const double v = sphere_volume(r);
    if (sum + v - target > target - sum) break;  // stopping short is closer to the target
    radii.push_back(r);
    sum += v;
    if (radii.size() > kMaxParticles)
      fail("the solid fraction needs more than 5e7 particles of this size; check units");
  }
  return radii;
}


GenerateResult generate_particles(const GenerateSpec& spec) {
  const auto fail = [&](const std::string& msg) { throw InputError(spec.origin, spec.line, "generate", msg); };
  if (const std::string p = spec.radius.problem(); !p.empty()) fail("radius: " + p);
  if (spec.count == 0 && !(spec.solid_fraction > 0.0 && spec.solid_fraction < 1.0))
    fail("give a count >= 1 or a solid_fraction in (0, 1)");
  if (!(spec.gap >= 0.0) || !std::isfinite(spec.gap)) fail("expected a gap >= 0, got " + number_text(spec.gap));
  if (spec.max_attempts == 0) fail("expected max_attempts >= 1");

  const Region region(spec.region, spec.origin, spec.line);
  GenerateResult res;
  res.region_volume = region.volume();

  Rng rng(spec.seed);
  std::vector<double> radii = draw_radii(spec, res.region_volume, rng);
  std::sort(radii.begin(), radii.end(), std::greater<>());
  if (radii.empty()) fail("the requested solid fraction is smaller than one particle");
  const double r_max = radii.front();
  if (!region.has_room(r_max + spec.gap))
    fail("the largest sphere (radius " + number_text(r_max) + " m, gap " + number_text(spec.gap) +
         " m) does not fit in the region");

  PlacementGrid grid(region.lo(), region.hi(), 2.0 * r_max + spec.gap, radii.size());
  res.particles.reserve(radii.size());
  double placed_volume = 0.0;
  for (std::size_t n = 0; n < radii.size(); ++n) {
    const double r = radii[n];
    bool done = false;
    for (std::size_t a = 0; a < spec.max_attempts && !done; ++a) {
      ++res.attempts;
      Vec3 c;
      if (!region.sample(rng, r + spec.gap, c) || !grid.free(c, r, spec.gap, res.particles)) continue;
      grid.insert(c, static_cast<int>(res.particles.size()));
      res.particles.push_back({c, r, Vec3{}});
      placed_volume += sphere_volume(r);
      done = true;
    }
    if (!done) {
      double wanted = 0.0;
      for (double x : radii) wanted += sphere_volume(x);
      fail("could not place particle " + std::to_string(n + 1) + " of " + std::to_string(radii.size()) + " (radius " +
           number_text(r) + " m) in " + std::to_string(spec.max_attempts) +
           " random attempts: reached solid fraction " + number_text(placed_volume / res.region_volume) +
           " of the requested " + number_text(wanted / res.region_volume) +
           ". Random sequential addition jams near 0.38 for equal spheres (less near walls); lower "
           "count/solid_fraction or gap, enlarge the region, or raise max_attempts");
    }
  }
  res.solid_fraction = placed_volume / res.region_volume;

  // Velocities from their own stream, so that positions do not depend on the velocity choice.
  Rng vrng(spec.seed ^ 0x9E3779B97F4A7C15ull);
  for (GeneratedParticle& p : res.particles) {
    if (spec.speed > 0.0) p.v = vrng.unit_vector() * spec.speed;
    else if (spec.velocity) p.v = *spec.velocity;
  }
  return res;
}

}  // namespace mpdem
