// The scene fingerprint of a scene with bonds (io/scene_fingerprint.hpp, parts "bonds" and
// "listed bonds"): every [bonds] key, each [[bonds.pair]] entry and each listed bond is an item,
// so that a resume of another bond scene is refused naming what differs; the same bonds listed in
// another order are the same scene, and scenes without bonds keep their parts.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "io/scene_fingerprint.hpp"
#include "scene/scene_reader.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

const std::string kScene = "[time]\nduration = 0.01\ndt = 1e-6\n"
                           "[[material]]\nname = \"glass\"\n[[material]]\nname = \"steel\"\n"
                           "[[particles]]\nfile = \"p.csv\"\n";
const std::string kParticles = "id,x,y,z,radius\n1,0,0,0,0.001\n2,0.0021,0,0,0.001\n3,0.0042,0,0,0.001\n";
const std::string kBonds = kScene +
                           "[bonds]\nradius_ratio = 0.5\nyoung = 1e9\nstiffness_ratio = 2\ntensile_strength = 1e6\n"
                           "shear_strength = 1e6\ndamping = 0.1\ngap = 1e-4\nfile = \"b.csv\"\n"
                           "[[bonds.pair]]\nmaterials = [\"glass\", \"steel\"]\nbonded = false\n";
const std::string kCsv = "id_i,id_j\n1,2\n2,3\n";

// What differs between the fingerprints of scene a (with bond CSV csv_a) and scene b.
std::string difference(const std::string& a, const std::string& csv_a, const std::string& b, const std::string& csv_b) {
  test::TempDir d("bond_fingerprint");
  d.write("p.csv", kParticles);
  d.write("scene.toml", a);
  d.write("b.csv", csv_a);
  const SceneFingerprint first = fingerprint_scene(load_scene(d.path / "scene.toml"));
  d.write("scene.toml", b);
  d.write("b.csv", csv_b);
  return fingerprint_difference(first, fingerprint_scene(load_scene(d.path / "scene.toml")));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace

TEST(BondFingerprint, EveryBondKeyIsAnItem) {
  EXPECT_EQ(difference(kBonds, kCsv, kBonds, kCsv), "");
  const std::vector<std::pair<std::string, std::string>> edits = {{"radius_ratio = 0.5", "radius_ratio"},
                                                                  {"young = 1e9", "young"},
                                                                  {"stiffness_ratio = 2", "stiffness_ratio"},
                                                                  {"tensile_strength = 1e6", "tensile_strength"},
                                                                  {"shear_strength = 1e6", "shear_strength"},
                                                                  {"damping = 0.1", "damping"},
                                                                  {"gap = 1e-4", "gap"}};
  for (const auto& [line, key] : edits) {
    // Another value, and the key left out (its default).
    const std::string edited = replaced(kBonds, line, line + "1");
    EXPECT_EQ(difference(kBonds, kCsv, edited, kCsv), "bonds (bonds." + key + ")") << line;
    if (key != "young") {
      const std::string left_out = replaced(kBonds, line + "\n", "");
      EXPECT_EQ(difference(kBonds, kCsv, left_out, kCsv), "bonds (bonds." + key + ")") << line;
    }
  }
  EXPECT_EQ(difference(kBonds, kCsv, replaced(kBonds, "bonded = false", "bonded = true"), kCsv),
            "bonds ([[bonds.pair]] 'glass'-'steel')");
  EXPECT_EQ(difference(kBonds, kCsv, replaced(kBonds, "bonded = false", "bonded = false\ngap = 0"), kCsv),
            "bonds ([[bonds.pair]] 'glass'-'steel')");
  EXPECT_EQ(difference(kBonds, kCsv, kBonds + "[[bonds.pair]]\nmaterials = [\"glass\", \"glass\"]\n", kCsv),
            "bonds (2 [[bonds.pair]] entries, the checkpoint's scene had 1)");
}

TEST(BondFingerprint, ListedBondsAreItems) {
  // The same bonds in another order or orientation: the same scene.
  EXPECT_EQ(difference(kBonds, kCsv, kBonds, "id_i,id_j\n3,2\n# a comment\n1,2\n"), "");
  EXPECT_EQ(difference(kBonds, kCsv, kBonds, "id_i,id_j\n1,3\n2,3\n"), "listed bonds (the bond between ids 1 and 3)");
  EXPECT_EQ(difference(kBonds, kCsv, kBonds, "id_i,id_j\n1,2\n2,3\n1,3\n"),
            "listed bonds (the bond between ids 1 and 3; 3 bonds in the bond CSV, the checkpoint's scene had 2)");
  // The file's name may change with its content kept.
  EXPECT_EQ(difference(kBonds, kCsv, replaced(kBonds, "file = \"b.csv\"", "file = \"./b.csv\""), kCsv), "");
}

TEST(BondFingerprint, BondsAddedOrRemovedAreRefused) {
  const std::string none = kScene;
  EXPECT_EQ(difference(none, kCsv, none, kCsv), "");
  EXPECT_EQ(difference(none, kCsv, kBonds, kCsv),
            "bonds (not in the checkpoint) and listed bonds (not in the checkpoint)");
  EXPECT_EQ(difference(kBonds, kCsv, none, kCsv),
            "bonds (in the checkpoint, not in this scene) and listed bonds (in the checkpoint, not in this scene)");
  // Bonds by the gap rule only still carry an (empty) listed part.
  const std::string gap_only = replaced(kBonds, "file = \"b.csv\"\n", "");
  EXPECT_EQ(difference(gap_only, kCsv, kBonds, kCsv),
            "listed bonds (2 bonds in the bond CSV, the checkpoint's scene had 0)");
}
