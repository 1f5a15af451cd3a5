// [bonds] and [[bonds.pair]] of the scene file and the bond CSV (scene/bond_reader.cpp): the keys
// as given, their defaults in the resolved law, the pair overrides, and one InputError naming
// file, line and key (or CSV column) for every bad value, checked for every key of both tables.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "scene/scene_reader.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

const std::string kHead = "[time]\nduration = 1.0\ndt = 1e-5\n"                                // 1-3
                          "[[material]]\nname = \"glass\"\n[[material]]\nname = \"steel\"\n";  // 4-7

// Particles 1-3 of glass along x (0.1 mm apart), 4-5 of steel, both fixed, and the entries naming them.
const std::string kParticles = "id,x,y,z,radius\n1,0,0,0,0.001\n2,0.0021,0,0,0.001\n3,0.0042,0,0,0.001\n";
const std::string kFixed = "id,x,y,z,radius\n4,0,0.01,0,0.001\n5,0.0021,0.01,0,0.001\n";
const std::string kSources = "[[particles]]\nfile = \"p.csv\"\nmaterial = \"glass\"\n"
                             "[[particles]]\nfile = \"q.csv\"\nmaterial = \"steel\"\nfixed = true\n";

// The numeric keys both tables share, each with a value out of its range and the range's text.
struct BadValue {
  std::string key, value, expect;
};
const std::vector<BadValue> kBadValues = {
    {"radius_ratio", "0", "expected a number > 0, got 0"},
    {"radius_ratio", "-0.5", "expected a number > 0, got -0.5"},
    {"young", "0", "expected a number > 0, got 0"},
    {"young", "-1e9", "expected a number > 0, got -1e+09"},
    {"stiffness_ratio", "0", "expected a number > 0, got 0"},
    {"tensile_strength", "-1", "expected a number >= 0, got -1"},
    {"shear_strength", "-1e6", "expected a number >= 0, got -1e+06"},
    {"damping", "-0.1", "expected a number >= 0, got -0.1"},
    {"gap", "-1e-6", "expected a number >= 0, got -1e-06"},
    {"tensile_strength", "nan", "expected a finite number"},
    {"young", "\"1e9\"", "expected a number > 0, got a string"},
};

// The message of the InputError that loading `toml` (after kHead) throws.
std::string load_error(const TempDir& d, const std::string& toml) {
  const fs::path scene = d.write("scene.toml", kHead + toml);
  return error_of([&] { load_scene(scene); });
}

std::string at(const TempDir& d, const std::string& file, int line, const std::string& key) {
  return (d.path / file).string() + ":" + std::to_string(line) + ": '" + key + "': ";
}

}  // namespace

TEST(BondReader, AcceptedSceneWithFileAndPairs) {
  TempDir d("mpdem_bonds");
  d.write("p.csv", kParticles);
  d.write("q.csv", kFixed);
  d.write("bonds/b.csv", "# two listed bonds\nid_i,id_j\n1,3\n\n5,2\n");
  const fs::path scene = d.write("scene.toml",
                                 kHead + kSources +
                                     "[bonds]\nradius_ratio = 0.8\nyoung = 2e9\nstiffness_ratio = 2\n"       // 15-18
                                     "tensile_strength = 1e6\nshear_strength = 2e6\ndamping = 0.1\n"         // 19-21
                                     "gap = 2e-4\nfile = \"bonds/b.csv\"\n"                                  // 22-23
                                     "[[bonds.pair]]\nmaterials = [\"steel\", \"steel\"]\nbonded = false\n"  // 24-26
                                     "[[bonds.pair]]\nmaterials = [\"glass\", \"glass\"]\n"                  // 27-28
                                     "young = 3e9\ngap = 0\nshear_strength = 0\n");
  const Scene s = load_scene(scene);
  const BondParams& b = s.model.params.bonds;
  ASSERT_TRUE(b.enabled());
  EXPECT_EQ(b.line, 15u);
  EXPECT_EQ(*b.defaults->radius_ratio, 0.8);
  EXPECT_EQ(*b.defaults->young, 2e9);
  EXPECT_EQ(*b.defaults->stiffness_ratio, 2.0);
  EXPECT_EQ(*b.defaults->tensile_strength, 1e6);
  EXPECT_EQ(*b.defaults->shear_strength, 2e6);
  EXPECT_EQ(*b.defaults->damping, 0.1);
  EXPECT_EQ(*b.defaults->gap, 2e-4);
  EXPECT_FALSE(b.defaults->bonded.has_value());
  EXPECT_EQ(b.file, (d.path / "bonds" / "b.csv").lexically_normal());
  ASSERT_EQ(b.listed.size(), 2u);
  EXPECT_EQ(b.listed[0].id_i, 1);
  EXPECT_EQ(b.listed[0].id_j, 3);
  EXPECT_EQ(b.listed[0].line, 3u);
  EXPECT_EQ(b.listed[1].id_i, 5);
  EXPECT_EQ(b.listed[1].id_j, 2);
  EXPECT_EQ(b.listed[1].line, 5u);
  ASSERT_EQ(b.pairs.size(), 2u);
  EXPECT_EQ(b.pairs[0].material_a, "steel");
  EXPECT_EQ(b.pairs[0].material_b, "steel");
  EXPECT_EQ(b.pairs[0].line, 24u);
  EXPECT_FALSE(*b.pairs[0].keys.bonded);
  EXPECT_FALSE(b.pairs[0].keys.young.has_value());
  EXPECT_EQ(*b.pairs[1].keys.young, 3e9);
  EXPECT_EQ(*b.pairs[1].keys.gap, 0.0);
  // The resolved laws: the pair's keys over the defaults, materials in either order.
  const BondLaw gg = bond_law(b, "glass", "glass");
  EXPECT_TRUE(gg.bonded);
  EXPECT_EQ(gg.young, 3e9);
  EXPECT_EQ(gg.gap, 0.0);
  EXPECT_EQ(gg.shear_strength, 0.0);
  EXPECT_EQ(gg.tensile_strength, 1e6);
  EXPECT_EQ(gg.radius_ratio, 0.8);
  EXPECT_EQ(gg.stiffness_ratio, 2.0);
  EXPECT_EQ(gg.damping, 0.1);
  EXPECT_FALSE(bond_law(b, "steel", "steel").bonded);
  const BondLaw sg = bond_law(b, "steel", "glass");
  EXPECT_TRUE(sg.bonded);
  EXPECT_EQ(sg.young, 2e9);
  EXPECT_EQ(sg.gap, 2e-4);
}

TEST(BondReader, DefaultsOfTheResolvedLaw) {
  TempDir d("mpdem_bonds");
  const Scene s = parse_scene_file(d.write("scene.toml", kHead + "[bonds]\nyoung = 1e9\ngap = 1e-5\n"));
  const BondParams& b = s.model.params.bonds;
  ASSERT_TRUE(b.enabled());
  EXPECT_TRUE(b.file.empty());
  EXPECT_TRUE(b.listed.empty());
  for (const auto& k : {b.defaults->radius_ratio, b.defaults->stiffness_ratio, b.defaults->tensile_strength,
                        b.defaults->shear_strength, b.defaults->damping})
    EXPECT_FALSE(k.has_value());
  const BondLaw law = bond_law(b, "glass", "steel");
  EXPECT_TRUE(law.bonded);
  EXPECT_EQ(law.radius_ratio, 1.0);
  EXPECT_EQ(law.young, 1e9);
  EXPECT_EQ(law.stiffness_ratio, BondKeys::kStiffnessRatio);
  EXPECT_EQ(law.stiffness_ratio, 2.5);
  EXPECT_EQ(law.tensile_strength, std::numeric_limits<double>::infinity());
  EXPECT_EQ(law.shear_strength, std::numeric_limits<double>::infinity());
  EXPECT_EQ(law.damping, 0.0);
  EXPECT_EQ(law.gap, 1e-5);
  // Without [bonds]: off, no law.
  const Scene none = parse_scene_file(d.write("none.toml", kHead));
  EXPECT_FALSE(none.model.params.bonds.enabled());
  EXPECT_FALSE(bond_law(none.model.params.bonds, "glass", "glass").bonded);
  // A gap given only by a pair entry makes bonds between its materials only.
  const Scene pair = parse_scene_file(d.write(
      "pair.toml", kHead + "[bonds]\nyoung = 1e9\n[[bonds.pair]]\nmaterials = [\"steel\", \"steel\"]\ngap = 1e-5\n"));
  EXPECT_EQ(bond_law(pair.model.params.bonds, "steel", "steel").gap, 1e-5);
  EXPECT_LT(bond_law(pair.model.params.bonds, "glass", "glass").gap, 0.0);
}

TEST(BondReader, EveryNumericKeyOfBothTablesIsRangeChecked) {
  for (const BadValue& v : kBadValues) {
    SCOPED_TRACE(v.key + " = " + v.value);
    TempDir d("mpdem_bonds");
    // [bonds]: the bad key on line 9, the required keys after it.
    std::string section = "[bonds]\n" + v.key + " = " + v.value + "\n";
    if (v.key != "young") section += "young = 1e9\n";
    if (v.key != "gap") section += "gap = 1e-5\n";
    const fs::path scene = d.write("scene.toml", kHead + section);
    expect_contains(error_of([&] { parse_scene_file(scene); }),
                    {scene.string() + ":9: 'bonds." + v.key + "': ", v.expect});
    // [[bonds.pair]]: line 13.
    const fs::path pair = d.write("pair.toml", kHead +
                                                   "[bonds]\nyoung = 1e9\ngap = 1e-5\n[[bonds.pair]]\n"
                                                   "materials = [\"glass\", \"steel\"]\n" +
                                                   v.key + " = " + v.value + "\n");
    expect_contains(error_of([&] { parse_scene_file(pair); }),
                    {pair.string() + ":13: 'bonds.pair." + v.key + "': ", v.expect});
  }
}

TEST(BondReader, BadTablesNameFileLineAndKey) {
  struct Case {
    std::string toml;
    int line;
    std::string key, expect;
  };
  const std::string b = "[bonds]\nyoung = 1e9\ngap = 1e-5\n";  // 8-10
  const std::string pair = b + "[[bonds.pair]]\n";             // 11
  const std::vector<Case> cases = {
      {"[bonds]\ngap = 1e-5\n", 8, "bonds.young", "missing required key"},
      {"[bonds]\nyoung = 1e9\n", 8, "bonds.gap", "bonds need gap (m, >= 0"},
      {"[bonds]\nyoung = 1e9\ntensile_strenght = 1e6\n", 10, "bonds.tensile_strenght",
       "unknown key (did you mean 'bonds.tensile_strength'"},
      {b + "bonded = false\n", 11, "bonds.bonded", "unknown key"},
      {b + "file = \"\"\n", 11, "bonds.file", "expected a file name, got an empty string"},
      {b + "file = 3\n", 11, "bonds.file", "expected a string"},
      {b + "file = \"missing.csv\"\n", 11, "bonds.file", "missing.csv' does not exist"},
      {b + "file = \".\"\n", 11, "bonds.file", "is a directory"},
      {"[[bonds.pair]]\nmaterials = [\"glass\", \"steel\"]\n", 8, "bonds.pair", "[[bonds.pair]] needs a [bonds] table"},
      {pair + "materials = [\"glass\", \"wood\"]\n", 12, "bonds.pair.materials",
       "unknown material 'wood' (known: glass, steel)"},
      {pair + "materials = [\"glass\"]\n", 12, "bonds.pair.materials", "expected an array of 2 strings"},
      {pair + "gap = 1e-5\n", 11, "bonds.pair.materials", "missing required key"},
      {pair + "materials = [\"glass\", \"steel\"]\nbonded = 0\n", 13, "bonds.pair.bonded", "expected a boolean"},
      {pair + "materials = [\"glass\", \"steel\"]\nfile = \"b.csv\"\n", 13, "bonds.pair.file", "unknown key"},
      {pair + "materials = [\"glass\", \"steel\"]\nbonde = true\n", 13, "bonds.pair.bonde",
       "unknown key (did you mean 'bonds.pair.bonded'"},
      {"[[bonds]]\nyoung = 1e9\n", 8, "bonds", "expected a table"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.toml);
    TempDir d("mpdem_bonds");
    const fs::path scene = d.write("scene.toml", kHead + c.toml);
    expect_contains(error_of([&] { parse_scene_file(scene); }),
                    {scene.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ", c.expect});
  }
}

TEST(BondReader, BadBondCsvNamesItsLineAndColumn) {
  struct Case {
    std::string csv;
    int line;
    std::string column, expect;
  };
  const std::vector<Case> cases = {
      {"id_i,idj\n1,2\n", 1, "idj", "unknown column (did you mean 'id_j'"},
      {"id_i\n1\n", 1, "id_j", "missing"},
      {"id_i,id_j\n1,2\n2,x\n", 3, "id_j", "expected an integer, got 'x'"},
      {"id_i,id_j\n1.5,2\n", 2, "id_i", "expected an integer, got '1.5'"},
      {"id_i,id_j\n1,\n", 2, "id_j", "expected an integer, got an empty field"},
      {"id_i,id_j\n1,2,3\n", 2, "", "expected 2 fields as in the header (line 1), got 3"},
      {"id_i,id_j\n3,3\n", 2, "id_j", "particle id 3 is bonded to itself"},
      {"id_i,id_j\n1,2\n2,3\n2,1\n", 4, "id_j", "ids 2 and 1 is listed twice (first at line 2"},
      {"id_i,id_j\n1,2\n1,2\n", 3, "id_j", "listed twice"},
      // Checked against the particles once they are loaded.
      {"id_i,id_j\n1,2\n9,2\n", 3, "id_i", "no particle has id 9"},
      {"id_i,id_j\n1,2\n2,-4\n", 3, "id_j", "no particle has id -4"},
      {"id_i,id_j\n1,2\n5,4\n", 3, "id_j", "ids 5 and 4 are both fixed: the bond could never act"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.csv);
    TempDir d("mpdem_bonds");
    d.write("p.csv", kParticles);
    d.write("q.csv", kFixed);
    d.write("b.csv", c.csv);
    const std::string msg = load_error(d, kSources + "[bonds]\nyoung = 1e9\nfile = \"b.csv\"\n");
    const std::string where = (d.path / "b.csv").string() + ":" + std::to_string(c.line) + ":";
    expect_contains(msg, {where, c.expect});
    if (!c.column.empty()) expect_contains(msg, {where + " '" + c.column + "': "});
  }
}

TEST(BondReader, ListedBondsThatCanNeverActAreRefused) {
  TempDir d("mpdem_bonds");
  d.write("p.csv", kParticles);
  d.write("q.csv", kFixed);
  // A fixed particle bonded to a free one acts (a cantilever's clamp): accepted.
  d.write("b.csv", "id_i,id_j\n4,1\n");
  const std::string bonds = "[bonds]\nyoung = 1e9\nfile = \"b.csv\"\n";
  EXPECT_EQ(load_scene(d.write("scene.toml", kHead + kSources + bonds)).model.params.bonds.listed.size(), 1u);
  // Materials that [[bonds.pair]] keeps apart.
  const std::string apart = bonds + "[[bonds.pair]]\nmaterials = [\"glass\", \"steel\"]\nbonded = false\n";
  expect_contains(load_error(d, kSources + apart),
                  {at(d, "b.csv", 2, "id_j"), "ids 4 and 1 are of materials 'steel' and 'glass'", "bonded = false"});
  // Two members of one clump body (ids 6, 7 after the free spheres' 1-5).
  d.write("bodies.csv", "id,x,y,z\n1,0,0.02,0\n");
  d.write("b.csv", "id_i,id_j\n1,2\n6,7\n");
  const std::string clump = "[[clump]]\nname = \"pair\"\nmembers = [[-0.0008, 0, 0, 0.001], [0.0008, 0, 0, 0.001]]\n"
                            "[[particles]]\nfile = \"bodies.csv\"\nclump = \"pair\"\n";
  expect_contains(load_error(d, clump + kSources + bonds),
                  {at(d, "b.csv", 3, "id_j"), "ids 6 and 7 are members of one clump body (1)"});
  // Members of two fixed bodies count as fixed.
  d.write("bodies.csv", "id,x,y,z,fixed\n1,0,0.02,0,1\n2,0,0.03,0,1\n");
  d.write("b.csv", "id_i,id_j\n6,8\n");
  expect_contains(load_error(d, clump + kSources + bonds), {at(d, "b.csv", 2, "id_j"), "both fixed"});
}

// A particle CSV row with its own density gets a variant of its material ("glass#1"): the pair
// entries naming the material apply to it, and messages name the material as given.
TEST(BondReader, MaterialVariantsFollowTheirMaterial) {
  TempDir d("mpdem_bonds");
  d.write("p.csv", "id,x,y,z,radius,density\n1,0,0,0,0.001,\n2,0.0021,0,0,0.001,3000\n3,0.0042,0,0,0.001,\n");
  d.write("q.csv", kFixed);
  d.write("b.csv", "id_i,id_j\n2,4\n");
  const std::string apart = "[bonds]\nyoung = 1e9\nfile = \"b.csv\"\n"
                            "[[bonds.pair]]\nmaterials = [\"glass\", \"steel\"]\nbonded = false\n";
  const std::string msg = load_error(d, kSources + apart);
  expect_contains(msg, {at(d, "b.csv", 2, "id_j"), "ids 2 and 4 are of materials 'glass' and 'steel'"});
  d.write("b.csv", "id_i,id_j\n2,1\n");
  const Scene s = load_scene(d.write("scene.toml", kHead + kSources + apart));
  ASSERT_GT(s.model.materials.size(), 2u);  // the variant was made
  EXPECT_EQ(s.model.params.bonds.listed.size(), 1u);
}

TEST(BondReader, TheCommandExitsWithStatusTwo) {
  TempDir d("mpdem_bonds");
  d.write("p.csv", kParticles);
  d.write("q.csv", kFixed);
  d.write("b.csv", "id_i,id_j\n1,2\n2,2\n");
  d.write("scene.toml", kHead + kSources + "[bonds]\nyoung = 1e9\nfile = \"b.csv\"\n");
  const CommandResult bad = run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(bad.status, 2) << bad.err;
  expect_contains(bad.err, {"b.csv:3: 'id_j': particle id 2 is bonded to itself"});
  d.write("scene.toml", kHead + kSources + "[bonds]\nyoung = -1\ngap = 1e-4\n");
  const CommandResult neg = run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(neg.status, 2) << neg.err;
  expect_contains(neg.err, {"scene.toml:16: 'bonds.young': expected a number > 0, got -1"});
}
