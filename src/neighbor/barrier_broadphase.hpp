#pragma once
// Broad phase between particles and barrier triangles (physics.md sections 7 and 11).
//
// Element e is a candidate of particle i when the distance from the centre x_i to e's current
// triangle (Barriers::vertex) is at most
//     margin = R_i + (t_b,e / 2 + skin)          (evaluated in exactly this order)
// widened by kPadDist (margin + max_a |x_i,a|) against rounding. A true contact (distance < R_i +
// t_b/2) always passes. The box test first - x_i in e's vertex box expanded by margin on every
// side, for each axis a: lo_a - margin <= x_i,a <= hi_a + margin - is exact and cheap and lets
// only those through (the distance to a triangle is at least the per-axis distance to its box);
// the distance test then drops what the box keeps of a long slanted element (a hopper's cone, a
// drum's wall), whose box holds many particles far from its plane.
//
// Elements are held in a bounding-volume hierarchy (median split on the longest axis), so a
// particle's query costs ~log M and an element of any size - a 100 m floor triangle among
// millimetre grains - is found from anywhere over it; there is no per-cell binning that a huge
// element would blow up, and no O(N M) loop. Output is a CSR list per particle, ascending,
// independent of the number of threads.
//
// Rebuild rule (kept simple, shared with the particle list): rebuild both lists when
//     max particle displacement + max barrier displacement > skin / 2,
// the barrier displacement being that of the element's farthest-moved vertex when it rotates.
// The candidate test stays valid up to a combined relative motion of `skin`, so this rule keeps a
// factor-2 margin, and with still barriers it is exactly the particle list's rule.
//
// Elements switched off (Barriers::active) are left out of the hierarchy, so they cost nothing;
// an element switching on or off between builds makes max_barrier_displacement infinite, which
// forces the rebuild at the first evaluation that sees the change.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "state/barriers.hpp"

namespace mpdem {

class BarrierBroadphase {
 public:
  // x [N] m centres, radius [N] m, barriers at their current offsets, skin >= 0 m.
  // Throws std::invalid_argument for mismatched sizes, a negative skin or thickness, or
  // non-finite input.
  void build(std::span<const Vec3> x, std::span<const double> radius, const Barriers& barriers, double skin);
  // Removes the particles whose keep[i] is 0: the others keep their candidates, which stay valid
  // as long as the rebuild rule says (VerletList::compact).
  void compact(const std::vector<char>& keep);
  // Frees the per-particle candidates before a rebuild (peak memory): none until the next build.
  void release_candidates();

  std::size_t size() const { return offset_.size() - 1; }            // N at the last build
  std::size_t num_elements() const { return offset_build_.size(); }  // M at the last build
  std::size_t num_candidates() const { return index_.size(); }
  // Candidate elements of particle i, ascending.
  std::span<const std::uint32_t> candidates(std::size_t i) const {
    return {index_.data() + offset_[i], offset_[i + 1] - offset_[i]};
  }
  const std::vector<std::uint32_t>& offsets() const { return offset_; }  // [N+1]
  const std::vector<std::uint32_t>& indices() const { return index_; }   // [num_candidates]
  // Particles with at least one candidate, ascending (so per-contact work can skip the rest).
  const std::vector<std::uint32_t>& active() const { return active_; }

  // Largest displacement of an active element since the build (m): |u_e - u_e(build)|, or with
  // rotating barriers that of its vertices; +infinity if the element count or the set of active
  // elements changed.
  double max_barrier_displacement(const Barriers& barriers) const;
  // True when max_particle_displacement + max_barrier_displacement > skin/2 (or the element
  // count changed, or never built). Pass VerletList::max_displacement(x).
  bool needs_rebuild(const Barriers& barriers, double max_particle_displacement) const;

  double skin() const { return skin_; }  // m
  // Incremented by every build(), so users of the lists can tell that they changed.
  std::uint64_t generation() const { return generation_; }

 private:
  struct Node {
    Vec3 lo, hi;              // m, box of the expanded element boxes below, padded outward
    std::uint32_t first = 0;  // leaf: first slot in perm_; inner: index of the right child
    std::uint32_t count = 0;  // leaf: number of elements; inner: 0 (left child is next node)
  };
  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end, double pad_scale);

  double skin_ = 0.0;  // m
  bool built_ = false;
  std::uint64_t generation_ = 0;
  std::vector<Vec3> lo_, hi_;               // [M] m, vertex box of each element (unexpanded)
  std::vector<double> grow_;                // [M] m, t_b/2 + skin of each element
  std::vector<Vec3> centroid_;              // [M] m, box centres, for splitting
  std::vector<std::uint32_t> perm_;         // [active elements] indices in leaf order
  std::vector<Node> nodes_;                 // [< 2M] hierarchy, root at 0
  std::vector<Vec3> offset_build_;          // [M] m, barrier offsets u(t) at build
  std::vector<Vec3> vertex_build_;          // [3M] m, current vertices of each element at the build
  bool rotating_build_ = false;             // the barriers rotated at the build
  std::vector<std::uint8_t> active_build_;  // [M] -, Barriers::active at build (only when timed; else empty)
  std::vector<std::uint32_t> offset_{0};    // [N+1] CSR offsets (at most 2^32 - 1 candidates)
  std::vector<std::uint32_t> index_;        // [candidates] element indices
  std::vector<std::uint32_t> active_;       // [particles with candidates] indices, ascending
  std::vector<std::vector<std::uint32_t>> thread_buf_;
  std::vector<std::vector<std::uint32_t>> thread_active_;
  std::vector<std::size_t> active_start_;  // [threads + 1] where each thread's active particles go
};

}  // namespace mpdem
