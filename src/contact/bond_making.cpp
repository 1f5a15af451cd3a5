// TEMPORARY stand-in (O(N^2)), replaced by helper bond-a's cell-grid search.
#include "contact/bond_making.hpp"

#include <algorithm>
#include <cmath>

namespace mpdem {

std::vector<MadeBond> make_bonds(const Model& model, const Particles& p) {
  std::vector<MadeBond> out;
  const BondParams& bp = model.params.bonds;
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b = a + 1; b < p.size(); ++b) {
      const BondLaw law = bond_law(bp, model.materials[static_cast<std::size_t>(p.material[a])].name,
                                   model.materials[static_cast<std::size_t>(p.material[b])].name);
      if (!law.bonded || law.gap < 0.0) continue;
      Vec3 d = p.x[b] - p.x[a];
      const DomainParams& dom = model.params.domain;
      for (int c = 0; c < 3; ++c)
        if (dom.periodic[static_cast<std::size_t>(c)]) {
          const double period = dom.max[c] - dom.min[c];
          d[c] -= period * std::round(d[c] / period);
        }
      if (norm(d) - p.radius[a] - p.radius[b] >= law.gap) continue;
      if (p.fixed[a] && p.fixed[b]) continue;
      if (p.body[a] != kNoBody && p.body[a] == p.body[b]) continue;
      const bool order = p.id[a] < p.id[b];
      out.push_back({static_cast<std::uint32_t>(order ? a : b), static_cast<std::uint32_t>(order ? b : a)});
    }
  for (const ListedBond& l : bp.listed) {
    std::size_t a = p.size(), b = p.size();
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (p.id[k] == l.id_i) a = k;
      if (p.id[k] == l.id_j) b = k;
    }
    if (a == p.size() || b == p.size()) continue;
    if (p.id[a] > p.id[b]) std::swap(a, b);
    out.push_back({static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
  }
  std::sort(out.begin(), out.end(), [&](const MadeBond& x, const MadeBond& y) {
    return std::pair(p.id[x.i], p.id[x.j]) < std::pair(p.id[y.i], p.id[y.j]);
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const MadeBond& x, const MadeBond& y) { return x.i == y.i && x.j == y.j; }),
            out.end());
  return out;
}

}  // namespace mpdem
