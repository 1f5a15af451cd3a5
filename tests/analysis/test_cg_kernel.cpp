// Coarse-graining kernels (analysis/cg_kernel.hpp) against quadrature: both kernels integrate to
// 1 in d = 1, 2, 3 (radial and Cartesian quadrature), the cutoffs and the closed-form constants,
// phi = 0 beyond the cutoff, and the line integral ∫_0^1 phi(|a + s b|) ds against brute-force
// Simpson quadrature for segments crossing, inside, tangent to and outside the cutoff sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "analysis/cg_kernel.hpp"

using namespace mpdem;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr CgKernel kKernels[] = {CgKernel::gaussian, CgKernel::lucy};
const char* name(CgKernel k) { return k == CgKernel::gaussian ? "gaussian" : "lucy"; }

// ∫ phi over R^d as ∫_0^cutoff S_d r^(d-1) phi(r) dr, composite Simpson with n panels. The
// support ends exactly at the cutoff, so the Gaussian's jump there costs nothing.
double radial_mass(const CgKernelFunction& phi, int n) {
  const double c = phi.cutoff(), h = c / n;
  const double surface[4] = {1.0, 2.0, 2.0 * kPi, 4.0 * kPi};  // S_d, "area" of the unit sphere in R^d
  const auto f = [&](double r) {
    const double rr = std::min(r, c * (1.0 - 1e-15));  // the closed end: the limit from inside
    return surface[phi.dims()] * std::pow(rr, phi.dims() - 1) * phi(rr * rr);
  };
  double sum = f(0.0) + f(c);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return sum * h / 3.0;
}

// ∫ phi over R^d on a Cartesian grid of n^d cells tiling [-c, c]^d (midpoint rule).
double cartesian_mass(const CgKernelFunction& phi, int n) {
  const double c = phi.cutoff(), h = 2.0 * c / n;
  const int d = phi.dims();
  const int ny = d >= 2 ? n : 1, nz = d >= 3 ? n : 1;
  double sum = 0.0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = -c + (i + 0.5) * h;
        const double y = d >= 2 ? -c + (j + 0.5) * h : 0.0, z = d >= 3 ? -c + (k + 0.5) * h : 0.0;
        sum += phi(x * x + y * y + z * z);
      }
  return sum * std::pow(h, d);
}

// Reference ∫_0^1 phi(|a + s b|) ds: composite Simpson (n panels, long double) on the pieces of
// [0, 1] between the crossings of the cutoff sphere (found by bisection, so the Gaussian's jump
// is at a piece end) and the closest approach (where Lucy's |.|^3 term has its kink).
double reference_line(const CgKernelFunction& phi, const Vec3& a, const Vec3& b, int n) {
  const auto r2 = [&](double s) { return norm2(a + s * b); };
  const double c2 = phi.cutoff() * phi.cutoff();
  std::vector<double> cuts{0.0, 1.0};
  const double b2 = norm2(b);
  const double smin = b2 > 0.0 ? std::clamp(-dot(a, b) / b2, 0.0, 1.0) : 0.0;
  cuts.push_back(smin);
  // r2 - c2 is monotone on [0, smin] and on [smin, 1]: bisect each for a sign change.
  for (const auto& [lo0, hi0] : {std::pair{0.0, smin}, std::pair{smin, 1.0}}) {
    double lo = lo0, hi = hi0;
    if ((r2(lo) < c2) == (r2(hi) < c2)) continue;
    const bool lo_inside = r2(lo) < c2;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if ((r2(mid) < c2) == lo_inside) lo = mid;
      else hi = mid;
    }
    cuts.push_back(0.5 * (lo + hi));
  }
  std::sort(cuts.begin(), cuts.end());
  long double total = 0.0L;
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    const double s0 = cuts[p], s1 = cuts[p + 1];
    if (s1 <= s0) continue;
    // A piece is wholly inside or outside the cutoff; at its ends take the limit from its side.
    if (!(r2(0.5 * (s0 + s1)) < c2)) continue;
    const double below = std::nextafter(c2, 0.0);
    const auto f = [&](double s) { return static_cast<long double>(phi(std::min(r2(s), below))); };
    const double h = (s1 - s0) / n;
    long double sum = f(s0) + f(s1);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0L : 2.0L) * f(s0 + i * h);
    total += sum * static_cast<long double>(h) / 3.0L;
  }
  return static_cast<double>(total);
}

Vec3 in_dims(const Vec3& v, int d) { return {v.x, d >= 2 ? v.y : 0.0, d >= 3 ? v.z : 0.0}; }
}  // namespace

TEST(CgKernel, CutoffsAndConstants) {
  EXPECT_DOUBLE_EQ(cg_cutoff(CgKernel::gaussian, 0.5), 1.5);  // 3w
  EXPECT_DOUBLE_EQ(cg_cutoff(CgKernel::lucy, 0.5), 1.0);      // c = 2w
  const double w = 0.7, c = 2.0 * w;
  // Lucy's A_d (phi(0) = A_d).
  EXPECT_NEAR(CgKernelFunction(CgKernel::lucy, w, 1).peak(), 5.0 / (4.0 * c), 1e-15);
  EXPECT_NEAR(CgKernelFunction(CgKernel::lucy, w, 2).peak(), 5.0 / (kPi * c * c), 1e-15);
  EXPECT_NEAR(CgKernelFunction(CgKernel::lucy, w, 3).peak(), 105.0 / (16.0 * kPi * c * c * c), 1e-15);
  // d = 0: phi = 1 (a plain volume average).
  EXPECT_EQ(CgKernelFunction(CgKernel::lucy, w, 0)(0.0), 1.0);
  EXPECT_EQ(CgKernelFunction(CgKernel::gaussian, w, 0)(0.0), 1.0);
  EXPECT_THROW(CgKernelFunction(CgKernel::lucy, 0.0, 3), std::invalid_argument);
  EXPECT_THROW(CgKernelFunction(CgKernel::lucy, 1.0, 4), std::invalid_argument);
}

TEST(CgKernel, ZeroBeyondCutoff) {
  for (CgKernel k : kKernels)
    for (int d = 1; d <= 3; ++d) {
      const CgKernelFunction phi(k, 0.3, d);
      const double c = phi.cutoff();
      EXPECT_EQ(phi(c * c), 0.0);
      EXPECT_EQ(phi(c * c * (1.0 + 1e-12)), 0.0);
      EXPECT_EQ(phi(4.0 * c * c), 0.0);
      const double inside = phi(c * c * (1.0 - 1e-9));
      if (k == CgKernel::gaussian) EXPECT_NEAR(inside / phi.peak(), std::exp(-4.5), 1e-8);  // the cut's jump
      else EXPECT_LT(inside / phi.peak(), 1e-25);  // Lucy: (1-q)^3 -> 0, C^2 at the cutoff
      EXPECT_GT(inside, 0.0);
    }
}

TEST(CgKernel, IntegratesToOne) {
  for (CgKernel k : kKernels)
    for (int d = 1; d <= 3; ++d) {
      const CgKernelFunction phi(k, 0.37, d);
      const double radial = radial_mass(phi, 20000);
      EXPECT_NEAR(radial, 1.0, 1e-6) << name(k) << " d=" << d;
      std::printf("[kernel] %-8s d=%d  radial quadrature: 1 %+.2e\n", name(k), d, radial - 1.0);
    }
  // Cartesian grids: for Lucy (smooth enough for the midpoint rule to converge fast) in d = 1..3,
  // for the Gaussian in 1-D where the cells tile [-3w, 3w] exactly (its jump is at a cell face).
  for (int d = 1; d <= 3; ++d) {
    const CgKernelFunction phi(CgKernel::lucy, 0.37, d);
    const double m = cartesian_mass(phi, d == 3 ? 300 : 2000);
    EXPECT_NEAR(m, 1.0, 1e-6) << "lucy d=" << d;
    std::printf("[kernel] lucy     d=%d  Cartesian midpoint: 1 %+.2e\n", d, m - 1.0);
  }
  const double m1 = cartesian_mass(CgKernelFunction(CgKernel::gaussian, 0.37, 1), 20000);
  EXPECT_NEAR(m1, 1.0, 1e-6);
  std::printf("[kernel] gaussian d=1  Cartesian midpoint: 1 %+.2e\n", m1 - 1.0);
}

TEST(CgKernel, LineIntegralMatchesQuadrature) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (CgKernel k : kKernels)
    for (int d = 1; d <= 3; ++d) {
      const CgKernelFunction phi(k, 0.25, d);
      const double c = phi.cutoff(), peak = phi.peak();
      struct Case {
        const char* what;
        Vec3 a, b;
      };
      std::vector<Case> cases = {
          {"through the centre", {-1.5 * c, 0, 0}, {3.0 * c, 0, 0}},
          {"inside", {0.2 * c, 0, 0}, {-0.5 * c, 0, 0}},
          {"one end inside", {0.3 * c, 0, 0}, {1.5 * c, 0, 0}},
          {"outside, pointing away", {1.2 * c, 0, 0}, {0.5 * c, 0, 0}},
          {"zero length", {0.4 * c, 0, 0}, {0, 0, 0}},
          {"very short", {0.4 * c, 0, 0}, {1e-12 * c, 0, 0}},
          {"short", {0.4 * c, 0, 0}, {0.01 * c, 0, 0}},
      };
      if (d >= 2) {
        cases.push_back({"crossing off-centre", {-1.2 * c, 0.5 * c, 0}, {2.5 * c, 0.1 * c, 0}});
        cases.push_back({"tangent", {-c, c, 0}, {2.0 * c, 0, 0}});
        cases.push_back({"near tangent", {-c, c * (1 - 1e-3), 0}, {2.0 * c, 0, 0}});
        cases.push_back({"missing the sphere", {-c, 1.1 * c, 0}, {2.0 * c, 0, 0}});
        cases.push_back({"crossing, close pass", {-c, 0.01 * c, 0}, {2.0 * c, 0, 0}});
      }
      for (int r = 0; r < 400; ++r) {  // random segments, lengths from 1e-3 c to 3 c
        const double len = c * std::pow(10.0, 1.5 * u(rng) - 1.0);
        const Vec3 dir{u(rng), u(rng), u(rng)};
        const Vec3 dd = in_dims(dir, d);
        if (norm(dd) < 1e-3) continue;
        cases.push_back({"random", in_dims(Vec3{u(rng), u(rng), u(rng)} * (1.1 * c), d), dd * (len / norm(dd))});
      }
      double worst_rel = 0.0, worst_small = 0.0;
      int zeros = 0;
      for (const Case& cs : cases) {
        const Vec3 a = in_dims(cs.a, d), b = in_dims(cs.b, d);
        const double got = phi.line_integral(a, b);
        const double ref = norm2(b) == 0.0 ? phi(norm2(a)) : reference_line(phi, a, b, 20000);
        // 1e-8 relative; an absolute floor of 1e-13 phi(0) for the values that vanish (tangent).
        EXPECT_NEAR(got, ref, 1e-8 * std::abs(ref) + 1e-13 * peak) << name(k) << " d=" << d << " " << cs.what;
        // Reversing the segment (start at a + b, go back) gives the same integral.
        EXPECT_NEAR(phi.line_integral(a + b, -b), got, 1e-12 * std::abs(got) + 1e-15 * peak)
            << name(k) << " " << cs.what;
        if (std::abs(ref) > 1e-6 * peak) worst_rel = std::max(worst_rel, std::abs(got - ref) / std::abs(ref));
        else if (ref != 0.0) worst_small = std::max(worst_small, std::abs(got - ref) / std::abs(ref));
        else zeros += got == 0.0 ? 1 : 0;
      }
      std::printf("[kernel] %-8s d=%d  line integral vs quadrature, %zu segments: max rel err %.1e, %.1e where "
                  "0 < |ref| < 1e-6 phi(0); %d zero in both\n",
                  name(k), d, cases.size(), worst_rel, worst_small, zeros);
    }
}

TEST(CgKernel, LineIntegralSpecialValues) {
  for (CgKernel k : kKernels) {
    const CgKernelFunction phi(k, 0.5, 3);
    const double c = phi.cutoff();
    // Outside: zero exactly. Tangent: the line touches the sphere at one point, zero.
    EXPECT_EQ(phi.line_integral({2 * c, 0, 0}, {0, c, 0}), 0.0);
    EXPECT_EQ(phi.line_integral({-c, c, 0}, {2 * c, 0, 0}), 0.0);
    // Zero length: phi at the point.
    EXPECT_EQ(phi.line_integral({0.3 * c, 0, 0}, {0, 0, 0}), phi(norm2(Vec3{0.3 * c, 0, 0})));
    // A segment through the centre from -R to +R, d = 1: the whole kernel mass / length.
    const CgKernelFunction p1(k, 0.5, 1);
    EXPECT_NEAR(p1.line_integral({-c, 0, 0}, {2 * c, 0, 0}), 1.0 / (2 * c), 1e-14 / c);
    EXPECT_NEAR(p1.line_integral({-3 * c, 0, 0}, {6 * c, 0, 0}), 1.0 / (6 * c), 1e-14 / c);
  }
}
