// [contact] of the scene file (io/contact_reader.cpp): the law keys, [[contact.pair]] entries,
// and messages naming file, line and key for bad values.
#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"

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
              "stiffness_normal = 2e4\nstiffness_tangential = 5e3\nrestitution = 0.5\n");
  const Scene s = parse_scene_file(scene);
  const ContactParams& c = s.model.params.contact;
  EXPECT_EQ(c.particle_particle.law, ContactLawKind::Hertz);
  EXPECT_EQ(*c.particle_particle.restitution, 0.7);
  EXPECT_EQ(c.particle_barrier.law, ContactLawKind::Linear);
  EXPECT_EQ(c.particle_barrier.stiffness_normal, 1e4);
  ASSERT_EQ(c.pairs.size(), 2u);
  EXPECT_EQ(c.pairs[0].material_a, "glass");
  EXPECT_EQ(c.pairs[0].material_b, "steel");
  EXPECT_TRUE(c.pairs[0].particle_particle && c.pairs[0].particle_barrier);
  EXPECT_EQ(*c.pairs[0].mu_static, 0.3);
  EXPECT_FALSE(c.pairs[0].restitution.has_value());
  EXPECT_TRUE(c.pairs[1].particle_particle && !c.pairs[1].particle_barrier);
  EXPECT_EQ(*c.pairs[1].law, ContactLawKind::Linear);
  EXPECT_EQ(*c.pairs[1].stiffness_tangential, 5e3);
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
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.toml);
    TempDir d("mpdem_contact");
    const fs::path scene = d.write("scene.toml", kHead + c.toml);
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    expect_contains(msg, {scene.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ", c.expect});
  }
}

}  // namespace
