#pragma once
// The keys of parallel bonds as given (docs/scene.md "[bonds]"): the [bonds] defaults, the
// [[bonds.pair]] overrides per pair of materials, the bond CSV's id pairs; and the law they
// resolve to for one pair of materials (BondLaw), which the bond kernels read
// (contact/bonds.hpp, physics/parallel_bond.hpp; docs/physics.md "Parallel bonds").
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mpdem {

// Unset: not given (the documented default, or the defaults' value for a pair entry).
struct BondKeys {
  std::optional<double> radius_ratio;      // -, lambda > 0: R_b = lambda min(R_i, R_j) (default 1)
  std::optional<double> young;             // Pa, E_b > 0 (required when bonds are on)
  std::optional<double> stiffness_ratio;   // -, k_n / k_s > 0 (default kStiffnessRatio)
  std::optional<double> tensile_strength;  // Pa, sigma_c >= 0 (default: never breaks in tension)
  std::optional<double> shear_strength;    // Pa, tau_c >= 0 (default: never breaks in shear)
  std::optional<double> damping;           // -, zeta >= 0, ratio of each bond spring's critical damping (default 0)
  std::optional<double> gap;               // m, surface gap below which bonds are made at t = 0 (unset: no gap rule)
  std::optional<bool> bonded;              // a pair entry: false: no bond between the two materials (default true)
  // E/G = 2 (1 + nu) for nu = 0.25, PFC's usual ratio of normal to shear bond stiffness.
  static constexpr double kStiffnessRatio = 2.5;
};

// The defaults with an entry's keys over them, key by key.
inline BondKeys overridden(BondKeys base, const BondKeys& over) {
  if (over.radius_ratio) base.radius_ratio = over.radius_ratio;
  if (over.young) base.young = over.young;
  if (over.stiffness_ratio) base.stiffness_ratio = over.stiffness_ratio;
  if (over.tensile_strength) base.tensile_strength = over.tensile_strength;
  if (over.shear_strength) base.shear_strength = over.shear_strength;
  if (over.damping) base.damping = over.damping;
  if (over.gap) base.gap = over.gap;
  if (over.bonded) base.bonded = over.bonded;
  return base;
}

// [[bonds.pair]]: overrides for the bonds between a particle of material_a and one of material_b.
struct BondPairParams {
  std::string material_a, material_b;
  BondKeys keys;
  std::size_t line = 0;  // line of the entry, for messages
};

// One row of the bond CSV ([bonds] file): a bond between the particles of these ids.
struct ListedBond {
  std::int64_t id_i = 0, id_j = 0;
  std::size_t line = 0;  // line in the CSV, for messages
};

struct BondParams {
  std::optional<BondKeys> defaults;  // [bonds] given: its keys (bonds on)
  std::vector<BondPairParams> pairs;
  std::filesystem::path file;      // [bonds] file: the bond CSV (absolute), or empty
  std::vector<ListedBond> listed;  // its rows
  std::size_t line = 0;            // line of [bonds] in the scene file, for messages
  bool enabled() const { return defaults.has_value(); }
};

// The resolved law of the bonds between two materials.
struct BondLaw {
  bool bonded = false;                                                // bonds are made between the two materials
  double radius_ratio = 1.0;                                          // -, lambda
  double young = 0.0;                                                 // Pa, E_b
  double stiffness_ratio = BondKeys::kStiffnessRatio;                 // -, k_n / k_s
  double tensile_strength = std::numeric_limits<double>::infinity();  // Pa, sigma_c
  double shear_strength = std::numeric_limits<double>::infinity();    // Pa, tau_c
  double damping = 0.0;                                               // -, zeta
  double gap = -1.0;  // m, gap rule's reach; < 0: the gap rule makes no bond between them
};

// The law for materials a and b: [bonds] with the last matching [[bonds.pair]] entry over it
// (materials named in either order). `names`: the materials' names by index.
inline BondLaw bond_law(const BondParams& params, const std::string& a, const std::string& b) {
  BondLaw law;
  if (!params.defaults) return law;
  BondKeys k = *params.defaults;
  for (const BondPairParams& e : params.pairs)
    if ((e.material_a == a && e.material_b == b) || (e.material_a == b && e.material_b == a)) k = overridden(k, e.keys);
  law.bonded = k.bonded.value_or(true) && k.young.has_value();
  if (k.radius_ratio) law.radius_ratio = *k.radius_ratio;
  if (k.young) law.young = *k.young;
  if (k.stiffness_ratio) law.stiffness_ratio = *k.stiffness_ratio;
  if (k.tensile_strength) law.tensile_strength = *k.tensile_strength;
  if (k.shear_strength) law.shear_strength = *k.shear_strength;
  if (k.damping) law.damping = *k.damping;
  if (k.gap) law.gap = *k.gap;
  return law;
}

}  // namespace mpdem
