#include "neighbor/neighbor_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "neighbor/spatial_order.hpp"

namespace mpdem {

bool NeighborSearch::needs_rebuild(const Particles& p, const Barriers& b) const {
  if (list_.size() != p.size() || broad_.num_elements() != b.size()) return true;
  // One pass over the particles: the barrier rule needs the displacement itself.
  if (b.size() == 0) return list_.needs_rebuild(p.x);
  return broad_.needs_rebuild(b, list_.max_displacement(p.x));
}

void NeighborSearch::rebuild(const Particles& p, const Barriers& b) {
  build(p.x, p.radius, b);
  ++rebuilds_;
}

void NeighborSearch::save(BinaryWriter& w) const {
  w.vector(list_.build_positions());
  w.vector(barrier_offsets_build_);
  w.value(rebuilds_);
  // Only scenes with rotating barriers: their placement at the build needs the time too.
  if (rotating_build_) w.value(barrier_time_build_);
}

void NeighborSearch::restore(BinaryReader& r, const Particles& p, const Barriers& b) {
  const std::vector<Vec3> x = r.vector<Vec3>();
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
  build(x, p.radius, at_build);
}

void NeighborSearch::build(std::span<const Vec3> x, std::span<const double> radius, const Barriers& b) {
  ++generation_;
  list_.build(x, radius, skin_, extra_);
  broad_.build(x, radius, b, skin_);
  barrier_offsets_build_ = b.offset;
  rotating_build_ = b.rotating();
  barrier_time_build_ = b.time;
  blocks_.build(list_);
  if (!want_incoming_) {
    in_offset_ = {};
    in_slot_ = {};
    return;
  }
  const std::size_t n = x.size();
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
  double rmax = 0.0;
  for (double r : p.radius) rmax = std::max(rmax, r);
  return mpdem::spatial_order(p.x, 2.0 * rmax + skin_ + extra_);
}

}  // namespace mpdem
