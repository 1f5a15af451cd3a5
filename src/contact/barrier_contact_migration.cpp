// BarrierContacts' committed history outside the evaluations: in the checkpoint, and keyed by
// particle id for particles that change rank (parallel/halo_exchange.hpp): one record per
// contact, anchored at its particle.
#include <algorithm>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "contact/barrier_contacts.hpp"

namespace mpdem {

AttachedRecords BarrierContacts::export_records(const Particles& p) const {
  // The checkpoint form (particle indices ascending, counts, slots) read back and keyed by id.
  BinaryWriter w;
  store_.save(w);
  BinaryReader r(w.bytes().data(), w.bytes().size());
  const auto index = r.vector<std::uint32_t>();
  const auto counts = r.vector<std::uint8_t>();
  const auto slots = r.vector<BarrierSlot>();
  AttachedRecords out = AttachedRecords::of<BarrierSlot>();
  std::size_t s = 0;
  for (std::size_t k = 0; k < index.size(); ++k)
    for (std::uint8_t c = 0; c < counts[k]; ++c) out.push(p.id[index[k]], slots[s++]);
  return out;
}

namespace {
// The checkpoint form of the records (BarrierContactStore::save: particle indices ascending,
// counts, slots) from (particle index, record) pairs; a particle's records keep their order.
void write_store_form(BinaryWriter& w, std::vector<std::pair<std::uint32_t, std::size_t>> order,
                      const AttachedRecords& rec) {
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::uint32_t> index;
  std::vector<std::uint8_t> counts;
  std::vector<BarrierSlot> slots;
  for (const auto& [i, r] : order) {
    if (index.empty() || index.back() != i) {
      index.push_back(i);
      counts.push_back(0);
    }
    if (counts.back() == BarrierContactStore::kSlots) continue;  // cannot happen: a particle never holds more
    ++counts.back();
    slots.push_back(rec.get<BarrierSlot>(r));
  }
  w.vector(index);
  w.vector(counts);
  w.vector(slots);
}
}  // namespace

void BarrierContacts::import_records(const Particles& p, const AttachedRecords& rec) {
  std::unordered_map<std::int64_t, std::uint32_t> where;
  where.reserve(rec.size());
  for (std::int64_t id : rec.anchor) where.emplace(id, 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (auto it = where.find(p.id[i]); it != where.end()) it->second = static_cast<std::uint32_t>(i) + 1;
  // Records of one particle arrive together and in their order (they travelled as a block).
  std::vector<std::pair<std::uint32_t, std::size_t>> order;  // (particle index, record)
  for (std::size_t r = 0; r < rec.size(); ++r)
    if (const std::uint32_t i = where[rec.anchor[r]]; i > 0) order.emplace_back(i - 1, r);
  BinaryWriter w;
  write_store_form(w, std::move(order), rec);
  BinaryReader r(w.bytes().data(), w.bytes().size());
  store_.restore(r, p.size());
}

void BarrierContacts::save_records(BinaryWriter& w, const AttachedRecords& rec, std::span<const std::int64_t> ids,
                                   std::uint64_t overflows) {
  std::vector<std::pair<std::uint32_t, std::size_t>> order;  // (particle index, record)
  for (std::size_t r = 0; r < rec.size(); ++r) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), rec.anchor[r]);
    if (it == ids.end() || *it != rec.anchor[r])
      throw std::logic_error("BarrierContacts::save_records: a record of a particle not in the list");
    order.emplace_back(static_cast<std::uint32_t>(it - ids.begin()), r);
  }
  write_store_form(w, std::move(order), rec);
  w.value(overflows);
}

void BarrierContacts::save(BinaryWriter& w) const {
  store_.save(w);
  w.value(overflows_);
}

void BarrierContacts::restore(BinaryReader& r, std::size_t particles) {
  store_.restore(r, particles);
  overflows_ = r.value<std::uint64_t>();
}

}  // namespace mpdem
