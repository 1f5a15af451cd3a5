// What `mpdem check` prints about cohesion (check/cohesion_summary.hpp): the JKR pull-off and the
// overlap the neck holds to, and the bridge's volume, force at touching and rupture distance, for
// two spheres of the scene's largest radius, against the closed forms (1e-3: printed to 4 digits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "check/cohesion_summary.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
constexpr double kPi = std::numbers::pi;

// The number printed after `label` in the line, or NaN.
double number_after(const std::string& line, const std::string& label) {
  const auto at = line.find(label);
  return at == std::string::npos ? std::nan("") : std::strtod(line.c_str() + at + label.size(), nullptr);
}
}  // namespace

TEST(CohesionSummary, PullOffNeckAndBridge) {
  Scene s = test::make_scene(1e-6, 1.0);
  test::set_material(s, 2500.0, 1e7, 0.3);
  const double R = 1e-3, w = 0.05, gamma = 0.07, V = 1e-11;
  test::add_particle(s, 1, 0.5 * R, {0.0, 0.0, 0.0});
  test::add_particle(s, 2, R, {0.01, 0.0, 0.0});  // the largest radius sets the numbers
  s.model.params.contact.particle_particle.cohesion = "jkr";
  s.model.params.contact.particle_particle.law_keys["surface_energy"] = w;
  LiquidBridgeKeys k;
  k.surface_tension = gamma;
  k.volume = V;
  s.model.params.contact.liquid_bridge.defaults = k;
  const std::vector<std::string> lines = cohesion_summary_lines(s);
  for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  ASSERT_GE(lines.size(), 4u);
  const double r_star = 0.5 * R, E_star = 1e7 / (2.0 * (1.0 - 0.09));
  const double fc = 1.5 * kPi * w * r_star;
  const double delta_c = -0.75 * std::cbrt(kPi * kPi * w * w * r_star / (E_star * E_star));
  const double pull = number_after(lines[1], "pull-off ");
  const double neck = number_after(lines[1], "holds to an overlap of ");
  EXPECT_LT(std::abs(pull - fc) / fc, 1e-3) << lines[1];
  EXPECT_LT(std::abs(neck - delta_c) / -delta_c, 1e-3) << lines[1];
  EXPECT_NE(lines[2].find("liquid bridge (willett)"), std::string::npos);
  const double f0 = number_after(lines[2], "m^3, "), sc = number_after(lines[2], "gap of ");
  EXPECT_LT(std::abs(f0 - 2.0 * kPi * R * gamma) / (2.0 * kPi * R * gamma), 1e-3) << lines[2];  // harmonic radius R
  EXPECT_LT(std::abs(sc - std::cbrt(V)) / std::cbrt(V), 1e-3) << lines[2];
  const double reach = number_after(lines.back(), "reaches ");
  EXPECT_LT(std::abs(reach - std::cbrt(V)) / std::cbrt(V), 1e-3) << lines.back();  // the bridge reaches farther
}

TEST(CohesionSummary, NothingWithoutCohesion) {
  Scene s = test::make_scene(1e-6, 1.0);
  test::add_particle(s, 1, 1e-3, {0.0, 0.0, 0.0});
  EXPECT_TRUE(cohesion_summary_lines(s).empty());
}
