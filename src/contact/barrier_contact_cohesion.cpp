// BarrierContacts with cohesion (contact/cohesive_contact.hpp, physics.md 21): detection beyond
// touching, the bridges by materials, and the formed contacts that vanished from detection.
#include <algorithm>

#include "contact/barrier_contacts.hpp"
#include "contact/cohesive_contact.hpp"

namespace mpdem {

void BarrierContacts::detect_cohesive(std::size_t i, const Particles& p, const Barriers& b,
                                      std::span<const std::uint32_t> cand, const BarrierSlot* old, int old_used,
                                      std::vector<BarrierContact>& found) const {
  detect_barrier_contacts(b, topo_, tris_, p.x[i], p.radius[i] + gap_, cand, found);
  // Apart, a contact is kept when it may take a formed record's history: the same element, or a
  // seam neighbour's (collect()'s inheritance).
  std::erase_if(found, [&](BarrierContact& f) {
    f.overlap -= gap_;
    if (f.overlap > 0.0) return false;
    for (int s = 0; s < old_used; ++s)
      if (old[s].state != 0 &&
          (old[s].element == static_cast<std::int32_t>(f.element) || dot(old[s].normal, f.normal) > kInheritCos))
        return false;
    return true;
  });
}

const BridgeLaw* BarrierContacts::bridge_of(int particle_material, int element_material) const {
  return table_.any_barrier_bridges() ? &table_.barrier_bridge(static_cast<std::size_t>(particle_material),
                                                               static_cast<std::size_t>(element_material))
                                      : nullptr;
}

// A formed neck or bridge that moved beyond the detection reach within one step broke there.
void BarrierContacts::book_undetected(int particle_material, const Barriers& b, double r, const BarrierSlot* old,
                                      int old_used, const BarrierSlot* const* taken, std::size_t count,
                                      BarrierSums& acc) const {
  for (int s = 0; s < old_used; ++s) {
    if (old[s].state == 0 || std::find(taken, taken + count, &old[s]) != taken + count) continue;
    const int e_material = b.material[static_cast<std::size_t>(old[s].element)];
    const PairLaw& law = table_.barrier_pair(static_cast<std::size_t>(particle_material),
                                             static_cast<std::size_t>(e_material));
    const auto which = static_cast<std::uint8_t>(old[s].state);
    acc[10] += (which & kLawFormed) != 0 ? 1.0 : 0.0;
    acc[11] += (which & kBridgeFormed) != 0 ? 1.0 : 0.0;
    with_law(law.law, [&]<class Law>(std::type_identity<Law>) {
      acc[12] += broken_energy<Law>(law, bridge_of(particle_material, e_material), which, r, 0.0);
    });
  }
}

}  // namespace mpdem
