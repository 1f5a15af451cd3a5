#include "check/bond_summary.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "check/scene_checks.hpp"
#include "contact/bond_making.hpp"
#include "physics/parallel_bond.hpp"

namespace mpdem {

namespace {

// The reduced value of a bond's two particles' masses (kg) or moments of inertia (kg m^2)
// (physics bond_reduced). A clump member's Particles::mass is its body's.
double reduced(const std::vector<double>& m, const std::vector<std::uint8_t>& held, std::size_t i, std::size_t j) {
  return bond_reduced(m[i], m[j], held[i] != 0, held[j] != 0);
}

// The materials (base ones, by index) bonded to no material at all, by [[bonds.pair]] bonded = false.
std::vector<std::uint8_t> unbondable_materials(const Model& model, const std::vector<BondLaw>& laws) {
  const std::size_t n = model.materials.size();
  std::vector<std::uint8_t> out(n, 1);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) out[a] = out[a] && !laws[a * n + b].bonded;
  return out;
}

}  // namespace

BondSummary bond_summary(const Scene& scene) {
  BondSummary s;
  const Model& model = scene.model;
  const Particles& p = scene.particles;
  if (!model.params.bonds.enabled()) return s;
  const std::vector<MadeBond> by_gap = gap_bonds(model, p), listed = listed_bonds(model, p);
  const std::vector<MadeBond> bonds = bond_union(p, by_gap, listed);  // make_bonds
  s.by_gap = by_gap.size();
  s.listed = listed.size();
  s.made = bonds.size();
  const std::vector<BondLaw> laws = bond_laws(model);
  const std::size_t nm = model.materials.size();
  const std::vector<std::uint8_t> held = held_fixed(p);
  std::vector<std::uint8_t> bonded(p.size(), 0);
  s.length_min = std::numeric_limits<double>::infinity();
  s.time_step = std::numeric_limits<double>::infinity();
  for (const MadeBond& b : bonds) {
    bonded[b.i] = bonded[b.j] = 1;
    const BondLaw& law =
        laws[static_cast<std::size_t>(p.material[b.i]) * nm + static_cast<std::size_t>(p.material[b.j])];
    const double L = bond_length(model, p, b.i, b.j);  // m
    s.length_min = std::min(s.length_min, L);
    s.length_max = std::max(s.length_max, L);
    const double r_b = law.radius_ratio * std::min(p.radius[b.i], p.radius[b.j]);  // m
    const BondSprings k = bond_springs(bond_section(r_b), L, law.young, law.stiffness_ratio);
    // The longer lever from a centre to the bond's centre, midway between the surfaces.
    const double lever = std::max(p.radius[b.i], p.radius[b.j]) + 0.5 * (L - p.radius[b.i] - p.radius[b.j]);  // m
    s.time_step = std::min(
        s.time_step, bond_critical_step(k, reduced(p.mass, held, b.i, b.j), reduced(p.inertia, held, b.i, b.j), lever));
  }
  if (bonds.empty()) s.length_min = s.time_step = 0.0;
  const std::vector<std::uint8_t> apart = unbondable_materials(model, laws);
  std::vector<std::uint8_t> used(nm, 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t m = static_cast<std::size_t>(p.material[i]);
    if (!bonded[i]) s.isolated_ids.push_back(p.id[i]);
    if (apart[m]) {
      ++s.unbondable;
      const Material& mat = model.materials[m];
      used[mat.variant_of >= 0 ? static_cast<std::size_t>(mat.variant_of) : m] = 1;
    }
  }
  s.isolated = s.isolated_ids.size();
  const std::size_t shown = std::min(s.isolated, kListedIds);
  std::partial_sort(s.isolated_ids.begin(), s.isolated_ids.begin() + static_cast<std::ptrdiff_t>(shown),
                    s.isolated_ids.end());
  s.isolated_ids.resize(shown);
  for (std::size_t m = 0; m < nm; ++m)
    if (used[m]) s.unbondable_materials.push_back(model.materials[m].name);
  return s;
}

std::vector<std::string> bond_summary_lines(const Scene& scene) {
  const BondParams& params = scene.model.params.bonds;
  if (!params.enabled()) return {};
  const BondSummary s = bond_summary(scene);
  std::vector<std::string> out;
  std::string sources = fmt::format("{} by the gap rule", s.by_gap);
  if (!params.file.empty())
    sources += fmt::format(", {} listed in {} ({} in both)", s.listed, params.file.filename().string(),
                           s.by_gap + s.listed - s.made);
  out.push_back(fmt::format("bonds: {} made at t = 0 ({})", s.made, sources));
  if (s.made > 0) {
    out.push_back(fmt::format("  bond lengths {:.4g} .. {:.4g} m", s.length_min, s.length_max));
    out.push_back(fmt::format("  bond time step 2 / omega (normal and rotational modes, physics.md 22): {:.4g} s (the "
                              "smallest over the bonds)",
                              s.time_step));
  }
  if (s.isolated > 0) {
    std::string ids;
    for (const std::int64_t id : s.isolated_ids) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    out.push_back(fmt::format("  isolated particles (no bond): {}, ids {}{}", s.isolated, ids,
                              s.isolated > s.isolated_ids.size() ? ", ..." : ""));
  }
  if (s.unbondable > 0) {
    std::string names;
    for (const std::string& n : s.unbondable_materials) names += (names.empty() ? "'" : ", '") + n + "'";
    out.push_back(
        fmt::format("  unbondable particles (bonded = false with every material): {}, of {}", s.unbondable, names));
  }
  return out;
}

}  // namespace mpdem
