// [contact] of the scene file (scene/contact_reader.cpp): the law keys, [[contact.pair]] entries,
// [liquid_bridge] and the entries' liquid_bridge tables (scene/liquid_bridge_reader.cpp), and
// messages naming file, line and key for bad values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "physics/restitution.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

const std::string kHead = "[time]\nduration = 1.0\ndt = 1e-5\n"                                // 1-3
                          "[[material]]\nname = \"glass\"\n[[material]]\nname = \"steel\"\n";  // 4-7

TEST(ContactReader, LawsAndPairEntries) {
  TempDir d("mpdem_contact");
  const fs::path scene = d.write(
      "scene.toml",
      kHead + "[contact.particle_particle]\nrestitution = 0.7\n"
              "[contact.particle_barrier]\nlaw = \"linear\"\nstiffness_normal = 1e4\n"
              "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\nmu_static = 0.3\nmu_dynamic = 0.2\n"
              "[[contact.pair]]\nmaterials = [\"steel\", \"steel\"]\nkind = \"particle_particle\"\nlaw = \"linear\"\n"
              "stiffness_normal = 2e4\nstiffness_tangential = 5e3\nrestitution = 0.5\n"
              "tangential_spring = \"incremental\"\ntangential_damping = 0.0\n");
  const Scene s = parse_scene_file(scene);
  const ContactParams& c = s.model.params.contact;
  EXPECT_EQ(c.particle_particle.law, "hertz");
  EXPECT_EQ(*c.particle_particle.restitution, 0.7);
  EXPECT_EQ(c.particle_barrier.law, "linear");
  EXPECT_EQ(c.particle_barrier.law_keys.at("stiffness_normal"), 1e4);
  ASSERT_EQ(c.pairs.size(), 2u);
  EXPECT_EQ(c.pairs[0].material_a, "glass");
  EXPECT_EQ(c.pairs[0].material_b, "steel");
  EXPECT_TRUE(c.pairs[0].particle_particle && c.pairs[0].particle_barrier);
  EXPECT_EQ(*c.pairs[0].mu_static, 0.3);
  EXPECT_FALSE(c.pairs[0].restitution.has_value());
  EXPECT_TRUE(c.pairs[1].particle_particle && !c.pairs[1].particle_barrier);
  EXPECT_EQ(*c.pairs[1].law, "linear");
  EXPECT_EQ(c.pairs[1].law_keys.at("stiffness_tangential"), 5e3);
  // tangential_damping left out: unset, so the table takes xi_n; given: as written.
  EXPECT_FALSE(c.particle_particle.tangential_damping.has_value());
  EXPECT_EQ(c.particle_particle.tangential_spring, TangentialSpring::Total);
  EXPECT_EQ(*c.pairs[1].tangential_spring, TangentialSpring::Incremental);
  EXPECT_EQ(*c.pairs[1].tangential_damping, 0.0);
  EXPECT_FALSE(c.pairs[0].tangential_spring.has_value());
}

TEST(ContactReader, BadValuesNameFileLineAndKey) {
  struct Case {
    std::string toml;
    int line;
    std::string key, expect;
  };
  const std::vector<Case> cases = {
      {"[contact.particle_particle]\nlaw = \"hooke\"\n", 9, "contact.particle_particle.law",
       "expected \"hertz\" or \"linear\""},
      {"[contact.particle_particle]\nlaw = \"linear\"\n", 9, "contact.particle_particle.law", "needs stiffness_normal"},
      {"[[contact.pair]]\nmaterials = [\"glass\", \"wood\"]\n", 9, "contact.pair.materials", "unknown material 'wood'"},
      {"[[contact.pair]]\nmaterials = [\"glass\"]\n", 9, "contact.pair.materials", "expected an array of 2 strings"},
      {"[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\nmu_dynamic = 0.9\n", 10, "contact.pair.mu_dynamic",
       "expected mu_dynamic <= mu_static"},
      {"[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\nkind = \"both\"\n", 10, "contact.pair.kind",
       "expected \"particle_particle\" or \"particle_barrier\""},
      {"[contact.particle_barrier]\nrestitution = 1.2\n", 9, "contact.particle_barrier.restitution",
       "expected a number in [0.001, 1], got 1.2"},
      {"[contact.particle_barrier]\ntangential_spring = \"history\"\n", 9, "contact.particle_barrier.tangential_spring",
       "expected \"total\" or \"incremental\", got \"history\""},
      {"[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\ntangential_spring = 1\n", 10,
       "contact.pair.tangential_spring", "expected a string"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.toml);
    TempDir d("mpdem_contact");
    const fs::path scene = d.write("scene.toml", kHead + c.toml);
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    expect_contains(msg, {scene.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ", c.expect});
  }
}

// A restitution below the calibration's smallest (kMinRestitution, physics/restitution.hpp) is
// refused at the reader, saying which value is the smallest and why, for the default tables and
// [[contact.pair]] entries alike; the smallest itself is accepted and calibrates.
TEST(ContactReader, RestitutionBelowTheCalibrationsSmallestIsRefused) {
  ASSERT_EQ(kMinRestitution, 1e-3);  // the messages below name it
  struct Case {
    std::string toml;
    int line;
    std::string key, got;
  };
  const std::vector<Case> cases = {
      {"[contact.particle_particle]\nrestitution = 0\n", 9, "contact.particle_particle.restitution", "got 0"},
      {"[contact.particle_barrier]\nrestitution = 0.0009\n", 9, "contact.particle_barrier.restitution", "got 9e-04"},
      {"[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\nrestitution = 1e-4\n", 10, "contact.pair.restitution",
       "got 1e-04"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.toml);
    TempDir d("mpdem_contact");
    const fs::path scene = d.write("scene.toml", kHead + c.toml);
    const std::string at = ':' + std::to_string(c.line) + ": '" + c.key + "': ", where = scene.string() + at;
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    EXPECT_EQ(msg.rfind(where, 0), 0u) << msg;
    expect_contains(msg, {"expected a number in [0.001, 1], " + c.got, "accepts e >= 0.001",
                          "no finite damping ratio gives e = 0", "give damping_ratio instead"});
    const CommandResult r = run_mpdem("check scene.toml", d.path);  // the command: exit status 2
    EXPECT_EQ(r.status, 2) << r.err;
    expect_contains(r.err, {"scene.toml" + at});
  }
  TempDir d("mpdem_contact");
  const fs::path scene = d.write("scene.toml",
                                 kHead + "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\nrestitution = 0.001\n");
  EXPECT_EQ(*parse_scene_file(scene).model.params.contact.pairs.at(0).restitution, 1e-3);
  const double xi = damping_ratio_for_restitution(kMinRestitution);
  std::printf("xi_n(e = %g) = %.6f\n", kMinRestitution, xi);
  EXPECT_TRUE(std::isfinite(xi) && xi > 0.0);
  EXPECT_NEAR(restitution_for_damping_ratio(xi), kMinRestitution, 1e-10);
}

TEST(LiquidBridgeKeys, SectionAndPairTables) {
  TempDir d("mpdem_bridge_keys");
  const fs::path scene = d.write(
      "scene.toml", kHead + "[liquid_bridge]\nmodel = \"rabinovich\"\nsurface_tension = 0.072\ncontact_angle = 45\n"
                            "liquid_fraction = 0.01\nviscosity = 1e-3\nmin_gap = 0.01\nbarriers = false\n"
                            "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\n"
                            "liquid_bridge = { model = \"willett\", volume = 1e-12 }\n"
                            "[[contact.pair]]\nmaterials = [\"steel\", \"steel\"]\n"
                            "[contact.pair.liquid_bridge]\nmodel = \"none\"\n");
  const ContactParams& c = parse_scene_file(scene).model.params.contact;
  ASSERT_TRUE(c.liquid_bridge.defaults.has_value());
  const LiquidBridgeKeys& k = *c.liquid_bridge.defaults;
  EXPECT_EQ(*k.model, "rabinovich");
  EXPECT_EQ(*k.surface_tension, 0.072);
  EXPECT_NEAR(*k.contact_angle, std::numbers::pi / 4.0, 1e-15);  // degrees in, radians kept
  EXPECT_EQ(*k.liquid_fraction, 0.01);
  EXPECT_FALSE(k.volume.has_value());
  EXPECT_EQ(*k.viscosity, 1e-3);
  EXPECT_EQ(*k.min_gap, 0.01);
  EXPECT_FALSE(c.liquid_bridge.barriers);
  ASSERT_EQ(c.pairs.size(), 2u);
  ASSERT_TRUE(c.pairs[0].liquid_bridge.has_value());
  EXPECT_EQ(*c.pairs[0].liquid_bridge->model, "willett");
  EXPECT_EQ(*c.pairs[0].liquid_bridge->volume, 1e-12);
  EXPECT_FALSE(c.pairs[0].liquid_bridge->surface_tension.has_value());  // the default's, resolved in the table
  EXPECT_EQ(*c.pairs[1].liquid_bridge->model, "none");
  // Without [liquid_bridge]: no defaults, barriers default true.
  const ContactParams plain = parse_scene_file(d.write("plain.toml", kHead)).model.params.contact;
  EXPECT_FALSE(plain.liquid_bridge.defaults.has_value());
  EXPECT_TRUE(plain.liquid_bridge.barriers);
  EXPECT_FALSE(plain.pairs.size());
}

TEST(LiquidBridgeKeys, BadValuesNameFileLineAndKey) {
  struct Case {
    std::string toml;
    int line;
    std::string key, expect;
  };
  const std::string ok = "surface_tension = 0.07\nvolume = 1e-12\n";  // 2 lines
  const std::string pair = "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\n";
  const std::vector<Case> cases = {
      {"[liquid_bridge]\nsurface_tension = 0\nvolume = 1e-12\n", 9, "liquid_bridge.surface_tension",
       "expected a number > 0, got 0"},
      {"[liquid_bridge]\nsurface_tension = -0.07\nvolume = 1e-12\n", 9, "liquid_bridge.surface_tension",
       "expected a number > 0, got -0.07"},
      {"[liquid_bridge]\nvolume = 1e-12\n", 8, "liquid_bridge.surface_tension", "missing required key"},
      {"[liquid_bridge]\nsurface_tension = 0.07\nvolume = 0\n", 10, "liquid_bridge.volume",
       "expected a number > 0, got 0"},
      {"[liquid_bridge]\nsurface_tension = 0.07\nvolume = -1e-12\n", 10, "liquid_bridge.volume",
       "expected a number > 0"},
      {"[liquid_bridge]\n" + ok + "contact_angle = 95\n", 11, "liquid_bridge.contact_angle",
       "expected a number in [0, 90], got 95"},
      {"[liquid_bridge]\n" + ok + "contact_angle = -5\n", 11, "liquid_bridge.contact_angle",
       "expected a number in [0, 90], got -5"},
      {"[liquid_bridge]\nsurface_tension = 0.07\nliquid_fraction = 1\n", 10, "liquid_bridge.liquid_fraction",
       "expected a number in (0, 1), got 1"},
      {"[liquid_bridge]\nsurface_tension = 0.07\nliquid_fraction = 0\n", 10, "liquid_bridge.liquid_fraction",
       "expected a number in (0, 1), got 0"},
      {"[liquid_bridge]\n" + ok + "liquid_fraction = 0.1\n", 11, "liquid_bridge.liquid_fraction",
       "give either volume or liquid_fraction, not both"},
      {"[liquid_bridge]\nsurface_tension = 0.07\n", 8, "liquid_bridge.volume",
       "give volume (m^3 per bridge, > 0) or liquid_fraction"},
      {"[liquid_bridge]\n" + ok + "model = \"lian\"\n", 11, "liquid_bridge.model",
       "expected \"willett\", \"rabinovich\" or \"none\", got \"lian\""},
      {"[liquid_bridge]\n" + ok + "viscosity = -1\n", 11, "liquid_bridge.viscosity", "expected a number >= 0"},
      {"[liquid_bridge]\n" + ok + "min_gap = 0\n", 11, "liquid_bridge.min_gap", "expected a number > 0"},
      {"[liquid_bridge]\n" + ok + "barriers = 1\n", 11, "liquid_bridge.barriers", "expected a boolean"},
      {"[liquid_bridge]\n" + ok + "tension = 1\n", 11, "liquid_bridge.tension", "unknown key"},
      // A pair entry: inline and standard tables, alone and over [liquid_bridge].
      {pair + "liquid_bridge = { surface_tension = 0.07 }\n", 10, "contact.pair.liquid_bridge.volume",
       "missing required key"},
      {pair + "liquid_bridge = { volume = 1e-12 }\n", 10, "contact.pair.liquid_bridge.surface_tension",
       "missing required key"},
      {pair + "[contact.pair.liquid_bridge]\n" + ok + "contact_angle = 91\n", 13,
       "contact.pair.liquid_bridge.contact_angle", "expected a number in [0, 90], got 91"},
      {pair + "liquid_bridge = { model = \"mikami\" }\n", 10, "contact.pair.liquid_bridge.model",
       "expected \"willett\", \"rabinovich\" or \"none\", got \"mikami\""},
      {"[liquid_bridge]\n" + ok + pair + "liquid_bridge = { volume = 1e-12, liquid_fraction = 0.1 }\n", 13,
       "contact.pair.liquid_bridge.liquid_fraction", "give either volume or liquid_fraction, not both"},
      {"[liquid_bridge]\n" + ok + pair + "liquid_bridge = { surface_tension = -1 }\n", 13,
       "contact.pair.liquid_bridge.surface_tension", "expected a number > 0, got -1"},
      {"[liquid_bridge]\n" + ok + pair + "liquid_bridge = 3\n", 13, "contact.pair.liquid_bridge", "expected a table"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.toml);
    TempDir d("mpdem_bridge_keys");
    const fs::path scene = d.write("scene.toml", kHead + c.toml);
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    expect_contains(msg, {scene.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ", c.expect});
  }
  // The command exits with status 2 and the same location.
  TempDir d("mpdem_bridge_keys");
  d.write("scene.toml", kHead + "[liquid_bridge]\nsurface_tension = 0.07\nvolume = 0\n");
  const CommandResult r = run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(r.status, 2) << r.err;
  expect_contains(r.err, {"scene.toml:10: 'liquid_bridge.volume': "});
}

}  // namespace
