#pragma once
// NeighborSearch: the Verlet pair list and the barrier candidate lists of a run, rebuilt only
// when needed (physics.md section 11): when the largest particle displacement plus the largest
// barrier displacement since the last build exceeds skin/2. Also the transposed pair index used
// to gather pair forces deterministically.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/binary_stream.hpp"
#include "neighbor/barrier_broadphase.hpp"
#include "neighbor/pair_blocks.hpp"
#include "parallel/periodic_images.hpp"
#include "neighbor/verlet_list.hpp"
#include "parallel/body_ownership.hpp"
#include "parallel/halo_exchange.hpp"
#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

class NeighborSearch {
 public:
  // skin [m] > 0; extra_range [m] >= 0 adds to the contact range (near-field cutoff); the
  // domain's periodic axes get ghost images (periodic_images.hpp), in a band widened by
  // member_offset [m] >= 0, the largest offset of a clump member from its body's centre.
  NeighborSearch(double skin, double extra_range, const DomainParams& domain = {}, double member_offset = 0.0)
      : skin_(skin), extra_(extra_range), member_offset_(member_offset), images_(domain) {}

  // A run over several ranks (docs/parallel.md): the ghosts are the halo of the neighbouring
  // bricks (and the periodic images, through the same exchange) instead of PeriodicImages.
  // Every build is then collective: all ranks rebuild together. `temperatures`: the ghosts'
  // temperatures and heat flows cross too (heat transfer on). `body_margin` (m): what the halo's
  // reach grows by for clumps, twice the largest distance of a member from its body's centre (a
  // member, owned with its body, lies beyond its brick's face by up to that distance, and so may
  // the neighbour's; docs/parallel.md "Clumps").
  void decompose(const Communicator& comm, BrickGrid grid, bool temperatures, double body_margin = 0.0);
  const HaloExchange* halo() const { return halo_.get(); }
  // Several ranks, between steps: moves the brick cuts to balance `cost` (this rank's, spread over
  // its owned particles; parallel/load_balance.hpp), keeping every brick wider than the halo of
  // the last build. True when a cut moved: then rebuild with migration. Collective.
  // A member's cost counts where its body's centre is (the body's owner).
  bool shift_cuts(const Particles& p, double cost) {
    return halo_ && halo_->shift_cuts(owner_points(p), cost, halo_width_);
  }
  // Sends the owned particles that left this rank's brick to their new owners (between steps,
  // no ghosts held), with the records in `attached` whose anchor id leaves (particle ids), and
  // those in `body_attached` whose anchor body leaves (body ids; HaloExchange::migrate).
  void migrate(Particles& p, std::span<AttachedRecords* const> attached,
               std::span<AttachedRecords* const> body_attached = {}) {
    if (halo_) halo_->migrate(p, attached, body_attached);
  }

  // The particles changed in count (or lost their ghosts) since the build, or moved too far.
  bool needs_rebuild(const Particles& p, const Barriers& b) const;
  // The same, for the owned particles' largest squared displacement from the build positions
  // max2 (m^2), measured by the pass that wrote p.x (the trapezoidal rule's predictor and updates).
  bool needs_rebuild(const Particles& p, const Barriers& b, double max2) const;
  bool stale(const Particles& p) const {
    return list_.owned() != p.size() || (halo_ ? halo_->size() : images_.size()) != p.n_ghost;
  }
  // Builds the lists for the current positions, replacing p's ghosts by new ones. after_list,
  // when given, runs once the pairs are listed, before the list stores its build positions and
  // before the barrier candidates and pair blocks are built: what it allocates (the new contact
  // history) does not meet them (peak memory).
  void rebuild(Particles& p, const Barriers& b, const std::function<void()>& after_list = {});
  // Whether compact() may stand for a rebuild after particles are removed: no ghosts (their
  // sources would move) and lists built for the present particles, still valid.
  bool compactable(const Particles& p) const;
  // Removes the particles whose keep[i] is 0 from the lists (before p is compacted): the others
  // keep their build positions, pairs and candidates, in order; what a build at the build
  // positions would list. Returns the old pair slot of every kept slot, ascending.
  std::vector<std::uint32_t> compact(const std::vector<char>& keep);
  // Frees what a rebuild recomputes and reading the old pairs does not need - the build
  // positions, barrier candidates, pair blocks and transposed index - before the old contact
  // history is carried out (peak memory). Until the next rebuild only pairs() may be read.
  void release_for_rebuild();
  // Wraps the owned particles into the periodic domain (between steps only; then rebuild).
  void wrap(Particles& p) const { images_.wrap(p); }
  // Copies the owned particles' state onto their ghosts (every evaluation) ...
  void refresh_ghosts(Particles& p) const {
    if (halo_) halo_->refresh(p);
    else images_.refresh(p);
  }
  // ... and adds the ghosts' forces, torques and heat flows to their owners after it.
  void fold_ghosts(Particles& p) const {
    if (halo_) halo_->fold(p);
    else images_.fold(p);
  }
  const PeriodicImages& images() const { return images_; }
  // Checkpoints: the build positions of both lists, so a resumed run rebuilds at the same steps
  // (and with the same ghosts).
  void save(BinaryWriter& w) const { save(w, std::span<const Vec3>(list_.build_positions()).first(list_.owned())); }
  // The same section for other particles (a decomposed run's, gathered): their build positions (m).
  void save(BinaryWriter& w, std::span<const Vec3> build_positions) const;
  // keep: only the particles i with keep[i] stay (p is compacted; a resume on several ranks
  // keeps those of this rank's brick).
  void restore(BinaryReader& r, Particles& p, const Barriers& b, const std::vector<char>* keep = nullptr);
  // Permutation sorting the particles along a space-filling curve (for cache locality).
  std::vector<std::uint32_t> spatial_order(const Particles& p) const;

  // The transposed pair index (incoming) costs 4 bytes per pair; it is built only for
  // the laws that gather per-slot values (heat conduction, near field). Takes effect at the
  // next rebuild.
  void set_incoming_index(bool on) { want_incoming_ = on; }

  const VerletList& pairs() const { return list_; }
  const PairBlocks& blocks() const { return blocks_; }
  const BarrierBroadphase& barrier_candidates() const { return broad_; }
  // Pair slots k (into pairs().indices()) whose second member is particle j, ascending
  // (set_incoming_index(true) only).
  std::span<const std::uint32_t> incoming(std::size_t j) const {
    return {in_slot_.data() + in_offset_[j], in_offset_[j + 1] - in_offset_[j]};
  }
  std::uint64_t rebuilds() const { return rebuilds_; }
  // Changes with every build (also a checkpoint restore): the particle order may have changed,
  // so caches indexed by particle must be refreshed.
  std::uint64_t generation() const { return generation_; }
  double skin() const { return skin_; }
  // m, >= 0: the barrier candidates reach this far beyond the particles' surfaces too (cohesion:
  // contacts that hold across a gap, contact/cohesion_reach.hpp); from the next build on.
  void set_barrier_gap(double gap) { barrier_gap_ = gap; }

 private:
  // The particles or elements changed in count (or lost their ghosts) since the build.
  bool lists_mismatch(const Particles& p, const Barriers& b) const;

  double skin_;
  double barrier_gap_ = 0.0;  // m, see set_barrier_gap
  double extra_;
  double member_offset_;  // m, widens the periodic images' band (clump members outside the period)
  PeriodicImages images_;
  std::unique_ptr<HaloExchange> halo_;  // several ranks: the ghosts' source instead of images_
  double halo_width_ = 0.0;             // m, the halo's reach at the last build (several ranks)
  double body_margin_ = 0.0;            // m, added to the halo's reach for clumps (decompose)
  std::uint64_t rebuilds_ = 0;
  std::uint64_t generation_ = 0;
  std::vector<Vec3> barrier_offsets_build_;  // [M] m, barrier offsets at the last build
  bool rotating_build_ = false;              // the barriers rotate (their build time is checkpointed)
  double barrier_time_build_ = 0.0;          // s, Barriers::time at the last build
  VerletList list_;
  BarrierBroadphase broad_;
  PairBlocks blocks_;
  bool want_incoming_ = false;
  std::vector<std::size_t> in_offset_;  // [N+1] CSR offsets of the transposed index (ghosts included)
  std::vector<std::uint32_t> in_slot_;  // [pairs] slots, grouped by second member

  // Builds for the owned particles' positions x_owned [N] (m): ghosts, lists, candidates.
  void build(Particles& p, std::span<const Vec3> x_owned, const Barriers& b,
             const std::function<void()>& after_list = {});
  void index_incoming();  // the transposed pair index, when wanted
};

}  // namespace mpdem
