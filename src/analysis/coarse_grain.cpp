#include "analysis/coarse_grain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mpdem {

namespace {

using Tensor = std::array<double, 9>;  // row-major 3x3

struct Axis {
  bool resolved = false;
  int n = 1;             // -, points along the axis (1 when averaged)
  double lo = 0.0;       // m, min
  double spacing = 0.0;  // m, (max - min) / cells
};

// The grid in the form the loops want: per-axis spacing, point coordinates, index strides.
struct Layout {
  std::array<Axis, 3> axis;
  std::array<std::vector<double>, 3> coord;  // m, [n] point coordinates per axis (0 when averaged)
  std::array<std::size_t, 3> stride{};       // -, index step per axis (x fastest)
  std::size_t points = 1;
  int dims = 0;
  double inv_extent = 1.0;  // 1/m^(3-d), 1 / product of the averaged extents

  explicit Layout(const CgGrid& g) {
    cg_validate(g);
    for (int k = 0; k < 3; ++k) {
      Axis& ax = axis[static_cast<std::size_t>(k)];
      ax.lo = g.min[k];
      if (g.resolved[static_cast<std::size_t>(k)]) {
        ax.resolved = true;
        ax.n = g.cells[static_cast<std::size_t>(k)];
        ax.spacing = (g.max[k] - g.min[k]) / ax.n;
        ++dims;
      } else {
        inv_extent /= g.max[k] - g.min[k];
      }
      auto& c = coord[static_cast<std::size_t>(k)];
      c.resize(static_cast<std::size_t>(ax.n), 0.0);
      if (ax.resolved)
        for (int j = 0; j < ax.n; ++j) c[static_cast<std::size_t>(j)] = ax.lo + (j + 0.5) * ax.spacing;
      stride[static_cast<std::size_t>(k)] = points;
      points *= static_cast<std::size_t>(ax.n);
    }
  }

  // x with its averaged components zeroed: the kernel sees only the resolved axes.
  Vec3 mask(const Vec3& x) const {
    return {axis[0].resolved ? x.x : 0.0, axis[1].resolved ? x.y : 0.0, axis[2].resolved ? x.z : 0.0};
  }

  // Calls f(index, r) for every point r (averaged components 0) whose coordinates are within
  // `reach` of the box [lo, hi] along every resolved axis. The ranges are padded by 1e-6 of a
  // cell so rounding never drops a point; the kernel's own r < cutoff test decides.
  template <class F>
  void for_each_near(const Vec3& lo, const Vec3& hi, double reach, F&& f) const {
    std::array<int, 3> first{0, 0, 0}, last{0, 0, 0};
    for (std::size_t k = 0; k < 3; ++k) {
      const Axis& ax = axis[k];
      if (!ax.resolved) continue;
      const int kk = static_cast<int>(k);
      const double a = (lo[kk] - reach - ax.lo) / ax.spacing - 0.5 - 1e-6;  // index units
      const double b = (hi[kk] + reach - ax.lo) / ax.spacing - 0.5 + 1e-6;
      if (!(b >= 0.0) || !(a <= ax.n - 1.0)) return;
      first[k] = a <= 0.0 ? 0 : static_cast<int>(std::ceil(a));
      last[k] = b >= ax.n - 1.0 ? ax.n - 1 : static_cast<int>(std::floor(b));
      if (first[k] > last[k]) return;
    }
    Vec3 r;
    for (int iz = first[2]; iz <= last[2]; ++iz) {
      r.z = coord[2][static_cast<std::size_t>(iz)];
      for (int iy = first[1]; iy <= last[1]; ++iy) {
        r.y = coord[1][static_cast<std::size_t>(iy)];
        const std::size_t row = static_cast<std::size_t>(iz) * stride[2] + static_cast<std::size_t>(iy) * stride[1];
        for (int ix = first[0]; ix <= last[0]; ++ix) {
          r.x = coord[0][static_cast<std::size_t>(ix)];
          f(row + static_cast<std::size_t>(ix) * stride[0], r);
        }
      }
    }
  }
};

void add_outer(Tensor& t, const Vec3& a, const Vec3& b, double w) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j)] += w * a[i] * b[j];
}

// Sizes every field to `points` (zeros).
void allocate(CgFields& f, std::size_t points) {
  for (auto* v : {&f.density, &f.solid_fraction, &f.number_density, &f.temperature, &f.coordination})
    v->assign(points, 0.0);
  for (auto* v : {&f.momentum, &f.velocity, &f.boundary_force_density}) v->assign(points, Vec3{});
  for (auto* v : {&f.kinetic_stress, &f.contact_stress, &f.stress}) v->assign(points, Tensor{});
}

void derive_velocity(CgFields& f) {
  for (std::size_t k = 0; k < f.size(); ++k) f.velocity[k] = f.density[k] > 0.0 ? f.momentum[k] / f.density[k] : Vec3{};
}

// The derived fields from the primary ones (velocity already set): T = tr(sigma_k)/(3 rho),
// Z = Σ z phi / Σ phi, sigma = sigma_k + sigma_c.
void finish(CgFields& f, const std::vector<double>& coordination_sum) {
  for (std::size_t k = 0; k < f.size(); ++k) {
    const Tensor& sk = f.kinetic_stress[k];
    f.temperature[k] = f.density[k] > 0.0 ? (sk[0] + sk[4] + sk[8]) / (3.0 * f.density[k]) : 0.0;
    f.coordination[k] = f.number_density[k] > 0.0 ? coordination_sum[k] / f.number_density[k] : 0.0;
    for (std::size_t c = 0; c < 9; ++c) f.stress[k][c] = sk[c] + f.contact_stress[k][c];
  }
}

// m, the image shifts a particle acts through: 0, then -L and +L along each periodic resolved
// axis and their combinations (averaged axes integrate the whole extent and need none).
std::vector<Vec3> image_shifts(const Layout& layout, const Vec3& period, double reach) {
  std::vector<Vec3> shifts{Vec3{}};
  for (int k = 0; k < 3; ++k) {
    const double L = period[k];
    if (!layout.axis[static_cast<std::size_t>(k)].resolved || !(L > 0.0)) continue;
    // Images two periods away would reach the cell only if the cutoff exceeded a period.
    if (!std::isfinite(L) || L < reach)
      throw std::invalid_argument("coarse_grain: a period (" + std::to_string(L) +
                                  " m) shorter than the kernel cutoff (" + std::to_string(reach) + " m)");
    const std::size_t n = shifts.size();
    for (double sign : {-1.0, 1.0})
      for (std::size_t j = 0; j < n; ++j) {
        Vec3 s = shifts[j];
        s[k] += sign * L;
        shifts.push_back(s);
      }
  }
  return shifts;
}

}  // namespace

void cg_validate(const CgGrid& g) {
  for (int k = 0; k < 3; ++k) {
    const std::string axis(1, static_cast<char>('x' + k));
    if (!(g.min[k] < g.max[k]) || !std::isfinite(g.min[k]) || !std::isfinite(g.max[k]))
      throw std::invalid_argument("CgGrid: min < max (finite) is required along " + axis);
    if (g.resolved[static_cast<std::size_t>(k)] && g.cells[static_cast<std::size_t>(k)] < 1)
      throw std::invalid_argument("CgGrid: cells >= 1 is required along resolved axis " + axis);
  }
}

int cg_dims(const CgGrid& g) { return int{g.resolved[0]} + int{g.resolved[1]} + int{g.resolved[2]}; }

std::size_t cg_point_count(const CgGrid& g) {
  std::size_t n = 1;
  for (std::size_t k = 0; k < 3; ++k)
    if (g.resolved[k]) n *= static_cast<std::size_t>(std::max(g.cells[k], 0));
  return n;
}

Vec3 cg_point(const CgGrid& g, std::size_t index) {
  Vec3 r;
  for (int k = 0; k < 3; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (!g.resolved[kk]) {
      r[k] = 0.5 * (g.min[k] + g.max[k]);
      continue;
    }
    const auto n = static_cast<std::size_t>(g.cells[kk]);
    const auto j = index % n;
    index /= n;
    // Same expression as Layout's coordinates, so the points agree to the last bit.
    r[k] = g.min[k] + (static_cast<double>(j) + 0.5) * ((g.max[k] - g.min[k]) / g.cells[kk]);
  }
  return r;
}

CgFields coarse_grain(const CgGrid& grid, CgKernel kernel, double width, std::span<const CgParticle> particles,
                      std::span<const CgContact> contacts, const Vec3& period) {
  const Layout layout(grid);
  const CgKernelFunction phi(kernel, width, layout.dims);
  const double reach = phi.cutoff();                                     // m
  const std::vector<Vec3> shifts = image_shifts(layout, period, reach);  // m, {0} first
  const double ie = layout.inv_extent;
  CgFields f;
  allocate(f, layout.points);
  std::vector<double> coordination_sum(layout.points, 0.0);  // 1/m^3, Σ z phi

  // Pass 1: the sums that are linear in the particles (Weinhart et al. 2012, rho, nu and p).
  for (const CgParticle& p : particles) {
    if (!isfinite(p.x)) throw std::invalid_argument("coarse_grain: non-finite particle position");
    const Vec3 x = layout.mask(p.x);
    const double m = p.mass * ie, vol = p.volume * ie, z = p.contacts * ie;
    const Vec3 mv = p.v * m;
    for (const Vec3& s : shifts) {
      const Vec3 xs = x + s;
      layout.for_each_near(xs, xs, reach, [&](std::size_t k, const Vec3& r) {
        const double w = phi(norm2(r - xs));
        if (w == 0.0) return;
        f.density[k] += m * w;
        f.solid_fraction[k] += vol * w;
        f.number_density[k] += ie * w;
        coordination_sum[k] += z * w;
        f.momentum[k] += mv * w;
      });
    }
  }
  derive_velocity(f);

  // Pass 2: kinetic stress about the velocity at the evaluation point, Σ m (v - V(r)) ⊗ (v - V(r)) phi
  // (two passes, rather than Σ m v v phi - p p / rho, so a fast uniform flow leaves no round-off).
  for (const CgParticle& p : particles) {
    const Vec3 x = layout.mask(p.x);
    const double m = p.mass * ie;
    for (const Vec3& s : shifts) {
      const Vec3 xs = x + s;
      layout.for_each_near(xs, xs, reach, [&](std::size_t k, const Vec3& r) {
        const double w = phi(norm2(r - xs));
        if (w == 0.0) return;
        const Vec3 dv = p.v - f.velocity[k];
        add_outer(f.kinetic_stress[k], dv, dv, m * w);
      });
    }
  }

  // Contacts: f ⊗ b spread along the branch from x_i (s = 0) to x_i - b (s = 1): the other
  // centre of a pair, or the contact point at a barrier (Weinhart et al. 2012, contact stress and
  // boundary term). Compression positive: f along +b (a pair pushed apart) gives sigma_aa > 0.
  for (const CgContact& c : contacts) {
    if (c.i >= particles.size()) throw std::out_of_range("coarse_grain: contact particle index out of range");
    if (!isfinite(c.branch)) throw std::invalid_argument("coarse_grain: non-finite contact branch");
    const Vec3 x = layout.mask(particles[c.i].x);
    const Vec3 b = layout.mask(c.branch);
    const Vec3 end = x - b;
    const Vec3 lo{std::min(x.x, end.x), std::min(x.y, end.y), std::min(x.z, end.z)};
    const Vec3 hi{std::max(x.x, end.x), std::max(x.y, end.y), std::max(x.z, end.z)};
    Tensor fb{};  // Pa m^d, f ⊗ b (full 3-D vectors) per unit averaged extent
    add_outer(fb, c.force, c.branch, ie);
    const Vec3 t = c.force * ie;
    for (const Vec3& s : shifts)
      layout.for_each_near(lo + s, hi + s, reach, [&](std::size_t k, const Vec3& r) {
        const Vec3 a = r - x - s;
        const double w = phi.line_integral(a, b);
        if (w != 0.0)
          for (std::size_t q = 0; q < 9; ++q) f.contact_stress[k][q] += w * fb[q];
        // The barrier's force density, applied at the contact point: it closes the momentum
        // balance within a kernel width of the wall (Weinhart et al. 2012, boundary term).
        if (c.boundary) f.boundary_force_density[k] += t * phi(norm2(a + b));
      });
  }
  finish(f, coordination_sum);
  return f;
}

void CgAverage::add(const CgFields& s) {
  const std::size_t n = s.size();
  if (samples_ == 0) {
    allocate(sum_, n);
    coordination_sum_.assign(n, 0.0);
    spread_.assign(n, Tensor{});
  } else if (n != sum_.size()) {
    throw std::invalid_argument("CgAverage::add: the sample has a different number of points");
  }
  for (std::size_t k = 0; k < n; ++k) {
    // Weighted Welford update of Σ rho_s (V_s - <V>)(V_s - <V>), <V> = Σ p / Σ rho: equals
    // Σ rho_s V_s V_s - (Σ p)(Σ p)/Σ rho without its cancellation in a fast mean flow.
    const double w_old = sum_.density[k], rho = s.density[k];
    if (w_old > 0.0 && rho > 0.0) {
      const Vec3 d = s.velocity[k] - sum_.momentum[k] / w_old;
      add_outer(spread_[k], d, d, rho * w_old / (w_old + rho));
    }
    sum_.density[k] += rho;
    sum_.solid_fraction[k] += s.solid_fraction[k];
    sum_.number_density[k] += s.number_density[k];
    coordination_sum_[k] += s.coordination[k] * s.number_density[k];
    sum_.momentum[k] += s.momentum[k];
    sum_.boundary_force_density[k] += s.boundary_force_density[k];
    for (std::size_t q = 0; q < 9; ++q) {
      sum_.kinetic_stress[k][q] += s.kinetic_stress[k][q];
      sum_.contact_stress[k][q] += s.contact_stress[k][q];
    }
  }
  ++samples_;
}

CgFields CgAverage::mean() const {
  CgFields f;
  if (samples_ == 0) return f;
  const std::size_t n = sum_.size();
  const double inv = 1.0 / static_cast<double>(samples_);
  allocate(f, n);
  std::vector<double> coordination(n);
  for (std::size_t k = 0; k < n; ++k) {
    f.density[k] = sum_.density[k] * inv;
    f.solid_fraction[k] = sum_.solid_fraction[k] * inv;
    f.number_density[k] = sum_.number_density[k] * inv;
    coordination[k] = coordination_sum_[k] * inv;
    f.momentum[k] = sum_.momentum[k] * inv;
    f.boundary_force_density[k] = sum_.boundary_force_density[k] * inv;
    for (std::size_t q = 0; q < 9; ++q) {
      f.kinetic_stress[k][q] = (sum_.kinetic_stress[k][q] + spread_[k][q]) * inv;
      f.contact_stress[k][q] = sum_.contact_stress[k][q] * inv;
    }
  }
  derive_velocity(f);
  finish(f, coordination);
  return f;
}

void CgAverage::clear() {
  samples_ = 0;
  sum_ = CgFields{};
  coordination_sum_.clear();
  spread_.clear();
}

}  // namespace mpdem
