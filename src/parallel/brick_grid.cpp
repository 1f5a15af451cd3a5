#include "parallel/brick_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mpdem {

std::array<int, 3> BrickGrid::choose_dims(int ranks, const Vec3& extent, const std::array<bool, 3>& periodic) {
  if (ranks < 1) throw std::invalid_argument("BrickGrid: at least one rank");
  const double area[3] = {extent.y * extent.z, extent.x * extent.z, extent.x * extent.y};  // m^2, normal to c
  std::array<int, 3> best{ranks, 1, 1};
  double best_cut = std::numeric_limits<double>::infinity();
  for (int dx = ranks; dx >= 1; --dx) {
    if (ranks % dx != 0) continue;
    for (int dy = ranks / dx; dy >= 1; --dy) {
      if ((ranks / dx) % dy != 0) continue;
      const int dz = ranks / dx / dy;
      const int d[3] = {dx, dy, dz};
      double cut = 0.0;
      for (int c = 0; c < 3; ++c)
        if (d[c] > 1) cut += (d[c] - (periodic[static_cast<std::size_t>(c)] ? 0 : 1)) * area[c];
      // Strictly smaller only: the first found (the most bricks along x, then y) wins ties.
      if (cut < best_cut * (1.0 - 1e-12)) {
        best_cut = cut;
        best = {dx, dy, dz};
      }
    }
  }
  return best;
}

BrickGrid::BrickGrid(int ranks, const Vec3& lo, const Vec3& hi, const std::array<bool, 3>& periodic)
    : periodic_(periodic), lo_(lo), hi_(hi) {
  dims_ = choose_dims(ranks, hi - lo, periodic);
  for (int c = 0; c < 3; ++c) {
    auto& cut = cuts_[static_cast<std::size_t>(c)];
    const int n = dims_[static_cast<std::size_t>(c)];
    for (int k = 1; k < n; ++k) cut.push_back(lo[c] + (hi[c] - lo[c]) * k / n);
  }
}

std::array<int, 3> BrickGrid::coords(int rank) const {
  return {rank % dims_[0], (rank / dims_[0]) % dims_[1], rank / (dims_[0] * dims_[1])};
}

int BrickGrid::rank_at(const std::array<int, 3>& c) const { return c[0] + dims_[0] * (c[1] + dims_[1] * c[2]); }

int BrickGrid::brick_along(int c, double x) const {
  const auto& cut = cuts_[static_cast<std::size_t>(c)];
  if (periodic_[static_cast<std::size_t>(c)]) {
    const double L = hi_[c] - lo_[c];
    if (x < lo_[c] || x >= hi_[c]) x -= std::floor((x - lo_[c]) / L) * L;
  }
  return static_cast<int>(std::upper_bound(cut.begin(), cut.end(), x) - cut.begin());
}

int BrickGrid::owner(const Vec3& x) const {
  return rank_at({brick_along(0, x.x), brick_along(1, x.y), brick_along(2, x.z)});
}

std::vector<char> BrickGrid::owned(std::span<const Vec3> x, int rank) const {
  std::vector<char> mask(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) mask[i] = owner(x[i]) == rank ? 1 : 0;
  return mask;
}

int BrickGrid::neighbour(int rank, int c, int dir) const {
  std::array<int, 3> k = coords(rank);
  const auto cc = static_cast<std::size_t>(c);
  k[cc] += dir;
  if (k[cc] < 0 || k[cc] >= dims_[cc]) {
    if (!periodic_[cc]) return -1;
    k[cc] = (k[cc] + dims_[cc]) % dims_[cc];
  }
  return rank_at(k);
}

double BrickGrid::lower(int rank, int c) const {
  const auto cc = static_cast<std::size_t>(c);
  const int k = coords(rank)[cc];
  if (k > 0) return cuts_[cc][static_cast<std::size_t>(k - 1)];
  return periodic_[cc] ? lo_[c] : -std::numeric_limits<double>::infinity();
}

double BrickGrid::upper(int rank, int c) const {
  const auto cc = static_cast<std::size_t>(c);
  const int k = coords(rank)[cc];
  if (k + 1 < dims_[cc]) return cuts_[cc][static_cast<std::size_t>(k)];
  return periodic_[cc] ? hi_[c] : std::numeric_limits<double>::infinity();
}

void BrickGrid::set_cuts(int c, std::vector<double> planes) {
  const auto cc = static_cast<std::size_t>(c);
  if (planes.size() + 1 != static_cast<std::size_t>(dims_[cc]) || !std::is_sorted(planes.begin(), planes.end()))
    throw std::invalid_argument("BrickGrid::set_cuts: one ascending plane per interior cut");
  cuts_[cc] = std::move(planes);
}

double BrickGrid::narrowest() const {
  double w = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 3; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    if (dims_[cc] == 1) continue;
    // The outer bricks of a non-periodic axis are unbounded; the interior ones and, along a
    // periodic axis, the end ones are bounded by the cuts and the box.
    std::vector<double> planes = cuts_[cc];
    if (periodic_[cc]) {
      planes.insert(planes.begin(), lo_[c]);
      planes.push_back(hi_[c]);
    }
    for (std::size_t k = 0; k + 1 < planes.size(); ++k) w = std::min(w, planes[k + 1] - planes[k]);
  }
  return w;
}

}  // namespace mpdem
