#include "parallel/periodic_images.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <string_view>

namespace mpdem {

PeriodicImages::PeriodicImages(const DomainParams& d) {
  if (!d.bounded) return;
  periodic_ = d.periodic;
  lo_ = d.min;
  hi_ = d.max;
  for (int c = 0; c < 3; ++c) period_[c] = periodic_[static_cast<std::size_t>(c)] ? d.max[c] - d.min[c] : 0.0;
}

namespace {

// Moves x into [lo, hi) by whole periods L = hi - lo; returns the periods taken off.
double wrap_coordinate(double& x, double lo, double hi, double L) {
  double m = std::floor((x - lo) / L);
  x -= m * L;
  // Round-off can leave x a hair outside [lo, hi).
  if (x >= hi) {
    x -= L;
    m += 1.0;
  } else if (x < lo) {
    x += L;
    m -= 1.0;
  }
  return m;
}

}  // namespace

void PeriodicImages::wrap(Particles& p) const {
  if (!active()) return;
  // A clump body's centre is wrapped and its members move with it by the same periods (never one
  // by one, so that a member stays at its place in the body and may lie outside the box by up to
  // its offset from the centre).
  Bodies& B = p.bodies;
  std::vector<Vec3> body_shift(B.size());  // m, what each body moved by
  for (std::size_t b = 0; b < B.size(); ++b)
    for (int c = 0; c < 3; ++c) {
      double& x = B.x[b][c];
      if (!periodic_[static_cast<std::size_t>(c)] || !std::isfinite(x) || (x >= lo_[c] && x < hi_[c])) continue;
      const double m = wrap_coordinate(x, lo_[c], hi_[c], period_[c]);
      body_shift[b][c] = m * period_[c];
      B.image[b][static_cast<std::size_t>(c)] += static_cast<std::int32_t>(m);
    }
  if (!B.empty()) B.index_members(p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != kNoBody) {
      const std::size_t b = B.owner[i];
      p.x[i] -= body_shift[b];
      p.image[i] = B.image[b];
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      if (!periodic_[static_cast<std::size_t>(c)]) continue;
      double& x = p.x[i][c];
      if (!std::isfinite(x) || (x >= lo_[c] && x < hi_[c])) continue;  // a non-finite one is reported elsewhere
      p.image[i][static_cast<std::size_t>(c)] += static_cast<std::int32_t>(
          wrap_coordinate(x, lo_[c], hi_[c], period_[c]));
    }
  }
}

void PeriodicImages::select(std::span<const Vec3> x, double width) {
  source_.clear();
  shift_.clear();
  if (!active()) return;
  for (int c = 0; c < 3; ++c)
    if (periodic_[static_cast<std::size_t>(c)] && !(period_[c] >= 2.0 * width))
      throw std::invalid_argument(fmt::format(
          "the periodic domain is {:.6g} m long along {}, shorter than twice the neighbour range {:.6g} m (2 x the "
          "largest radius + skin + near-field reach, plus a skin for the drift and the largest clump member's "
          "offset from its centre): enlarge [domain] min/max along {} or use smaller particles",
          period_[c], "xyz"[c], width, "xyz"[c]));
  for (std::size_t i = 0; i < x.size(); ++i) {
    // Per axis: -1 (near max: an image one period down), +1 (near min: one period up), or 0.
    int side[3] = {0, 0, 0};
    bool any = false;
    for (int c = 0; c < 3; ++c) {
      if (!periodic_[static_cast<std::size_t>(c)]) continue;
      if (x[i][c] < lo_[c] + width) side[c] = 1;
      else if (x[i][c] >= hi_[c] - width) side[c] = -1;
      any = any || side[c] != 0;
    }
    if (!any) continue;
    // Every combination of the axes' images but the particle itself (bit c: shifted along c).
    for (int mask = 1; mask < 8; ++mask) {
      bool valid = true;
      Vec3 s{};
      for (int c = 0; c < 3; ++c) {
        if (!(mask & (1 << c))) continue;
        valid = valid && side[c] != 0;
        s[c] = side[c] * period_[c];
      }
      if (!valid) continue;
      source_.push_back(static_cast<std::uint32_t>(i));
      shift_.push_back(s);
    }
  }
}

void PeriodicImages::append(Particles& p) const {
  if (p.n_ghost != 0) throw std::logic_error("periodic images: the particles already hold ghosts");
  const std::size_t n = p.size(), g = source_.size();
  p.for_each_array([&](const char*, auto& a) {
    a.resize(n + g);
    for (std::size_t k = 0; k < g; ++k) a[n + k] = a[source_[k]];
  });
  p.n_ghost = g;
  for (std::size_t k = 0; k < g; ++k) p.x[n + k] += shift_[k];
}

void PeriodicImages::refresh(Particles& p) const {
  const std::size_t n = p.size(), g = p.n_ghost;
  if (g == 0) return;
  // Every array follows its source (a material or radius edited between steps too) but the
  // accumulators, which start at zero: what a ghost receives is folded onto its source.
  p.for_each_array([&](const char* name, auto& a) {
    const std::string_view s(name);
    using T = typename std::decay_t<decltype(a)>::value_type;
    if (s == "force" || s == "torque" || s == "heat") {
      for (std::size_t k = 0; k < g; ++k) a[n + k] = T{};
      return;
    }
    for (std::size_t k = 0; k < g; ++k) a[n + k] = a[source_[k]];
  });
  for (std::size_t k = 0; k < g; ++k) p.x[n + k] += shift_[k];
}

void PeriodicImages::fold(Particles& p) const {
  const std::size_t n = p.size(), g = p.n_ghost;
  for (std::size_t k = 0; k < g; ++k) {
    const std::uint32_t s = source_[k];
    p.force[s] += p.force[n + k];
    p.torque[s] += p.torque[n + k];
    p.heat[s] += p.heat[n + k];
  }
}

std::size_t PeriodicImages::memory_bytes() const {
  return source_.capacity() * sizeof(std::uint32_t) + shift_.capacity() * sizeof(Vec3);
}

}  // namespace mpdem
