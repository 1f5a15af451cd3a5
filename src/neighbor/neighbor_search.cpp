#include "neighbor/neighbor_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/release.hpp"
#include "neighbor/size_levels.hpp"
#include "neighbor/spatial_order.hpp"

namespace mpdem {

bool NeighborSearch::lists_mismatch(const Particles& p, const Barriers& b) const {
  return stale(p) || list_.size() != p.size_with_ghosts() || broad_.num_elements() != b.size();
}

bool NeighborSearch::needs_rebuild(const Particles& p, const Barriers& b) const {
  if (lists_mismatch(p, b)) return true;
  // One pass over the particles: the barrier rule needs the displacement itself.
  if (b.size() == 0) return list_.needs_rebuild(p.x);
  return broad_.needs_rebuild(b, list_.max_displacement(p.x));
}

bool NeighborSearch::needs_rebuild(const Particles& p, const Barriers& b, double max2) const {
  if (lists_mismatch(p, b)) return true;
  if (b.size() == 0) return list_.needs_rebuild(max2);
  return !list_.built() || broad_.needs_rebuild(b, std::sqrt(max2));  // max_displacement's value
}

void NeighborSearch::rebuild(Particles& p, const Barriers& b, const std::function<void()>& after_list) {
  p.drop_ghosts();
  build(p, p.x, b, after_list);
  ++rebuilds_;
}

void NeighborSearch::release_for_rebuild() {
  list_.release_build_positions();
  broad_.release_candidates();
  blocks_.clear();
  release(in_offset_);
  release(in_slot_);
}

void NeighborSearch::save(BinaryWriter& w, std::span<const Vec3> build_positions) const {
  w.vector(std::vector<Vec3>(build_positions.begin(), build_positions.end()));
  w.vector(barrier_offsets_build_);
  w.value(rebuilds_);
  // Only scenes with rotating barriers: their placement at the build needs the time too.
  if (rotating_build_) w.value(barrier_time_build_);
}

void NeighborSearch::restore(BinaryReader& r, Particles& p, const Barriers& b, const std::vector<char>* keep) {
  p.drop_ghosts();
  std::vector<Vec3> x = r.vector<Vec3>();
  Barriers at_build = b;
  at_build.offset = r.vector<Vec3>();
  rebuilds_ = r.value<std::uint64_t>();
  if (x.size() != p.size() || at_build.offset.size() != b.size())
    throw std::runtime_error("checkpoint does not match the scene (particle or barrier count)");
  for (const Vec3& v : x)
    if (!isfinite(v)) throw std::runtime_error("a neighbour list's build position is not finite");
  for (const Vec3& v : at_build.offset)
    if (!isfinite(v)) throw std::runtime_error("a barrier offset at the last build is not finite");
  if (b.rotating()) {
    const double t = r.value<double>();  // s, the barriers' time at the last build
    if (!std::isfinite(t)) throw std::runtime_error("the barriers' time at the last build is not finite");
    at_build.turn_to(t);
  }
  if (keep) {
    if (keep->size() != x.size()) throw std::logic_error("NeighborSearch::restore: keep does not match the particles");
    std::size_t n = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if ((*keep)[i]) x[n++] = x[i];
    x.resize(n);
    p.compact(*keep);
  }
  build(p, x, at_build);
}

void NeighborSearch::decompose(const Communicator& comm, BrickGrid grid, bool temperatures, double body_margin) {
  body_margin_ = body_margin;
  halo_ = std::make_unique<HaloExchange>(comm, std::move(grid));
  halo_->temperatures(temperatures);
}

void NeighborSearch::build(Particles& p, std::span<const Vec3> x_owned, const Barriers& b,
                           const std::function<void()>& after_list) {
  ++generation_;
  const std::size_t owned = p.size();
  std::vector<Vec3> x_all;  // m, build positions of the owned particles and their ghosts
  std::span<const Vec3> x = x_owned;
  double rmax = 0.0;  // m, the largest owned radius (ghosts: images of owned particles, or halo copies)
  if (halo_ || images_.active())
    for (std::size_t i = 0; i < owned; ++i) rmax = std::max(rmax, p.radius[i]);
  if (halo_) {
    // The ghosts come with their current centres; the build positions of the owned ones may be
    // a checkpoint's, so the list is built over those and the ghosts' own.
    x_all.assign(x_owned.begin(), x_owned.end());
    rmax = halo_->comm().max(rmax);  // a ghost may be larger than every owned particle
    halo_width_ = periodic_image_width(rmax, extra_, skin_) + body_margin_;
    halo_->build(p, halo_width_);
    x_all.insert(x_all.end(), p.x.begin() + static_cast<std::ptrdiff_t>(owned), p.x.end());
    x = x_all;
  } else if (images_.active()) {
    // x_owned may be p.x, which appending the ghosts reallocates: copied first.
    x_all.assign(x_owned.begin(), x_owned.end());
    images_.select(x_all, periodic_image_width(rmax, extra_, skin_, member_offset_));
    images_.append(p);
    x_all.reserve(owned + images_.size());
    for (std::size_t g = 0; g < images_.size(); ++g) x_all.push_back(x_all[images_.source(g)] + images_.shift(g));
    x = x_all;
  }
  const std::span<const double> radius(p.radius.data(), owned);
  if (p.has_bodies()) {
    // Clumps: a body's members never interact with each other (ghosts carry their body's id).
    list_.build(x, p.radius, skin_, extra_, owned, p.id, [&] {
      list_.drop_pairs_within_groups(p.body);
      if (after_list) after_list();
    });
  } else {
    list_.build(x, p.radius, skin_, extra_, owned, p.id, after_list);
  }
  if (barrier_gap_ > 0.0) {
    std::vector<double> grown(radius.begin(), radius.end());  // m, the radii reaching the gap
    for (double& r : grown) r += barrier_gap_;
    broad_.build(x.first(owned), grown, b, skin_);
  } else {
    broad_.build(x.first(owned), radius, b, skin_);
  }
  barrier_offsets_build_ = b.offset;
  rotating_build_ = b.rotating();
  barrier_time_build_ = b.time;
  blocks_.build(list_);
  index_incoming();
}

bool NeighborSearch::compactable(const Particles& p) const {
  return !halo_ && images_.size() == 0 && p.n_ghost == 0 && list_.size() == p.size() && list_.owned() == p.size() &&
         broad_.size() == p.size() && !list_.needs_rebuild(p.x);
}

std::vector<std::uint32_t> NeighborSearch::compact(const std::vector<char>& keep) {
  ++generation_;
  std::vector<std::uint32_t> from = list_.compact(keep);
  broad_.compact(keep);
  blocks_.build(list_);
  index_incoming();
  return from;
}

void NeighborSearch::index_incoming() {
  if (!want_incoming_) {
    release(in_offset_);
    release(in_slot_);
    return;
  }
  const std::size_t n = list_.size();  // ghosts included: they are second members too
  // Transposed index: counting sort of the slots by their second member keeps them ascending.
  const auto& idx = list_.indices();
  in_offset_.assign(n + 1, 0);
  for (std::size_t k = 0; k < idx.size(); ++k) ++in_offset_[idx[k] + 1];
  for (std::size_t j = 0; j < n; ++j) in_offset_[j + 1] += in_offset_[j];
  in_slot_.resize(idx.size());
  std::vector<std::size_t> fill(in_offset_.begin(), in_offset_.end() - 1);
  for (std::size_t k = 0; k < idx.size(); ++k) in_slot_[fill[idx[k]]++] = static_cast<std::uint32_t>(k);
}

std::vector<std::uint32_t> NeighborSearch::spatial_order(const Particles& p) const {
  // Cells of the finest size level (the largest radius when all are within a factor 2): a few
  // large spheres must not coarsen the order of the many small ones.
  const std::size_t n = p.size();
  const double r = size_levels(std::span<const double>(p.radius.data(), n)).finest_r_max();
  return mpdem::spatial_order(std::span<const Vec3>(p.x.data(), n), 2.0 * r + skin_ + extra_);
}

}  // namespace mpdem
