// Dense random packing by growth and overlap removal (docs/tools.md "mpdem agglomerate").
#include "generate/dense_packing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/value_range.hpp"
#include "generate/sphere_cells.hpp"

namespace mpdem {

namespace {

constexpr double kStartFraction = 0.3;      // -, solid fraction of the shrunk spheres at the start
constexpr double kGrowth = 5e-3;            // -, relative radius growth per sweep while growing
constexpr double kGrowBelow = 0.1;          // -, the radii grow only while the overlaps are below this
constexpr double kRelax = 1.9;              // -, over-relaxation: a projection moves a pair 1.9 x its overlap apart
constexpr int kPushes = 8;                  // pushes back inside per sphere and sweep, at most
constexpr std::size_t kMaxTries = 1000000;  // random centres tried per sphere at the start

// The state of a packing between sweeps: the centres, and for each sphere a position around
// which it stays clear of the container's surface.
class Packer {
 public:
  Packer(const std::vector<double>& r, const PackingContainer& box, double r_max)
      : r_(r), box_(box), cells_(box.lo(), box.hi(), 2.0 * r_max * 1.05), x_(r.size()), ref_(r.size()),
        clear_(r.size(), -1.0) {}

  std::vector<Vec3>& x() { return x_; }

  // One sweep at radius scale g: every overlapping pair pushed apart, every sphere put back
  // inside. Returns the largest relative overlap met (before its removal).
  double sweep(double g) {
    cells_.build(x_);
    double worst = 0.0;
    cells_.each_pair([&](std::size_t i, std::size_t j) {
      const double s = g * (r_[i] + r_[j]);
      const Vec3 d = x_[j] - x_[i];
      const double l2 = norm2(d);
      if (l2 >= s * s) return;
      const double l = std::sqrt(l2);
      const Vec3 n = l > 0.0 ? d / l : Vec3{1.0, 0.0, 0.0};  // coincident centres: any direction
      const double overlap = s - l;
      worst = std::max(worst, overlap / (g * std::min(r_[i], r_[j])));
      const Vec3 shift = n * (0.5 * kRelax * overlap);
      x_[i] -= shift;
      x_[j] += shift;
    });
    for (std::size_t i = 0; i < x_.size(); ++i) put_inside(i, g * r_[i]);
    return worst;
  }

  // Largest relative overlap and protrusion at the current positions (full radii, nothing moved).
  void measure(double& overlap, double& protrusion) {
    cells_.build(x_);
    overlap = 0.0;
    cells_.each_pair([&](std::size_t i, std::size_t j) {
      const double l = std::sqrt(norm2(x_[j] - x_[i]));
      overlap = std::max(overlap, (r_[i] + r_[j] - l) / std::min(r_[i], r_[j]));
    });
    protrusion = 0.0;
    for (std::size_t i = 0; i < x_.size(); ++i) protrusion = std::max(protrusion, (r_[i] - box_.depth(x_[i])) / r_[i]);
  }

 private:
  // A sphere that has not left the ball of radius clear - r about its reference position is
  // still inside: the container's surface is asked only about the others (those near it).
  void put_inside(std::size_t i, double r) {
    if (clear_[i] >= 0.0 && norm(x_[i] - ref_[i]) + r <= clear_[i]) return;
    // Near an edge or a corner of a surface one push clears the nearest face only: a few more
    // clear the others.
    for (int k = 0; k < kPushes && box_.push_inside(x_[i], r) > 0.0; ++k) {}
    ref_[i] = x_[i];
    clear_[i] = box_.depth(x_[i]);
  }

  const std::vector<double>& r_;  // m, radii, shape [n]
  const PackingContainer& box_;
  SphereCells cells_;
  std::vector<Vec3> x_;        // m, centres, shape [n]
  std::vector<Vec3> ref_;      // m, where each sphere's clearance was measured, shape [n]
  std::vector<double> clear_;  // m, depth inside the container at ref_, shape [n]; < 0: unknown
};

}  // namespace

DensePacking pack_dense(const std::vector<double>& radii, const PackingContainer& container, const PackingOptions& o) {
  DensePacking out;
  if (radii.empty()) {
    out.converged = true;
    return out;
  }
  double r_max = 0.0, volume = 0.0;  // m, m^3
  for (const double r : radii) {
    r_max = std::max(r_max, r);
    volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  }
  const double fraction = volume / container.volume();
  double g = std::min(1.0, std::cbrt(kStartFraction / fraction));  // -, radius scale

  Packer p(radii, container, r_max);
  Rng rng(o.seed);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    std::size_t tries = 0;
    while (!container.sample(rng, g * radii[i], p.x()[i]))
      if (++tries == kMaxTries)
        throw std::invalid_argument("no room in the container for a sphere of radius " + number_text(g * radii[i]) +
                                    " m: none of " + std::to_string(kMaxTries) + " random centres kept it inside");
  }

  while (out.sweeps < o.max_sweeps) {
    const double worst = p.sweep(g);
    ++out.sweeps;
    if (g < 1.0) {
      if (worst < kGrowBelow) g = std::min(1.0, g * (1.0 + kGrowth));
      continue;
    }
    if (worst > o.tolerance) continue;
    p.measure(out.largest_overlap, out.largest_protrusion);
    if (out.largest_overlap <= o.tolerance && out.largest_protrusion <= o.tolerance) {
      out.converged = true;
      break;
    }
  }
  if (!out.converged) p.measure(out.largest_overlap, out.largest_protrusion);
  out.largest_overlap = std::max(0.0, out.largest_overlap);
  out.largest_protrusion = std::max(0.0, out.largest_protrusion);
  out.x = std::move(p.x());
  return out;
}

}  // namespace mpdem
