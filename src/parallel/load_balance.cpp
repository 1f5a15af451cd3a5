#include "parallel/load_balance.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace mpdem {

double imbalance(const Communicator& comm, double cost) {
  const double worst = comm.max(cost);
  const double mean = comm.sum(cost) / comm.size();
  return mean > 0.0 ? worst / mean : 1.0;
}

namespace {

constexpr int kBinsPerBrick = 64;  // histogram resolution: a cut lands within 1/64 of a brick

// The cut planes (m, ascending) that split the cost histogram `h` (its sum `total`) over [lo, hi]
// into n equal parts, linear within a bin.
std::vector<double> quantile_cuts(const std::vector<double>& h, double total, double lo, double hi, int n) {
  const double bin = (hi - lo) / static_cast<double>(h.size());
  std::vector<double> cuts;
  double below = 0.0;  // cost in the bins before b
  std::size_t b = 0;
  for (int k = 1; k < n; ++k) {
    const double target = total * k / n;
    while (b + 1 < h.size() && below + h[b] < target) below += h[b++];
    const double frac = h[b] > 0.0 ? std::clamp((target - below) / h[b], 0.0, 1.0) : 0.5;
    cuts.push_back(lo + (static_cast<double>(b) + frac) * bin);
  }
  return cuts;
}

// `want` moved into the allowed region: each cut strictly between its old neighbours, bounded
// bricks at least min_width wide. False when that is impossible.
bool constrain(std::vector<double>& want, const std::vector<double>& old, double lo, double hi, bool periodic,
               double min_width) {
  const std::size_t m = old.size();
  const double inf = std::numeric_limits<double>::infinity();
  const double eps = 1e-9 * (hi - lo);
  const auto lower = [&](std::size_t k) { return k == 0 ? (periodic ? lo : -inf) : old[k - 1]; };
  const auto upper = [&](std::size_t k) { return k + 1 == m ? (periodic ? hi : inf) : old[k + 1]; };
  for (std::size_t k = 0; k < m; ++k) want[k] = std::clamp(want[k], lower(k) + eps, upper(k) - eps);
  // Widths: forward (each cut at least min_width above the previous one), then backward.
  for (std::size_t k = 0; k < m; ++k) {
    const double floor = k == 0 ? (periodic ? lo + min_width : -inf) : want[k - 1] + min_width;
    want[k] = std::max(want[k], floor);
  }
  for (std::size_t k = m; k-- > 0;) {
    const double ceil = k + 1 == m ? (periodic ? hi - min_width : inf) : want[k + 1] - min_width;
    want[k] = std::min(want[k], ceil);
  }
  const double tol = 1e-12 * (hi - lo);
  for (std::size_t k = 0; k < m; ++k) {
    if (!(want[k] > lower(k) && want[k] < upper(k))) return false;
    const double below = k == 0 ? (periodic ? lo : -inf) : want[k - 1];
    if (!(want[k] - below >= min_width - tol)) return false;
  }
  return !periodic || hi - want[m - 1] >= min_width - tol;
}

}  // namespace

bool shift_cuts(BrickGrid& grid, const Communicator& comm, std::span<const Vec3> x, double cost, double min_width) {
  const double weight = x.empty() ? 0.0 : cost / static_cast<double>(x.size());  // per particle
  // A margin above the halo's reach, so that round-off in placing a cut at the least width does
  // not make the brick narrower than the halo's check wants.
  min_width *= 1.0 + 1e-6;
  bool moved = false;
  for (int c = 0; c < 3; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const int n = grid.dims()[cc];
    const double lo = grid.box_lower()[c], hi = grid.box_upper()[c];
    if (n == 1 || !(hi > lo)) continue;
    const bool periodic = grid.periodic()[cc];
    std::vector<double> h(static_cast<std::size_t>(kBinsPerBrick * n), 0.0);
    const double per_bin = static_cast<double>(h.size()) / (hi - lo);
    for (const Vec3& p : x) {
      double u = p[c];
      if (periodic) u -= std::floor((u - lo) / (hi - lo)) * (hi - lo);
      const double b = std::clamp(std::floor((u - lo) * per_bin), 0.0, static_cast<double>(h.size() - 1));
      h[static_cast<std::size_t>(b)] += weight;
    }
    comm.sum(h);  // in rank order: the same histogram, so the same cuts, on every rank
    double total = 0.0;
    for (double v : h) total += v;
    if (!(total > 0.0)) continue;
    std::vector<double> want = quantile_cuts(h, total, lo, hi, n);
    if (!constrain(want, grid.cuts(c), lo, hi, periodic, min_width) || want == grid.cuts(c)) continue;
    grid.set_cuts(c, std::move(want));
    moved = true;
  }
  return moved;
}

}  // namespace mpdem
