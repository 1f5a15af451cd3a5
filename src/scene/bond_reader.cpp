#include "scene/bond_reader.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include <fmt/core.h>

#include "core/input_error.hpp"
#include "io/csv_table.hpp"
#include "model/bond_rules.hpp"
#include "scene/contact_reader.hpp"
#include "scene/input_paths.hpp"

namespace mpdem {

namespace {

constexpr std::array<std::string_view, 9> kSectionKeys{
    "radius_ratio", "young", "stiffness_ratio", "tensile_strength", "shear_strength", "damping", "gap", "file", "pair"};
constexpr std::array<std::string_view, 9> kPairKeys{"materials",      "bonded",          "radius_ratio",
                                                    "young",          "stiffness_ratio", "tensile_strength",
                                                    "shear_strength", "damping",         "gap"};
constexpr std::array<std::string_view, 2> kColumns{"id_i", "id_j"};

// The keys both tables share, each range-checked.
BondKeys read_keys(const TomlSection& s) {
  BondKeys k;
  k.radius_ratio = s.number("radius_ratio", kPositive);
  k.young = s.number("young", kPositive);
  k.stiffness_ratio = s.number("stiffness_ratio", kPositive);
  k.tensile_strength = s.number("tensile_strength", kNonNegative);
  k.shear_strength = s.number("shear_strength", kNonNegative);
  k.damping = s.number("damping", kNonNegative);
  k.gap = s.number("gap", kNonNegative);
  return k;
}

// The bond CSV's rows: two integer ids per row, no particle bonded to itself, no bond twice.
std::vector<ListedBond> read_bond_csv(const std::filesystem::path& file) {
  const CsvTable t = CsvTable::read(file, kColumns.size());
  t.check_known(kColumns);
  for (const std::string_view c : kColumns) t.require(c);
  const int ci = t.column("id_i"), cj = t.column("id_j");
  std::vector<ListedBond> out;
  std::map<std::pair<std::int64_t, std::int64_t>, std::size_t> seen;  // (smaller id, larger id) -> line
  for (const CsvRow& row : t.rows()) {
    const ListedBond b{t.integer(row, ci), t.integer(row, cj), row.line};
    if (b.id_i == b.id_j) t.fail(row, cj, "particle id " + std::to_string(b.id_i) + " is bonded to itself");
    const auto [at, fresh] = seen.emplace(std::minmax(b.id_i, b.id_j), row.line);
    if (!fresh)
      t.fail(row, cj,
             "the bond between ids " + std::to_string(b.id_i) + " and " + std::to_string(b.id_j) +
                 " is listed twice (first at line " + std::to_string(at->second) + ", in either order)");
    out.push_back(b);
  }
  return out;
}

void read_pairs(const TomlSection& s, const Model& model, BondParams& bonds) {
  for (const TomlSection& e : s.tables("pair", kPairKeys)) {
    BondPairParams pair;
    pair.line = e.line();
    const std::vector<std::string> names = e.require(e.strings("materials", 2), "materials");
    for (const std::string& n : names) check_material(e, "materials", n, model);
    pair.material_a = names[0];
    pair.material_b = names[1];
    pair.keys = read_keys(e);
    pair.keys.bonded = e.boolean("bonded");
    bonds.pairs.push_back(std::move(pair));
  }
}

}  // namespace

void read_bonds(const TomlSection& root, const std::filesystem::path& dir, Model& model) {
  const auto s = root.table("bonds", std::span<const std::string_view>(kSectionKeys));
  if (!s) return;
  BondParams& bonds = model.params.bonds;
  const std::vector<TomlSection> pairs = s->tables("pair", kPairKeys);
  // [[bonds.pair]] alone makes an implicit [bonds] table that holds only the entries.
  if (!pairs.empty() &&
      std::none_of(kSectionKeys.begin(), kSectionKeys.end() - 1, [&](std::string_view k) { return s->has(k); }))
    throw InputError(root.file(), pairs.front().line(), "bonds.pair",
                     "[[bonds.pair]] needs a [bonds] table (with young, and gap or file)");
  bonds.line = s->line();
  bonds.defaults = read_keys(*s);
  if (!bonds.defaults->young) s->fail("young", "missing required key (Pa, > 0: the bonds' Young's modulus E_b)");
  if (s->has("file")) {
    bonds.file = existing_file(*s, "file", dir);
    bonds.listed = read_bond_csv(bonds.file);
  }
  read_pairs(*s, model, bonds);
  const bool gap_rule = bonds.defaults->gap || std::any_of(bonds.pairs.begin(), bonds.pairs.end(),
                                                           [](const auto& e) { return e.keys.gap.has_value(); });
  if (!gap_rule && !s->has("file"))
    s->fail("gap", "missing: bonds need gap (m, >= 0: bonds between particles whose surface gap at t = 0 is below "
                   "it) or file (a bond CSV with columns id_i,id_j), or both");
}

void check_listed_bonds(const Scene& scene) {
  const BondParams& bonds = scene.model.params.bonds;
  if (bonds.listed.empty()) return;
  const Particles& p = scene.particles;
  const std::string file = bonds.file.string();
  std::unordered_map<std::int64_t, std::size_t> index;  // particle id -> index
  index.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) index.emplace(p.id[i], i);
  const std::vector<std::uint8_t> held = held_fixed(p);
  const std::vector<BondLaw> laws = bond_laws(scene.model);
  const std::size_t nm = scene.model.materials.size();
  const auto base_name = [&](std::size_t m) {
    const Material& mat = scene.model.materials[m];
    return mat.variant_of >= 0 ? scene.model.materials[static_cast<std::size_t>(mat.variant_of)].name : mat.name;
  };
  for (const ListedBond& b : bonds.listed) {
    const auto i = index.find(b.id_i), j = index.find(b.id_j);
    if (i == index.end() || j == index.end()) {
      const bool first = i == index.end();
      throw InputError(file, b.line, first ? "id_i" : "id_j",
                       fmt::format("no particle has id {} (the scene's particles at t = 0)", first ? b.id_i : b.id_j));
    }
    const std::size_t pi = i->second, pj = j->second;
    if (p.body[pi] != kNoBody && p.body[pi] == p.body[pj])
      throw InputError(file, b.line, "id_j",
                       fmt::format("ids {} and {} are members of one clump body ({}), which moves rigidly: the bond "
                                   "could never act",
                                   b.id_i, b.id_j, p.body[pi]));
    if (held[pi] && held[pj])
      throw InputError(file, b.line, "id_j",
                       fmt::format("ids {} and {} are both fixed: the bond could never act", b.id_i, b.id_j));
    const std::size_t ma = static_cast<std::size_t>(p.material[pi]), mc = static_cast<std::size_t>(p.material[pj]);
    if (!laws[ma * nm + mc].bonded)
      throw InputError(file, b.line, "id_j",
                       fmt::format("ids {} and {} are of materials '{}' and '{}', which [[bonds.pair]] makes "
                                   "unbondable (bonded = false)",
                                   b.id_i, b.id_j, base_name(ma), base_name(mc)));
  }
}

}  // namespace mpdem
