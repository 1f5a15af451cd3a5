// The parallel bonds' share of the driver (contact/bonds.hpp): their breaks collected for
// bonds_broken.csv and the Python module, their records gathered for the bond VTU, and bonds
// added between steps.
#include <algorithm>
#include <string>
#include <tuple>

#include "core/input_error.hpp"
#include "output/output_manager.hpp"
#include "parallel/gather.hpp"
#include "sim/simulation.hpp"

namespace mpdem {

std::vector<BondRecord> Simulation::gathered_bonds() const {
  std::vector<BondRecord> all = gather_values<BondRecord>(*comm_, interactions_->bonds()->records(), 0);
  std::sort(all.begin(), all.end(), bond_before);
  return all;
}

void Simulation::collect_bond_breaks(bool always) {
  Bonds* bonds = interactions_->bonds();
  if (bonds == nullptr) return;
  // Several ranks: the same decision on every rank, from the count the step's collective summed.
  if (comm_ && !always && step_collective_.bond_breaks == 0) return;
  std::vector<BondBreak> breaks = bonds->take_breaks();
  if (comm_) breaks = gather_values<BondBreak>(*comm_, breaks, 0);
  if (breaks.empty()) return;
  // By time and ids: the file does not depend on the bond order or the rank count.
  std::sort(breaks.begin(), breaks.end(), [](const BondBreak& a, const BondBreak& b) {
    return std::tie(a.time, a.id_i, a.id_j) < std::tie(b.time, b.id_i, b.id_j);
  });
  if (output_) output_->bond_breaks(breaks);
  if (options_.keep_bond_breaks) bond_breaks_.insert(bond_breaks_.end(), breaks.begin(), breaks.end());
}

std::vector<BondBreak> Simulation::take_bond_breaks() {
  if (initialized_ && !comm_) collect_bond_breaks(true);  // also those of an evaluation between steps
  std::vector<BondBreak> out;
  out.swap(bond_breaks_);
  return out;
}

void Simulation::add_bond(std::int64_t a, std::int64_t b) {
  if (comm_) throw InputError("", 0, "", "adding bonds between steps is for a run on one rank");
  Bonds* bonds = interactions_->bonds();
  if (bonds == nullptr) throw InputError("", 0, "bonds", "the scene has no [bonds] section: no bond can be added");
  if (a == b) throw InputError("", 0, "id", "a bond joins two particles: both ids are " + std::to_string(a));
  const Particles& p = scene_.particles;
  const auto index = [&](std::int64_t id) {
    const auto end = p.id.begin() + static_cast<std::ptrdiff_t>(p.size());
    const auto it = std::find(p.id.begin(), end, id);
    if (it == end) throw InputError("", 0, "id", "no particle with id " + std::to_string(id));
    return static_cast<std::size_t>(it - p.id.begin());
  };
  const std::size_t i = index(a), j = index(b);
  const std::int64_t lo = std::min(a, b), hi = std::max(a, b);
  for (const BondRecord& r : bonds->records())
    if (r.id_i == lo && r.id_j == hi && r.intact)
      throw InputError("", 0, "id",
                       "particles " + std::to_string(lo) + " and " + std::to_string(hi) + " are bonded already");
  bonds->add(p, i, j);
}

}  // namespace mpdem
