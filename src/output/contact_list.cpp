#include "output/contact_list.hpp"

#include "contact/barrier_contacts.hpp"
#include "contact/particle_contacts.hpp"
#include "neighbor/neighbor_search.hpp"

namespace mpdem {

std::vector<ContactEntry> contact_list(const Particles& p, const Barriers& b, const Interactions& in) {
  std::vector<ContactEntry> out;
  const std::vector<PairRecord>& rec = in.particle_contacts().records();
  const NeighborSearch& search = in.search();
  const std::vector<std::uint32_t>& first = search.blocks().first_members();
  const std::vector<std::uint32_t>& second = search.pairs().indices();
  if (rec.size() == second.size()) {
    for (std::size_t k = 0; k < rec.size(); ++k) {
      const PairRecord& r = rec[k];
      if (r.live == 0) continue;
      const std::size_t i = first[k], j = second[k];
      ContactEntry e;
      e.first = p.id[i];
      e.second = p.id[j];  // a periodic image (ghost) carries its source's id
      e.normal = r.normal;
      e.overlap = r.overlap;
      e.point = p.x[i] - r.normal * (p.radius[i] - 0.5 * r.overlap);
      e.normal_force = r.normal * r.normal_force;
      e.tangential_force = r.force - e.normal_force;
      e.sliding = r.sliding != 0;
      e.first_index = i;
      e.centre = p.x[i];
      e.branch = p.x[i] - p.x[j];
      e.first_body = p.body[i];
      e.second_body = p.body[j];
      out.push_back(e);
    }
  }
  const BarrierContactStore& store = in.barrier_contacts().store();
  for (std::size_t k = 0; k < store.size(); ++k) {
    const std::uint32_t i = store.particle(k);
    if (i == BarrierContactStore::kGone) continue;
    const BarrierSlot* slot = store.committed(k);
    const BarrierLoad* load = store.loads(k);
    for (std::size_t c = 0; c < store.load_used(k); ++c) {
      ContactEntry e;
      e.first = p.id[i];
      e.element = b.id[static_cast<std::size_t>(load[c].element)];
      e.point = load[c].point;
      e.normal = slot[c].normal;
      e.overlap = load[c].overlap;
      const Vec3 f = -load[c].force;  // the load is the element's: the particle takes minus it
      e.normal_force = e.normal * dot(f, e.normal);
      e.tangential_force = f - e.normal_force;
      e.sliding = slot[c].slipped != 0;
      e.first_index = i;
      e.centre = p.x[i];
      e.branch = p.x[i] - e.point;
      e.first_body = p.body[i];
      out.push_back(e);
    }
  }
  return out;
}

}  // namespace mpdem
