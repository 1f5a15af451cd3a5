// The health scan (integrate/health_scan.hpp): its energy sums against the closed forms, and
// without them ([checks] energy_ledger = false) the same counts of non-finite states and of
// particles outside the domain, with the energy sums left at zero.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "integrate/health_scan.hpp"

namespace mpdem {
namespace {

constexpr double kRho = 2500.0;  // kg/m^3

// 37 spheres on a line through the box [0, 1]^3 (more than one lane group of 8), moving and
// spinning, with charges; particle 5 has a NaN spin, 11 an infinite temperature, 20 lies beyond
// x = 1 and 29 below z = 0.
Particles line_of_spheres() {
  Particles p;
  for (int i = 0; i < 37; ++i) {
    const double s = 0.02 * i;
    p.add(i, 0, 1e-3 * (1.0 + 0.01 * i), kRho, {0.1 + s, 0.5, 0.2 + s}, {0.3 - s, 0.1 * s, -0.2});
    p.w.back() = {10.0 * s, -3.0, 1.0 + s};
    p.charge.back() = 1e-9 * (i - 18);
  }
  p.w[5].y = std::numeric_limits<double>::quiet_NaN();
  p.T[11] = std::numeric_limits<double>::infinity();
  p.x[20].x = 1.25;
  p.x[29].z = -0.5;
  return p;
}

DomainParams unit_box(bool periodic_x) {
  DomainParams d;
  d.bounded = true;
  d.min = {0.0, 0.0, 0.0};
  d.max = {1.0, 1.0, 1.0};
  d.periodic[0] = periodic_x;
  return d;
}

TEST(HealthScan, EnergiesMatchTheClosedFormsAndTheCountsNameEveryCase) {
  const Particles p = line_of_spheres();
  FieldParams f;
  f.gravity = {0.0, 0.0, -9.81};
  f.electric = {0.0, 0.0, 2e3};
  double kinetic = 0.0, potential = 0.0, electric = 0.0;  // J, over the finite particles' terms
  for (std::size_t i = 0; i < p.size(); ++i) {
    kinetic += 0.5 * p.mass[i] * norm2(p.v[i]);
    potential -= p.mass[i] * dot(f.gravity, p.x[i]);
    electric -= p.charge[i] * dot(f.electric, p.x[i]);
  }
  const HealthScan s = scan_state(p, f, unit_box(false));
  // Summed in another order (8 lanes): equal to round-off.
  EXPECT_NEAR(s.energy.kinetic, kinetic, 1e-12 * kinetic);
  EXPECT_NEAR(s.energy.potential, potential, 1e-12 * std::abs(potential));
  EXPECT_NEAR(s.electric, electric, 1e-12 * std::abs(electric) + 1e-300);
  EXPECT_TRUE(std::isnan(s.energy.rotational));  // particle 5's NaN spin reaches the sum
  EXPECT_EQ(s.nonfinite, 2u);                    // 5 and 11
  EXPECT_EQ(s.outside, 2u);                      // 20 and 29
  // A periodic x axis: 20 is not outside (it is wrapped at the next rebuild), 29 still is.
  EXPECT_EQ(scan_state(p, f, unit_box(true)).outside, 1u);
}

TEST(HealthScan, WithoutEnergiesTheCountsAreTheSameAndTheSumsZero) {
  const Particles p = line_of_spheres();
  FieldParams f;
  f.electric = {1e3, 0.0, 0.0};
  for (const bool periodic : {false, true}) {
    const DomainParams d = unit_box(periodic);
    const HealthScan with = scan_state(p, f, d, true);
    const HealthScan without = scan_state(p, f, d, false);
    EXPECT_EQ(without.nonfinite, with.nonfinite);
    EXPECT_EQ(without.outside, with.outside);
    EXPECT_EQ(without.energy.kinetic, 0.0);
    EXPECT_EQ(without.energy.rotational, 0.0);
    EXPECT_EQ(without.energy.potential, 0.0);
    EXPECT_EQ(without.electric, 0.0);
    EXPECT_GT(with.energy.kinetic, 0.0);  // so the comparison is not between zeros
  }
  // One range at a time, as the integrators call it: the same counts for every split.
  for (std::size_t cut = 0; cut <= p.size(); cut += 9) {
    std::array<double, kScanSums> acc{};
    scan_range(p, 0, cut, f, unit_box(false), acc, false);
    scan_range(p, cut, p.size(), f, unit_box(false), acc, false);
    EXPECT_EQ(acc[4], 2.0) << "cut at " << cut;
    EXPECT_EQ(acc[5], 2.0) << "cut at " << cut;
  }
}

}  // namespace
}  // namespace mpdem
