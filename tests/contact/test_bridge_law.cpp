// Capillary liquid bridges (contact/bridges/): Willett's closed form against the paper's
// acceptance table and its equal-sphere form, Rabinovich's against its own terms, the energies
// against their forces, the viscous term, the liquid-fraction volume rule, and the contact
// table's resolution per pair of materials from [liquid_bridge] and [[contact.pair]] entries.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "contact/bridges/bridge_law.hpp"
#include "contact/contact_table.hpp"
#include "scene/scene_reader.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kPi = std::numbers::pi;

// Willett et al. (2000) acceptance case: equal spheres R = 2.381 mm, gamma = 20.6 mN/m,
// theta = 0, V = 74.2 nL.
constexpr double kR = 2.381e-3, kGamma = 20.6e-3, kV = 74.2e-12;

BridgeLaw willett(double volume, double theta = 0.0) {
  BridgeLaw b;
  b.model = BridgeModel::willett;
  b.surface_tension = kGamma;
  b.contact_angle = theta;
  b.volume = volume;
  b.min_gap = 1e-3;
  return b;
}

// r* and 1 / (R_i + R_j) of two spheres.
double r_star(double a, double b) { return a * b / (a + b); }
double inv_reach(double a, double b) { return 1.0 / (a + b); }

TEST(BridgeLaw, WillettConstantIsTheDiscriminantRoot) {
  EXPECT_NEAR(willett::kRootD, std::sqrt(4.0 * 2.5 - 1.05 * 1.05), 1e-15);
}

TEST(BridgeLaw, WillettAcceptanceTableOfEqualSpheres) {
  const BridgeLaw b = willett(kV);
  const std::array<double, 5> gaps{0.0, 0.05e-3, 0.1e-3, 0.2e-3, 0.3e-3};       // m
  const std::array<double, 5> printed{0.3082, 0.2057, 0.1286, 0.0571, 0.0308};  // mN, the paper's table
  for (std::size_t k = 0; k < gaps.size(); ++k) {
    const double S = gaps[k];
    // The equal-sphere form: 2 pi R gamma cos(theta) / (1 + 2.1 s + 10 s^2), s = (S/2) sqrt(R/V).
    const double s = 0.5 * S * std::sqrt(kR / kV);
    const double expected = 2.0 * kPi * kR * kGamma / (1.0 + 2.1 * s + 10.0 * s * s);
    const BridgeForce f = bridge_force(b, r_star(kR, kR), inv_reach(kR, kR), -S, 0.0);
    std::printf("S = %.2f mm: F = %.6f mN (paper %.4f)\n", S * 1e3, -f.fn * 1e3, printed[k]);
    EXPECT_NEAR(-f.fn, expected, 1e-12 * expected);
    EXPECT_NEAR(-f.fn * 1e3, printed[k], 5e-4 * printed[k]);
    EXPECT_EQ(f.damping, 0.0);
  }
  const double sc = bridge_rupture_distance(b, r_star(kR, kR), inv_reach(kR, kR));
  std::printf("rupture distance %.6f mm (paper 0.420)\n", sc * 1e3);
  EXPECT_NEAR(sc, std::cbrt(kV), 1e-15);  // (1 + theta/2) V^(1/3), theta = 0
  EXPECT_NEAR(sc * 1e3, 0.420, 0.0005);   // printed to 3 decimals: within half of the last digit
}

// Unequal spheres take the harmonic mean radius R = 2 R_i R_j / (R_i + R_j); a sphere on a plane
// (a barrier: r* = R, kappa = 0) takes 2 R, so that F(0) = 4 pi R gamma cos(theta).
TEST(BridgeLaw, WillettUnequalSpheresAndBarrier) {
  const double theta = 0.5, a = 1e-3, c = 3e-3;
  const BridgeLaw b = willett(2e-11, theta);
  const double R = 2.0 * a * c / (a + c);
  for (const double S : {0.0, 2e-5, 1e-4, 2.5e-4}) {
    const double x = S * std::sqrt(R / b.volume);
    const double expected = 2.0 * kPi * R * kGamma * std::cos(theta) / (1.0 + 1.05 * x + 2.5 * x * x);
    const double fn = bridge_force(b, r_star(a, c), inv_reach(a, c), -S, 0.0).fn;
    EXPECT_NEAR(-fn, expected, 1e-12 * expected) << S;
  }
  const double f0 = -bridge_force(b, a, 0.0, 0.0, 0.0).fn;
  EXPECT_NEAR(f0, 4.0 * kPi * a * kGamma * std::cos(theta), 1e-12 * f0);
  // In contact the force stays at its S = 0 value.
  EXPECT_EQ(bridge_force(b, a, 0.0, 1e-6, 0.0).fn, -f0);
}

// d(energy)/d(overlap) = fn for both models (the laws' convention, f = dU/d(delta)), apart and in
// contact (central differences).
TEST(BridgeLaw, EnergyDerivativeIsTheForce) {
  for (const BridgeModel model : {BridgeModel::willett, BridgeModel::rabinovich})
    for (const double theta : {0.0, 0.7}) {
      BridgeLaw b = willett(kV, theta);
      b.model = model;
      const double rs = r_star(kR, 2.0 * kR), k = inv_reach(kR, 2.0 * kR);
      const double sc = bridge_rupture_distance(b, rs, k);
      EXPECT_EQ(bridge_force(b, rs, k, 0.0, 0.0).energy, 0.0);
      for (const double overlap : {2e-6, -0.01 * sc, -0.2 * sc, -0.5 * sc, -sc}) {
        const double h = 1e-4 * sc;
        const double up = bridge_force(b, rs, k, overlap + h, 0.0).energy;
        const double down = bridge_force(b, rs, k, overlap - h, 0.0).energy;
        const double fn = bridge_force(b, rs, k, overlap, 0.0).fn;
        EXPECT_NEAR((up - down) / (2.0 * h), fn, 1e-6 * std::abs(fn)) << static_cast<int>(model) << " " << overlap;
        if (overlap < 0.0) {
          EXPECT_GT(bridge_force(b, rs, k, overlap, 0.0).energy, 0.0);
        }
      }
    }
}

// Rabinovich et al. (2005): at S = 0 the pressure term is Willett's 2 pi R gamma cos(theta) and
// the contact line adds 2 pi R gamma sin(a0) sin(theta + a0), a0 = (2V / (pi R^3))^(1/4); the
// force falls with the gap; the terms at a gap from their own formulas.
TEST(BridgeLaw, RabinovichTermsAndFall) {
  const double theta = 0.3;
  BridgeLaw b = willett(kV, theta);
  b.model = BridgeModel::rabinovich;
  const double rs = r_star(kR, kR), k = inv_reach(kR, kR), R = 2.0 * rs;
  const double w0 = -bridge_force(willett(kV, theta), rs, k, 0.0, 0.0).fn;
  const double a0 = std::pow(2.0 * kV / (kPi * R * R * R), 0.25);
  const double line0 = 2.0 * kPi * R * kGamma * std::sin(a0) * std::sin(theta + a0);
  const double f0 = -bridge_force(b, rs, k, 0.0, 0.0).fn;
  std::printf("Rabinovich F(0) = %.6f mN = Willett %.6f + contact line %.6f (alpha_0 = %.4f rad)\n", f0 * 1e3, w0 * 1e3,
              line0 * 1e3, a0);
  EXPECT_NEAR(f0, w0 + line0, 1e-12 * f0);
  const double sc = bridge_rupture_distance(b, rs, k);
  double last = f0;
  for (int i = 1; i <= 20; ++i) {
    const double S = sc * i / 20.0;
    const double d_sp = 0.5 * S * (-1.0 + std::sqrt(1.0 + 2.0 * kV / (kPi * R * S * S)));
    const double alpha = std::sqrt(2.0 * d_sp / R);
    const double expected = 2.0 * kPi * R * kGamma * std::cos(theta) / (1.0 + S / (2.0 * d_sp)) +
                            2.0 * kPi * R * kGamma * std::sin(alpha) * std::sin(theta + alpha);
    const double f = -bridge_force(b, rs, k, -S, 0.0).fn;
    EXPECT_NEAR(f, expected, 1e-10 * expected) << S;
    EXPECT_LT(f, last) << S;
    last = f;
  }
}

// The quadrature of Rabinovich's energy against composite Simpson over the gap (2e5 panels):
// within 1e-10 of the energy, for wetting and partly wetting bridges and a small volume (a long
// gap range against the bridge's own length sqrt(2V / (pi R))).
TEST(BridgeLaw, RabinovichEnergyQuadrature) {
  for (const double volume : {kV, 1e-6 * kR * kR * kR})
    for (const double theta : {0.0, 1.0, kPi / 2.0}) {
      BridgeLaw b = willett(volume, theta);
      b.model = BridgeModel::rabinovich;
      const double rs = r_star(kR, kR), k = inv_reach(kR, kR);
      const double S = bridge_rupture_distance(b, rs, k);
      const int n = 200000;
      const double h = S / n;
      double sum = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double f = -bridge_force(b, rs, k, -i * h, 0.0).fn;
        sum += f * (i == 0 || i == n ? 1.0 : i % 2 == 1 ? 4.0 : 2.0);
      }
      const double reference = sum * h / 3.0, energy = bridge_force(b, rs, k, -S, 0.0).energy;
      std::printf("V = %.3e m^3, theta = %.3f: energy %.12e J, Simpson %.12e J\n", volume, theta, energy, reference);
      EXPECT_NEAR(energy, reference, 1e-10 * reference);
    }
}

// F_v = -6 pi mu r*^2 v_n / max(S, min_gap r*): repulsive approaching, attractive separating,
// dissipating -F_v v_n >= 0 either way, at S_min in contact.
TEST(BridgeLaw, ViscousTermSignAndPower) {
  BridgeLaw b = willett(kV);
  b.viscosity = 1e-3;
  const double rs = r_star(kR, kR), k = inv_reach(kR, kR), S = 1e-4;
  const double capillary = bridge_force(willett(kV), rs, k, -S, 0.0).fn;
  for (const double vn : {-0.1, 0.1}) {
    const BridgeForce f = bridge_force(b, rs, k, -S, vn);
    const double fv = -6.0 * kPi * 1e-3 * rs * rs * vn / S;
    EXPECT_NEAR(f.fn - capillary, fv, 1e-12 * std::abs(fv));
    EXPECT_EQ(vn<0.0, fv> 0.0);
    EXPECT_NEAR(f.damping, -fv * vn, 1e-12 * std::abs(fv * vn));
    EXPECT_GT(f.damping, 0.0);
    // In contact (and at gaps below it) the gap is min_gap r*.
    const double fc = bridge_force(b, rs, k, 1e-7, vn).fn - bridge_force(willett(kV), rs, k, 1e-7, 0.0).fn;
    EXPECT_NEAR(fc, -6.0 * kPi * 1e-3 * rs * vn / 1e-3, 1e-12 * std::abs(fc));
  }
}

// V = phi (V_i + V_j) / 2 for two particles, phi V_i / 2 on a barrier; the largest rupture
// distance for radii <= r_max is the one of two spheres of r_max.
TEST(BridgeLaw, LiquidFractionRuleAndReach) {
  BridgeLaw b = willett(0.0, 0.4);
  b.liquid_fraction = 0.01;
  const double a = 1e-3, c = 2.5e-3;
  const double pair = 0.01 * (4.0 / 3.0 * kPi * (a * a * a + c * c * c)) / 2.0;
  EXPECT_NEAR(bridge_volume(b, r_star(a, c), inv_reach(a, c)), pair, 1e-12 * pair);
  const double wall = 0.01 * (4.0 / 3.0 * kPi * c * c * c) / 2.0;
  EXPECT_NEAR(bridge_volume(b, c, 0.0), wall, 1e-14 * wall);
  EXPECT_NEAR(bridge_rupture_distance(b, c, 0.0), 1.2 * std::cbrt(wall), 1e-14);
  EXPECT_NEAR(bridge_reach(b, c, false), bridge_rupture_distance(b, r_star(c, c), inv_reach(c, c)), 1e-15);
  EXPECT_NEAR(bridge_reach(b, c, true), bridge_rupture_distance(b, c, 0.0), 1e-15);
  EXPECT_GT(bridge_reach(b, c, false), bridge_rupture_distance(b, r_star(a, c), inv_reach(a, c)));
  b.volume = 3e-11;  // a volume wins over the fraction
  EXPECT_EQ(bridge_volume(b, r_star(a, c), inv_reach(a, c)), 3e-11);
  EXPECT_NEAR(bridge_reach(b, c, true), 1.2 * std::cbrt(3e-11), 1e-15);
  EXPECT_EQ(bridge_reach(BridgeLaw{}, c, false), 0.0);
  EXPECT_EQ(bridge_force(BridgeLaw{}, r_star(a, c), inv_reach(a, c), -1e-5, -1.0).fn, 0.0);
}

// The contact table resolves [liquid_bridge] and the entries' liquid_bridge tables per pair of
// materials and contact kind.
TEST(BridgeLaw, ContactTableResolvesPairs) {
  TempDir d("mpdem_bridge");
  const std::string head = "[time]\nduration = 1.0\ndt = 1e-5\n"
                           "[[material]]\nname = \"glass\"\n[[material]]\nname = \"steel\"\n"
                           "[[material]]\nname = \"wood\"\n";
  const std::string scene_text =
      head + "[liquid_bridge]\nsurface_tension = 0.07\nvolume = 1e-12\ncontact_angle = 30\nbarriers = false\n"
             "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\n"
             "liquid_bridge = { model = \"rabinovich\", liquid_fraction = 0.02, viscosity = 1e-3, min_gap = 0.01 }\n"
             "[[contact.pair]]\nmaterials = [\"wood\", \"wood\"]\nliquid_bridge = { model = \"none\" }\n"
             "[[contact.pair]]\nmaterials = [\"steel\", \"steel\"]\nkind = \"particle_barrier\"\n"
             "[contact.pair.liquid_bridge]\nsurface_tension = 0.02\n";
  const Scene s = parse_scene_file(d.write("scene.toml", scene_text));
  ContactTable t;
  t.build(s.model);
  const BridgeLaw& gg = t.particle_bridge(0, 0);
  EXPECT_EQ(gg.model, BridgeModel::willett);
  EXPECT_EQ(gg.surface_tension, 0.07);
  EXPECT_NEAR(gg.contact_angle, kPi / 6.0, 1e-15);
  EXPECT_EQ(gg.volume, 1e-12);
  EXPECT_EQ(gg.min_gap, LiquidBridgeKeys::kMinGap);
  for (const auto& [a, b] : {std::pair<std::size_t, std::size_t>{0, 1}, {1, 0}}) {  // symmetric, both kinds
    for (const BridgeLaw* l : {&t.particle_bridge(a, b), &t.barrier_bridge(a, b)}) {
      EXPECT_EQ(l->model, BridgeModel::rabinovich);
      EXPECT_EQ(l->volume, 0.0);  // the fraction replaces the default volume
      EXPECT_EQ(l->liquid_fraction, 0.02);
      EXPECT_EQ(l->viscosity, 1e-3);
      EXPECT_EQ(l->min_gap, 0.01);
      EXPECT_EQ(l->surface_tension, 0.07);
    }
  }
  EXPECT_EQ(t.particle_bridge(2, 2).model, BridgeModel::none);
  EXPECT_EQ(t.particle_bridge(0, 2).model, BridgeModel::willett);
  EXPECT_EQ(t.barrier_bridge(0, 0).model, BridgeModel::none);  // barriers = false
  EXPECT_EQ(t.barrier_bridge(1, 1).model, BridgeModel::willett);
  EXPECT_EQ(t.barrier_bridge(1, 1).surface_tension, 0.02);
  EXPECT_EQ(t.particle_bridge(1, 1).surface_tension, 0.07);  // the entry is for barriers only
  EXPECT_TRUE(t.any_particle_bridges() && t.any_barrier_bridges());
  EXPECT_EQ(t.particle_bridges()[0 * 3 + 1].model, BridgeModel::rabinovich);
  EXPECT_EQ(t.barrier_bridges()[1 * 3 + 1].surface_tension, 0.02);
  // The reach: the largest over the pairs, the glass-steel fraction's at r_max = 1 mm.
  const double r = 1e-3, frac = 1.0 + kPi / 12.0;
  const double from_fraction = frac * std::cbrt(0.02 * (2.0 / 3.0) * kPi * 2.0 * r * r * r);
  EXPECT_NEAR(t.bridge_reach(r), std::max(frac * std::cbrt(1e-12), from_fraction), 1e-15);
  EXPECT_NEAR(t.barrier_bridge_reach(r),
              std::max(frac * std::cbrt(1e-12), frac * std::cbrt(0.02 * (2.0 / 3.0) * kPi * r * r * r)), 1e-15);

  // Without bridges: none anywhere, reach 0.
  ContactTable none;
  none.build(parse_scene_file(d.write("plain.toml", head)).model);
  EXPECT_FALSE(none.any_particle_bridges() || none.any_barrier_bridges());
  EXPECT_EQ(none.bridge_reach(r), 0.0);
  EXPECT_EQ(none.barrier_bridge_reach(r), 0.0);
  // An entry alone turns them on for its pair (the default model, Willett).
  ContactTable one;
  one.build(parse_scene_file(d.write("one.toml", head + "[[contact.pair]]\nmaterials = [\"wood\", \"glass\"]\n"
                                                        "liquid_bridge = { surface_tension = 0.05, volume = 2e-12 }\n"))
                .model);
  EXPECT_EQ(one.particle_bridge(2, 0).model, BridgeModel::willett);
  EXPECT_EQ(one.barrier_bridge(0, 2).volume, 2e-12);
  EXPECT_EQ(one.particle_bridge(0, 0).model, BridgeModel::none);
}

}  // namespace
