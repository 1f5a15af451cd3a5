// The Hertz normal law against its closed forms and the restitution calibration against an independent
// dimensional integration (physics.md section 5). Every tolerance is stated where it is used.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "physics/contact_geometry.hpp"
#include "physics/hertz.hpp"
#include "physics/restitution.hpp"
#include "support/hertz_oracle.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;

struct Sphere {
  double R, rho, E, nu;  // m, kg/m^3, Pa, -
  double mass() const { return 4.0 / 3.0 * kPi * R * R * R * rho; }
};

// Effective properties of a collision: sphere a against sphere b, or against a rigid wall.
struct Pair {
  double E_star, r_star, m_star;
};
Pair make_pair(const Sphere& a, const Sphere& b) {
  return {effective_modulus(a.E, a.nu, b.E, b.nu), effective_radius(a.R, b.R), effective_mass(a.mass(), b.mass())};
}
Pair make_wall(const Sphere& a) { return {effective_modulus_rigid(a.E, a.nu), a.R, a.mass()}; }

// Undamped closed forms (Hertz, e.g. Johnson, Contact Mechanics, 11.2):
// energy 1/2 m* v^2 = 2/5 K delta_max^(5/2), K = 4/3 E* sqrt(r*)
//   -> delta_max = (15 m* v^2 / (16 E* sqrt(r*)))^(2/5)
// t_c = 2 int_0^dmax ddelta / sqrt(v^2 - 4K/(5 m*) delta^(5/2))
//     = 2 (dmax/v) int_0^1 du / sqrt(1 - u^(5/2)) = (dmax/v) (4/5) B(2/5, 1/2)
//     = 2.943275184 dmax / v
//     = 2.868265699 (m*^2 / (E*^2 r* v))^(1/5)        [2.943275 * (15/16)^(2/5)]
//     = 3.218065460 (m* / K)^(2/5) v^(-1/5)           [2.943275 * (5/4)^(2/5)]
// (2.868265699 is the coefficient of the (m*^2/(E*^2 r* v))^(1/5) form, not of dmax/v.)
double hertz_delta_max(const Pair& p, double v) {
  return std::pow(15.0 * p.m_star * v * v / (16.0 * p.E_star * std::sqrt(p.r_star)), 0.4);
}
double hertz_duration(const Pair& p, double v) { return 2.943275184 * hertz_delta_max(p, v) / v; }

// One RK4 integration of a head-on collision along z, written independently of the library's
// calibration: the bodies are advanced in absolute coordinates, and the normal force comes from
// the hertz.hpp law (with or without its zero clamp). Starts at first touch with closing speed
// v; steps = undamped contact duration / dt. Returns the rebound restitution and, through the
// out-parameters, the peak overlap, peak force and contact duration.
struct CollisionResult {
  double e, max_overlap, max_force, duration;
};

CollisionResult collide(const Sphere& a, const Sphere* b, double v, double xi, bool clamp, int steps_per_contact) {
  const Pair p = b ? make_pair(a, *b) : make_wall(a);
  const double ma = a.mass(), mb = b ? b->mass() : 0.0;
  const double Rb = b ? b->R : 0.0;
  // State: z positions and z velocities of a (above) and b (below; a wall stays at z = 0).
  struct S {
    double za, va, zb, vb;
  };
  auto force_on_a = [&](const S& s) {  // N, along +z (n_ab = +z while a is above b)
    const PairGeometry g = pair_geometry({0, 0, s.za}, a.R, {0, 0, s.zb}, Rb);
    if (!g.touching) return 0.0;
    const double rate = (s.va - s.vb) * g.normal.z;  // d(delta)/dt, negative approaching
    if (clamp) return normal_contact_force(p.E_star, p.r_star, p.m_star, xi, g.overlap, rate).magnitude * g.normal.z;
    const double d = normal_damping_coefficient(xi, p.m_star, p.E_star, p.r_star, g.overlap);
    return (hertz_elastic_force(p.E_star, p.r_star, g.overlap) - d * rate) * g.normal.z;
  };
  auto deriv = [&](const S& s) {
    const double f = force_on_a(s);
    return S{s.va, f / ma, b ? s.vb : 0.0, b ? -f / mb : 0.0};
  };
  auto axpy = [](const S& s, double h, const S& k) {
    return S{s.za + h * k.za, s.va + h * k.va, s.zb + h * k.zb, s.vb + h * k.vb};
  };
  // Closing speed v split so the total momentum is zero (a wall takes nothing).
  const double va0 = b ? -v * mb / (ma + mb) : -v;
  const double vb0 = b ? v * ma / (ma + mb) : 0.0;
  S s{a.R + Rb, va0, 0.0, vb0};
  const double dt = hertz_duration(p, v) / steps_per_contact;
  CollisionResult r{0, 0, 0, 0};
  double t = 0.0, overlap_prev = 0.0;
  for (long n = 0; n < 200L * steps_per_contact; ++n) {
    const S k1 = deriv(s), k2 = deriv(axpy(s, 0.5 * dt, k1)), k3 = deriv(axpy(s, 0.5 * dt, k2)),
            k4 = deriv(axpy(s, dt, k3));
    s = S{s.za + dt / 6 * (k1.za + 2 * k2.za + 2 * k3.za + k4.za),
          s.va + dt / 6 * (k1.va + 2 * k2.va + 2 * k3.va + k4.va),
          s.zb + dt / 6 * (k1.zb + 2 * k2.zb + 2 * k3.zb + k4.zb),
          s.vb + dt / 6 * (k1.vb + 2 * k2.vb + 2 * k3.vb + k4.vb)};
    t += dt;
    const double overlap = a.R + Rb - (s.za - s.zb);
    r.max_overlap = std::max(r.max_overlap, overlap);
    r.max_force = std::max(r.max_force, std::abs(force_on_a(s)));
    if (overlap <= 0.0) {
      // Overlap closes linearly near separation: interpolate the crossing inside the step.
      r.duration = t - dt * (-overlap) / (overlap_prev - overlap);
      r.e = (s.va - s.vb) / v;
      return r;
    }
    overlap_prev = overlap;
  }
  ADD_FAILURE() << "collision did not end";
  return r;
}

const Sphere kGlass{1e-3, 2500.0, 7e10, 0.22};
const Sphere kSteel{5e-3, 7800.0, 2.1e11, 0.3};
const Sphere kRubber{2e-2, 1100.0, 1e7, 0.45};

}  // namespace

// ---------------------------------------------------------------------------------------------
// Hertz normal law
// ---------------------------------------------------------------------------------------------

TEST(Hertz, EffectivePropertiesMatchDefinitions) {
  // Identical spheres: E* = E / (2 (1 - nu^2)), r* = R/2, m* = m/2 (51)-(53); tolerance 1e-14 rel.
  EXPECT_NEAR(effective_modulus(7e10, 0.22, 7e10, 0.22), 7e10 / (2 * (1 - 0.22 * 0.22)), 1e-14 * 7e10);
  EXPECT_NEAR(effective_radius(2.0, 2.0), 1.0, 1e-15);
  EXPECT_NEAR(effective_mass(3.0, 6.0), 2.0, 1e-15);
  // A very stiff partner tends to the rigid-barrier value E/(1 - nu^2); tolerance 1e-9 rel.
  EXPECT_NEAR(effective_modulus(1e8, 0.3, 1e20, 0.2) / effective_modulus_rigid(1e8, 0.3), 1.0, 1e-9);
  // Stiffness is the derivative of the force; force the derivative of the energy.
  // Central differences, tolerance 1e-6 rel.
  const double E = 1e9, r = 0.01, d = 1e-4, h = 1e-9;
  const double dF = (hertz_elastic_force(E, r, d + h) - hertz_elastic_force(E, r, d - h)) / (2 * h);
  EXPECT_NEAR(dF / hertz_stiffness(E, r, d), 1.0, 1e-6);
  const double dU = (hertz_elastic_energy(E, r, d + h) - hertz_elastic_energy(E, r, d - h)) / (2 * h);
  EXPECT_NEAR(dU / hertz_elastic_force(E, r, d), 1.0, 1e-6);
}

TEST(Hertz, ContactDurationConstantsAgree) {
  // 2 int_0^1 (1 - u^(5/2))^(-1/2) du = (4/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10); 1e-9 abs.
  const double c = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  EXPECT_NEAR(c, 2.943275184, 1e-9);
  // The three closed forms of t_c agree for an arbitrary pair; tolerance 1e-8 rel.
  const Pair p = make_pair(kSteel, kRubber);
  const double v = 0.7;
  const double t1 = hertz_duration(p, v);
  const double t2 = 2.868265699 * std::pow(p.m_star * p.m_star / (p.E_star * p.E_star * p.r_star * v), 0.2);
  const double K = 4.0 / 3.0 * p.E_star * std::sqrt(p.r_star);
  const double t3 = 3.218065460 * std::pow(p.m_star / K, 0.4) * std::pow(v, -0.2);
  EXPECT_NEAR(t2 / t1, 1.0, 1e-8);
  EXPECT_NEAR(t3 / t1, 1.0, 1e-8);
}

TEST(Hertz, UndampedHeadOnCollisionMatchesClosedForms) {
  for (const double v : {0.05, 2.0}) {
    const CollisionResult r = collide(kGlass, &kGlass, v, 0.0, true, 100000);
    const Pair p = make_pair(kGlass, kGlass);
    const double dmax = hertz_delta_max(p, v);
    const double fmax = 4.0 / 3.0 * p.E_star * std::sqrt(p.r_star) * std::pow(dmax, 1.5);
    EXPECT_NEAR(r.max_overlap / dmax, 1.0, 1e-3) << "v=" << v;               // 0.1 %
    EXPECT_NEAR(r.max_force / fmax, 1.0, 1e-3) << "v=" << v;                 // 0.1 %
    EXPECT_NEAR(r.duration / hertz_duration(p, v), 1.0, 5e-3) << "v=" << v;  // 0.5 %
    EXPECT_NEAR(r.e, 1.0, 1e-6) << "v=" << v;                                // conservative law: rebound at full speed
    // Energy at the turning point is all elastic: 8/15 E* sqrt(r*) dmax^(5/2) = 1/2 m* v^2.
    EXPECT_NEAR(hertz_elastic_energy(p.E_star, p.r_star, dmax) / (0.5 * p.m_star * v * v), 1.0, 1e-12);
  }
}

TEST(Hertz, ForceIsNeverAttractive) {
  // Fast separation with strong damping: the damped force would be negative; it is clamped to
  // exactly zero and the dissipated power equals the released elastic force times the rate.
  const NormalForce f = normal_contact_force(1e9, 0.01, 0.1, 0.5, 1e-5, 10.0);
  EXPECT_TRUE(f.clamped);
  EXPECT_EQ(f.magnitude, 0.0);
  EXPECT_NEAR(f.dissipated_power, f.elastic * 10.0, 1e-12 * f.elastic * 10.0);
  // Approach: force = elastic + d* |rate|, dissipation d* rate^2 (1e-12 rel).
  const double rate = -0.3;
  const NormalForce g = normal_contact_force(1e9, 0.01, 0.1, 0.5, 1e-5, rate);
  const double d = normal_damping_coefficient(0.5, 0.1, 1e9, 0.01, 1e-5);
  EXPECT_FALSE(g.clamped);
  EXPECT_NEAR(g.magnitude, g.elastic - d * rate, 1e-12 * g.magnitude);
  EXPECT_NEAR(g.dissipated_power, d * rate * rate, 1e-12 * d * rate * rate);
  // (50): d* = 2 xi sqrt(2 m* E* sqrt(r* delta)); 1e-12 rel.
  EXPECT_NEAR(d, 2 * 0.5 * std::sqrt(2 * 0.1 * 1e9 * std::sqrt(0.01 * 1e-5)), 1e-12 * d);
  EXPECT_EQ(normal_contact_force(1e9, 0.01, 0.1, 0.5, 0.0, -1.0).magnitude, 0.0);  // no contact
}

// ---------------------------------------------------------------------------------------------
// Restitution calibration (Departure of section 5)
// ---------------------------------------------------------------------------------------------

TEST(Restitution, CalibratedDampingGivesRequestedRestitutionAtAnySpeedSizeMaterial) {
  // Three collision kinds with different radii and materials, including a rigid wall.
  struct Case {
    const Sphere* a;
    const Sphere* b;  // nullptr: rigid barrier
  };
  const Case cases[] = {{&kGlass, &kGlass}, {&kSteel, &kRubber}, {&kSteel, nullptr}};
  for (const double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
    const double xi = damping_ratio_for_restitution(e);
    for (const Case& c : cases)
      for (const double v : {0.01, 0.1, 1.0, 10.0}) {
        const CollisionResult r = collide(*c.a, c.b, v, xi, true, 20000);
        EXPECT_NEAR(r.e, e, 0.002) << "e=" << e << " v=" << v << " wall=" << (c.b == nullptr);
      }
  }
}

TEST(Restitution, MappingAccurateTo1e5) {
  // Finer independent integration (step = t_c / 2e5, error ~1e-7 here) at one configuration:
  // the calibrated xi reproduces e to 2e-5 (the calibration claims ~1e-10).
  for (int k = 1; k <= 9; ++k) {
    const double e = 0.1 * k;
    const CollisionResult r = collide(kSteel, &kGlass, 0.5, damping_ratio_for_restitution(e), true, 200000);
    EXPECT_NEAR(r.e, e, 2e-5) << "e=" << e;
  }
  EXPECT_EQ(damping_ratio_for_restitution(1.0), 0.0);
  EXPECT_EQ(restitution_for_damping_ratio(0.0), 1.0);
  EXPECT_THROW(damping_ratio_for_restitution(0.0), std::invalid_argument);
  EXPECT_THROW(damping_ratio_for_restitution(1.5), std::invalid_argument);
}

TEST(Restitution, MappingIsMonotone) {
  // More damping, less rebound: xi(e) strictly decreasing on a 0.05 grid.
  double prev = damping_ratio_for_restitution(0.05);
  for (int k = 2; k <= 20; ++k) {
    const double xi = damping_ratio_for_restitution(0.05 * k);
    EXPECT_LT(xi, prev) << "e=" << 0.05 * k;
    prev = xi;
  }
}

TEST(Restitution, ThesisFormulaMissesTheRequestedRestitution) {
  // Why the Departure exists: (55) was derived for a linear spring-dashpot. Fed into the
  // nonlinear damping (50) for e = 0.5:
  //  - without the zero clamp the rebound is clearly LOWER than 0.5 (the damper pulls the
  //    spheres back together at the end of contact);
  //  - with the zero clamp the spec requires, the rebound misses 0.5 as well (it lands above:
  //    the clamp removes that final pull), by more than 0.01.
  // The calibrated xi hits 0.5 within 0.002 in both senses of the comparison.
  const double e = 0.5;
  const double xi55 = thesis_damping_ratio(e);
  EXPECT_NEAR(xi55, std::log(2.0) / std::sqrt(kPi * kPi + std::log(2.0) * std::log(2.0)), 1e-15);
  const CollisionResult unclamped = collide(kGlass, &kGlass, 1.0, xi55, false, 20000);
  EXPECT_LT(unclamped.e, e - 0.01);
  const CollisionResult clamped = collide(kGlass, &kGlass, 1.0, xi55, true, 20000);
  EXPECT_GT(std::abs(clamped.e - e), 0.01);
  const CollisionResult calibrated = collide(kGlass, &kGlass, 1.0, damping_ratio_for_restitution(e), true, 20000);
  EXPECT_NEAR(calibrated.e, e, 0.002);
}
