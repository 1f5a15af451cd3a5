#include "contact/bond_making.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/input_error.hpp"
#include "neighbor/cell_grid.hpp"
#include "parallel/periodic_images.hpp"

namespace mpdem {

namespace {

// The periodic axes of the scene's domain and their periods (m; 0 along the other axes).
struct Periodic {
  std::array<bool, 3> axis{};
  Vec3 min{}, period{};
  explicit Periodic(const DomainParams& d) {
    if (!d.bounded) return;
    axis = d.periodic;
    min = d.min;
    period = PeriodicImages(d).period();
  }
  bool on(int c) const { return axis[static_cast<std::size_t>(c)]; }
  // x - y as its nearest image.
  Vec3 difference(const Vec3& x, const Vec3& y) const { return nearest_image(x - y, period); }
  // x moved into [min, max) along the periodic axes.
  Vec3 wrapped(Vec3 x) const {
    for (int c = 0; c < 3; ++c)
      if (on(c)) {
        double t = std::fmod(x[c] - min[c], period[c]);
        if (t < 0.0) t += period[c];
        x[c] = min[c] + (t < period[c] ? t : 0.0);
      }
    return x;
  }
};

bool by_ids(const Particles& p, const MadeBond& a, const MadeBond& b) {
  return p.id[a.i] != p.id[b.i] ? p.id[a.i] < p.id[b.i] : p.id[a.j] < p.id[b.j];
}

MadeBond oriented(const Particles& p, std::size_t i, std::size_t j) {
  return p.id[i] < p.id[j] ? MadeBond{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)}
                           : MadeBond{static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i)};
}

// Whether a bond between i and j could ever act (held: held_fixed's mask).
bool can_act(const Particles& p, const std::vector<std::uint8_t>& held, std::size_t i, std::size_t j) {
  if (p.body[i] != kNoBody && p.body[i] == p.body[j]) return false;
  return !(held[i] && held[j]);
}

}  // namespace

double bond_length(const Model& model, const Particles& p, std::uint32_t i, std::uint32_t j) {
  return norm(Periodic(model.params.domain).difference(p.x[j], p.x[i]));
}

std::vector<MadeBond> gap_bonds(const Model& model, const Particles& p) {
  const std::size_t n = p.size(), nm = model.materials.size();
  if (!model.params.bonds.enabled() || n < 2) return {};
  const std::vector<BondLaw> laws = bond_laws(model);
  double reach = -1.0;  // m, the largest gap of a pair the gap rule bonds
  for (const BondLaw& l : laws)
    if (l.bonded) reach = std::max(reach, l.gap);
  if (reach < 0.0) return {};
  double r_max = 0.0;  // m
  for (std::size_t i = 0; i < n; ++i) r_max = std::max(r_max, p.radius[i]);
  // Two centres the rule may bond are closer than this (m): one cell and its neighbours hold them.
  const double cutoff = 2.0 * r_max + reach;
  const Periodic per(model.params.domain);
  std::vector<Vec3> x(n);  // m, centres wrapped into the periodic cell [N]
  for (std::size_t i = 0; i < n; ++i) x[i] = per.wrapped(p.x[i]);
  CellGrid grid;
  grid.build(x, cutoff);
  const std::vector<std::uint8_t> held = held_fixed(p);
  std::vector<MadeBond> out;
  std::vector<std::uint32_t> near;  // candidates j > i of particle i
  for (std::size_t i = 0; i < n; ++i) {
    // The images of i that may reach across a periodic face: shifts by one period per axis.
    std::array<std::array<double, 3>, 3> shifts{};
    std::array<int, 3> count{1, 1, 1};
    for (int c = 0; c < 3; ++c) {
      if (!per.on(c)) continue;
      if (x[i][c] - per.min[c] < cutoff) shifts[c][count[c]++] = per.period[c];
      if (per.min[c] + per.period[c] - x[i][c] < cutoff) shifts[c][count[c]++] = -per.period[c];
    }
    near.clear();
    for (int a = 0; a < count[0]; ++a)
      for (int b = 0; b < count[1]; ++b)
        for (int c = 0; c < count[2]; ++c) {
          const CellCoord cc = grid.coord_of(x[i] + Vec3{shifts[0][a], shifts[1][b], shifts[2][c]});
          for (std::int64_t dz = -1; dz <= 1; ++dz)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
              for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const std::uint32_t cell = grid.find({cc.x + dx, cc.y + dy, cc.z + dz});
                if (cell == CellGrid::kNone) continue;
                for (const std::uint32_t j : grid.cell_particles(cell))
                  if (j > i) near.push_back(j);
              }
        }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const std::uint32_t j : near) {
      const BondLaw& law = laws[static_cast<std::size_t>(p.material[i]) * nm + static_cast<std::size_t>(p.material[j])];
      if (!law.bonded || law.gap < 0.0 || !can_act(p, held, i, j)) continue;
      const double gap = norm(per.difference(x[j], x[i])) - p.radius[i] - p.radius[j];  // m
      if (gap < law.gap) out.push_back(oriented(p, i, j));
    }
  }
  std::sort(out.begin(), out.end(), [&](const MadeBond& a, const MadeBond& b) { return by_ids(p, a, b); });
  return out;
}

std::vector<MadeBond> listed_bonds(const Model& model, const Particles& p) {
  const BondParams& bonds = model.params.bonds;
  if (!bonds.enabled() || bonds.listed.empty()) return {};
  std::unordered_map<std::int64_t, std::uint32_t> index;  // particle id -> index
  index.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) index.emplace(p.id[i], static_cast<std::uint32_t>(i));
  const std::vector<BondLaw> laws = bond_laws(model);
  const std::size_t nm = model.materials.size();
  const std::vector<std::uint8_t> held = held_fixed(p);
  std::vector<MadeBond> out;
  for (const ListedBond& b : bonds.listed) {
    const auto i = index.find(b.id_i), j = index.find(b.id_j);
    if (i == index.end() || j == index.end())
      throw InputError(bonds.file.string(), b.line, i == index.end() ? "id_i" : "id_j",
                       "no particle has id " + std::to_string(i == index.end() ? b.id_i : b.id_j));
    const std::size_t mi = static_cast<std::size_t>(p.material[i->second]);
    const std::size_t mj = static_cast<std::size_t>(p.material[j->second]);
    if (laws[mi * nm + mj].bonded && can_act(p, held, i->second, j->second))
      out.push_back(oriented(p, i->second, j->second));
  }
  std::sort(out.begin(), out.end(), [&](const MadeBond& a, const MadeBond& b) { return by_ids(p, a, b); });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<MadeBond> bond_union(const Particles& p, std::vector<MadeBond> a, const std::vector<MadeBond>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end(), [&](const MadeBond& x, const MadeBond& y) { return by_ids(p, x, y); });
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

std::vector<MadeBond> make_bonds(const Model& model, const Particles& p) {
  return bond_union(p, gap_bonds(model, p), listed_bonds(model, p));
}

}  // namespace mpdem
