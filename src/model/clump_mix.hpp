#pragma once
// The clump templates a source of bodies draws from (docs/scene.md "Clumps"): `clump = "name"`
// (one template) or `clump = { tetra = 0.7, dumbbell = 0.3 }` (templates with number fractions),
// for generated bodies and inlets. Each new body draws its template: one uniform number u in
// [0, 1) from the source's template stream, and the first template (in the order given) whose
// cumulative fraction exceeds u, so template i comes with probability fraction i. A single
// template draws nothing (the streams of a scene with one template are those without a mix).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/random.hpp"
#include "model/clump_template.hpp"

namespace mpdem {

struct ClumpMix {
  std::vector<int> clumps;        // indices into Model::clumps, in the order given [T]
  std::vector<double> fractions;  // -, number fractions [T], each > 0, summing to 1 (within 1e-9)

  bool empty() const { return clumps.empty(); }
  bool contains(int clump) const { return std::find(clumps.begin(), clumps.end(), clump) != clumps.end(); }

  // The template of the next body (an index into Model::clumps); see above.
  int draw(Rng& rng) const {
    if (clumps.size() == 1) return clumps.front();
    const double u = rng.uniform();
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < clumps.size(); ++i) {
      sum += fractions[i];
      if (u < sum) return clumps[i];
    }
    return clumps.back();  // the last one's share, and any round-off of the sum below 1
  }
  // m^3, a body's mean volume (the union of its members) over the mix.
  double mean_volume(const std::vector<ClumpTemplate>& templates) const {
    double v = 0.0;
    for (std::size_t i = 0; i < clumps.size(); ++i) v += fractions[i] * at(templates, i).shape.volume;
    return v;
  }
  // kg, a body's mean mass over the mix for a material of density rho (kg/m^3).
  double mean_mass(const std::vector<ClumpTemplate>& templates, double rho) const {
    double m = 0.0;
    for (std::size_t i = 0; i < clumps.size(); ++i) m += fractions[i] * at(templates, i).body_mass(rho);
    return m;
  }
  // m, the largest reach (ClumpTemplate::reach) of the templates.
  double reach(const std::vector<ClumpTemplate>& templates) const {
    double r = 0.0;
    for (std::size_t i = 0; i < clumps.size(); ++i) r = std::max(r, at(templates, i).reach());
    return r;
  }
  // m, the radii of the templates' members, each once, ascending.
  std::vector<double> member_radii(const std::vector<ClumpTemplate>& templates) const {
    std::vector<double> r;
    for (std::size_t i = 0; i < clumps.size(); ++i)
      for (const ClumpMember& m : at(templates, i).members()) r.push_back(m.r);
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    return r;
  }

 private:
  const ClumpTemplate& at(const std::vector<ClumpTemplate>& templates, std::size_t i) const {
    return templates[static_cast<std::size_t>(clumps[i])];
  }
};

}  // namespace mpdem
