// Greedy fill of a closed surface with inscribed spheres (tools/clump_fill.hpp).
#include "tools/clump_fill.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <stdexcept>

#include "geometry/mesh_solid.hpp"

namespace mpdem {

namespace {

// The sample grid: cell-centred points of spacing s, symmetric about the bounding box's centre.
struct SampleGrid {
  std::array<int, 3> n{1, 1, 1};  // points per axis
  Vec3 first;                     // m, point (0, 0, 0)
  double s = 0.0;                 // m, spacing

  SampleGrid(const Vec3& lo, const Vec3& hi, int resolution) {
    const Vec3 ext = hi - lo;
    s = std::max({ext.x, ext.y, ext.z}) / resolution;
    for (int a = 0; a < 3; ++a) {
      n[a] = std::max(1, static_cast<int>(std::ceil(ext[a] / s - 1e-9)));
      if ((n[a] - resolution) % 2 != 0) ++n[a];  // the longest edge's parity: odd K, a point at every middle
      first[a] = lo[a] + 0.5 * (ext[a] - n[a] * s) + 0.5 * s;
    }
  }
  std::size_t size() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  std::size_t row(int i, int j) const { return static_cast<std::size_t>(i) * n[1] + j; }
  std::size_t index(int i, int j, int k) const { return row(i, j) * n[2] + k; }
  Vec3 point(int i, int j, int k) const { return first + Vec3{double(i), double(j), double(k)} * s; }
};

struct Candidate {
  std::array<int, 3> at{};  // grid indices of the centre
  double r = 0.0;           // m, distance to the surface
  double r2 = 0.0;          // (r / s)^2: a point at integer offset d is in the sphere iff |d|^2 <= r2
};

struct Entry {
  std::size_t gain = 0;  // uncovered sample points in the sphere (stale: an upper bound)
  double r = 0.0;        // m
  std::size_t cand = 0;  // candidate index (grid order)
};
// Priority: more gain, then the larger radius, then the lower index.
bool lower(const Entry& a, const Entry& b) {
  if (a.gain != b.gain) return a.gain < b.gain;
  if (a.r != b.r) return a.r < b.r;
  return a.cand > b.cand;
}

// Calls f(row, k0, k1) for every grid row (i, j) that candidate c's sphere meets, with the range
// k0..k1 of the row's points inside the sphere.
template <class F>
void for_each_row_in_sphere(const SampleGrid& g, const Candidate& c, F&& f) {
  const int reach = static_cast<int>(std::floor(std::sqrt(c.r2)));
  const auto inside = [&](long d2) { return static_cast<double>(d2) <= c.r2; };
  for (int di = std::max(-reach, -c.at[0]); di <= std::min(reach, g.n[0] - 1 - c.at[0]); ++di)
    for (int dj = std::max(-reach, -c.at[1]); dj <= std::min(reach, g.n[1] - 1 - c.at[1]); ++dj) {
      const long dij = long(di) * di + long(dj) * dj;
      if (!inside(dij)) continue;
      int dk = static_cast<int>(std::floor(std::sqrt(std::max(0.0, c.r2 - double(dij)))));
      while (inside(dij + long(dk + 1) * (dk + 1))) ++dk;  // sqrt's rounding, either way
      while (dk > 0 && !inside(dij + long(dk) * dk)) --dk;
      f(g.row(c.at[0] + di, c.at[1] + dj), std::max(-dk, -c.at[2]) + c.at[2],
        std::min(dk, g.n[2] - 1 - c.at[2]) + c.at[2]);
    }
}

// Whether the sphere at grid point `at` lies inside the sphere of one of its 26 neighbours
// (radius: m, per grid point), up to 1e-9 s.
bool inside_a_neighbour(const SampleGrid& g, const std::vector<double>& radius, const std::array<int, 3>& at) {
  const double r = radius[g.index(at[0], at[1], at[2])];
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj)
      for (int dk = -1; dk <= 1; ++dk) {
        const int i = at[0] + di, j = at[1] + dj, k = at[2] + dk;
        if ((di | dj | dk) == 0 || i < 0 || j < 0 || k < 0 || i >= g.n[0] || j >= g.n[1] || k >= g.n[2]) continue;
        const double d = g.s * std::sqrt(double(di * di + dj * dj + dk * dk));
        if (r + d <= radius[g.index(i, j, k)] + 1e-9 * g.s) return true;
      }
  return false;
}

}  // namespace

ClumpFill fill_with_spheres(const TriangleMesh& mesh, int count, int resolution) {
  if (count < 1) throw std::invalid_argument("the number of spheres must be at least 1");
  if (resolution < 2) throw std::invalid_argument("the grid resolution must be at least 2");
  const MeshSolid solid(mesh);
  const SampleGrid g(solid.lo(), solid.hi(), resolution);

  enum : std::int8_t { kOutside = -1, kUncovered = 0, kCovered = 1 };
  std::vector<std::int8_t> state(g.size(), kOutside);  // per grid point: outside, or a sample point
  std::vector<double> radius(g.size(), 0.0);           // m, per grid point: distance to the surface (0 outside)
  ClumpFill out;
  out.spacing = g.s;
  for (int i = 0; i < g.n[0]; ++i)
    for (int j = 0; j < g.n[1]; ++j)
      for (int k = 0; k < g.n[2]; ++k) {
        const Vec3 p = g.point(i, j, k);
        if (!solid.contains(p)) continue;
        state[g.index(i, j, k)] = kUncovered;
        ++out.samples;
        radius[g.index(i, j, k)] = solid.distance_to_surface(p);
      }
  // A sphere inside a neighbour's sphere (r + d <= r_neighbour) covers a subset of its points, so
  // it can never gain more, and loses ties to the larger radius: dropping it changes no choice
  // (up to sample points within 1e-9 s of a sphere's surface) and leaves, where one face is
  // nearest, only the points near the medial surface.
  std::vector<Candidate> cand;
  for (int i = 0; i < g.n[0]; ++i)
    for (int j = 0; j < g.n[1]; ++j)
      for (int k = 0; k < g.n[2]; ++k) {
        const double r = radius[g.index(i, j, k)];
        if (!(r > 0.0) || inside_a_neighbour(g, radius, {i, j, k})) continue;
        cand.push_back({{i, j, k}, r, (r / g.s) * (r / g.s)});
      }
  if (cand.empty()) throw std::invalid_argument("no grid point falls inside the solid: raise the grid resolution");

  // Per grid row (i, j), prefix counts of the uncovered points: a sphere's gain is a sum over its
  // rows of O(1) differences.
  const std::size_t stride = static_cast<std::size_t>(g.n[2]) + 1;
  std::vector<std::uint32_t> prefix(static_cast<std::size_t>(g.n[0]) * g.n[1] * stride);  // per row: n[2] + 1
  const auto count_row = [&](std::size_t r) {
    std::uint32_t acc = 0;
    for (int k = 0; k < g.n[2]; ++k) {
      prefix[r * stride + k] = acc;
      acc += state[r * g.n[2] + k] == kUncovered;
    }
    prefix[r * stride + g.n[2]] = acc;
  };
  for (std::size_t r = 0; r < prefix.size() / stride; ++r) count_row(r);
  const auto gain = [&](const Candidate& c) {
    std::size_t n = 0;
    for_each_row_in_sphere(
        g, c, [&](std::size_t r, int k0, int k1) { n += prefix[r * stride + k1 + 1] - prefix[r * stride + k0]; });
    return n;
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(&lower)> queue(&lower);
  for (std::size_t c = 0; c < cand.size(); ++c) queue.push({gain(cand[c]), cand[c].r, c});
  while (out.members.size() < static_cast<std::size_t>(count) && !queue.empty()) {
    Entry e = queue.top();
    queue.pop();
    e.gain = gain(cand[e.cand]);
    if (!queue.empty() && lower(e, queue.top())) {  // no longer the best: back with its fresh gain
      queue.push(e);
      continue;
    }
    if (e.gain == 0) break;  // the best gains nothing: every sample point some candidate reaches is covered
    const Candidate& c = cand[e.cand];
    for_each_row_in_sphere(g, c, [&](std::size_t r, int k0, int k1) {
      for (int k = k0; k <= k1; ++k)
        if (state[r * g.n[2] + k] == kUncovered) state[r * g.n[2] + k] = kCovered;
      count_row(r);
    });
    out.covered += e.gain;
    out.members.push_back({g.point(c.at[0], c.at[1], c.at[2]), c.r});
  }
  return out;
}

}  // namespace mpdem
