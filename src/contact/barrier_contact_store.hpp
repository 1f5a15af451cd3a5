#pragma once
// BarrierContactStore: the per-contact records of BarrierContacts, held only for "active"
// particles - those with broad-phase candidate elements, or with records worth keeping - so the
// memory follows the number of contacts near the barriers, not the number of particles.
//
// Layout (rebuilt by relayout() whenever the broad phase was rebuilt): the active particles in
// ascending order; active particle k owns the slot range [begin(k), begin(k + 1)) of capacity
// min(kSlots, max(candidates, kept records)) - a particle touches at most one element per
// candidate - in four parallel arrays: committed history, tentative history (the evaluation in
// progress), the first iteration's stick/slip decisions, and the loads on the elements. Records
// are packed from the start of the range, in the order of detection (ascending element).
//
// Records move with their particle: permute() and compact() only renumber the particle indices
// of the active list; the next relayout() merges the renumbered records into the new layout
// (O(active + candidates), plus O(N) for the renumbering itself). Committed history and the
// first-iteration decisions are carried (a rebuild may happen between two iterations of a step);
// tentative history and loads belong to one evaluation and are not.
#include <type_traits>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "core/binary_stream.hpp"
#include "neighbor/barrier_broadphase.hpp"

namespace mpdem {

struct BarrierSlot {          // history of one contact (no padding: checkpoints copy its bytes)
  std::int32_t element = -1;  // barrier element index
  std::uint32_t slipped = 0;  // 1 when the Coulomb limit was hit
  Vec3 spring;                // m, tangential spring
  Vec3 vt0;                   // m/s, tangential velocity (start of the next step)
  Vec3 normal;                // -, contact normal (towards the particle)
  Vec3 wr0;                   // rad/s, the particle's rotation (start of the next step, rolling law)
  std::uint32_t state = 0;    // cohesion: kLawFormed | kBridgeFormed (contact/cohesive_contact.hpp)
  std::uint32_t unused = 0;   // (padding, written as zero)
};
// Checkpoints hold these records byte for byte: a layout change is a format change.
static_assert(sizeof(BarrierSlot) == 112 && std::is_trivially_copyable_v<BarrierSlot>,
              "BarrierSlot changed: bump kCheckpointFormat (io/checkpoint_format.hpp) and this size");

struct BarrierLoad {          // one contact's action on its element
  Vec3 force;                 // N, on the element
  Vec3 point;                 // m, contact point
  double overlap = 0.0;       // m
  std::int32_t element = -1;  // barrier element index
};

struct BarrierFirst {         // the first iteration's stick/slip decision of one contact
  std::int32_t element = -1;  // barrier element index
  std::uint32_t slipped = 0;  // 1 when the contact slipped
};

class BarrierContactStore {
 public:
  static constexpr int kSlots = 8;               // simultaneous barrier contacts per particle
  static constexpr std::uint32_t kGroup = 1024;  // particles per reduction group (see groups())

  // True when the layout does not match the broad phase (rebuilt, or records renumbered).
  bool stale(const BarrierBroadphase& broad) const { return dirty_ || generation_ != broad.generation(); }
  // New layout for the broad phase's current lists, carrying the kept records.
  void relayout(const BarrierBroadphase& broad);
  // Particles were reordered: new index k holds the old particle order[k].
  void permute(const std::vector<std::uint32_t>& order);
  // Particles with keep[i] == 0 were removed; the others keep their order.
  void compact(const std::vector<char>& keep);
  // The tentative history of the last evaluation becomes the committed history.
  void commit();

  // Checkpoints: the committed history, keyed by particle index (independent of the layout).
  void save(BinaryWriter& w) const;
  void restore(BinaryReader& r, std::size_t particles);
  std::size_t bytes() const;  // memory held by the store (capacities)

  // --- the layout (valid when !stale) ---
  std::size_t size() const { return active_.size(); }  // active particles A
  std::uint32_t particle(std::size_t k) const { return active_[k]; }
  std::size_t capacity(std::size_t k) const { return begin_[k + 1] - begin_[k]; }  // slots of k
  // Reduction groups: the active particles whose indices fall in one block of kGroup particles,
  // group g = [group_begin(g), group_begin(g + 1)). Sums over contacts formed per group in
  // particle order, then over groups in order, equal deterministic_sums' blocked sums.
  std::size_t groups() const { return group_.size() - 1; }
  std::size_t group_begin(std::size_t g) const { return group_[g]; }
  // Active particles that have element e among their candidates, ascending (element loads are
  // summed over them in particle order).
  std::size_t elements() const { return elem_offset_.size() - 1; }
  const std::uint32_t* element_users(std::size_t e, std::size_t& count) const {
    count = elem_offset_[e + 1] - elem_offset_[e];
    return elem_user_.data() + elem_offset_[e];
  }

  // Records of active particle k (pointers to its slot range) and their counts.
  const BarrierSlot* committed(std::size_t k) const { return committed_.data() + begin_[k]; }
  BarrierSlot* tentative(std::size_t k) { return tentative_.data() + begin_[k]; }
  BarrierFirst* first(std::size_t k) { return first_.data() + begin_[k]; }
  BarrierLoad* loads(std::size_t k) { return loads_.data() + begin_[k]; }
  const BarrierLoad* loads(std::size_t k) const { return loads_.data() + begin_[k]; }
  std::uint8_t& committed_used(std::size_t k) { return committed_used_[k]; }
  std::uint8_t& tentative_used(std::size_t k) { return tentative_used_[k]; }
  std::uint8_t& first_used(std::size_t k) { return first_used_[k]; }
  std::uint8_t& load_used(std::size_t k) { return load_used_[k]; }
  std::uint8_t load_used(std::size_t k) const { return load_used_[k]; }

  static constexpr std::uint32_t kGone = 0xffffffffu;  // particle index of a removed particle

 private:
  std::vector<std::uint32_t> active_;          // [A] particle indices (ascending unless dirty_)
  std::vector<std::uint32_t> begin_{0};        // [A + 1] slot ranges
  std::vector<std::uint32_t> group_{0};        // [groups + 1] positions in active_
  std::vector<std::uint32_t> elem_offset_{0};  // [M + 1] CSR of elem_user_
  std::vector<std::uint32_t> elem_user_;       // [candidates of active particles] positions in active_
  std::vector<BarrierSlot> committed_;         // [slots]
  std::vector<BarrierSlot> tentative_;         // [slots]
  std::vector<BarrierFirst> first_;            // [slots]
  std::vector<BarrierLoad> loads_;             // [slots] of the last evaluation
  std::vector<std::uint8_t> committed_used_;   // [A] records in committed_
  std::vector<std::uint8_t> tentative_used_;   // [A] records in tentative_
  std::vector<std::uint8_t> first_used_;       // [A] records in first_
  std::vector<std::uint8_t> load_used_;        // [A] records in loads_
  bool dirty_ = true;                          // records renumbered or restored since the layout
  bool sorted_ = true;                         // active_ ascending (false after permute)
  std::uint64_t generation_ = 0;               // broad-phase build of the layout
};

}  // namespace mpdem
