#include "output/contact_list.hpp"

#include "contact/barrier_contacts.hpp"
#include "contact/particle_contacts.hpp"
#include "neighbor/neighbor_search.hpp"

namespace mpdem {

std::optional<ContactEntry> pair_entry(const Particles& p, std::size_t i, std::size_t j, const PairRecord& r) {
  if (r.live == 0) return std::nullopt;
  ContactEntry e;
  e.first = p.id[i];
  e.second = p.id[j];  // a periodic image (ghost) carries its source's id
  e.normal = r.normal;
  e.overlap = r.overlap;
  // R_i - overlap / 2 from i's centre: the middle of the overlap, or of the gap when overlap < 0.
  e.point = p.x[i] - r.normal * (p.radius[i] - 0.5 * r.overlap);
  e.normal_force = r.normal * r.normal_force;
  e.tangential_force = r.force - e.normal_force;
  e.sliding = r.sliding != 0;
  e.touching = (r.live & kLawFormed) != 0;
  e.bridge = (r.live & kBridgeFormed) != 0;
  e.first_index = i;
  e.centre = p.x[i];
  e.branch = p.x[i] - p.x[j];
  e.first_body = p.body[i];
  e.second_body = p.body[j];
  return e;
}

std::optional<ContactEntry> barrier_entry(const Particles& p, std::size_t i, std::int64_t element,
                                          const BarrierSlot& slot, const BarrierLoad& load) {
  const std::uint32_t live = barrier_live(slot.state, load.overlap);
  if (live == 0) return std::nullopt;
  ContactEntry e;
  e.first = p.id[i];
  e.element = element;
  e.point = load.point;  // on the barrier's surface, also across a gap
  e.normal = slot.normal;
  e.overlap = load.overlap;
  const Vec3 f = -load.force;  // the load is the element's: the particle takes minus it
  e.normal_force = e.normal * dot(f, e.normal);
  e.tangential_force = f - e.normal_force;
  e.sliding = slot.slipped != 0;
  e.touching = (live & kLawFormed) != 0;
  e.bridge = (live & kBridgeFormed) != 0;
  e.first_index = i;
  e.centre = p.x[i];
  e.branch = p.x[i] - e.point;
  e.first_body = p.body[i];
  return e;
}

std::vector<ContactEntry> contact_list(const Particles& p, const Barriers& b, const Interactions& in) {
  std::vector<ContactEntry> out;
  const std::vector<PairRecord>& rec = in.particle_contacts().records();
  const NeighborSearch& search = in.search();
  const std::vector<std::uint32_t>& first = search.blocks().first_members();
  const std::vector<std::uint32_t>& second = search.pairs().indices();
  if (rec.size() == second.size())
    for (std::size_t k = 0; k < rec.size(); ++k)
      if (const auto e = pair_entry(p, first[k], second[k], rec[k])) out.push_back(*e);
  const BarrierContactStore& store = in.barrier_contacts().store();
  for (std::size_t k = 0; k < store.size(); ++k) {
    const std::uint32_t i = store.particle(k);
    if (i == BarrierContactStore::kGone) continue;
    const BarrierSlot* slot = store.committed(k);
    const BarrierLoad* load = store.loads(k);
    for (std::size_t c = 0; c < store.load_used(k); ++c)
      if (const auto e = barrier_entry(p, i, b.id[static_cast<std::size_t>(load[c].element)], slot[c], load[c]))
        out.push_back(*e);
  }
  return out;
}

}  // namespace mpdem
