#include "neighbor/barrier_broadphase.hpp"

#include "core/release.hpp"
#include "neighbor/cell_grid.hpp"  // kNeighborParallelMin
#include "neighbor/csr_compaction.hpp"
#include "neighbor/csr_offsets.hpp"
#include "geometry/triangle_closest_point.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace mpdem {

namespace {

constexpr std::uint32_t kLeafSize = 4;
// Node boxes are padded outward by this relative amount so that rounding in the node test can
// never reject an element the exact per-element test would accept (node test is conservative).
constexpr double kPadRel = 1e-12;
// The distance test is widened by this relative amount (header), far above the rounding of the
// closest point (~1e-16 of the coordinates) and far below any skin.
constexpr double kPadDist = 1e-9;

Vec3 vmin(const Vec3& a, const Vec3& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
Vec3 vmax(const Vec3& a, const Vec3& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }

// The documented candidate test (header): lo - margin <= x <= hi + margin on every axis.
bool in_expanded_box(const Vec3& p, const Vec3& lo, const Vec3& hi, double margin) {
  return p.x >= lo.x - margin && p.x <= hi.x + margin && p.y >= lo.y - margin && p.y <= hi.y + margin &&
         p.z >= lo.z - margin && p.z <= hi.z + margin;
}

// The documented distance test (header): |x - closest point of triangle abc| <= margin, widened.
bool within_distance(const Vec3& p, const Vec3* abc, double margin) {
  const double scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const double lim = margin + kPadDist * (margin + scale);
  return norm2(closest_point_on_triangle(p, abc[0], abc[1], abc[2]).point - p) <= lim * lim;
}

}  // namespace

std::uint32_t BarrierBroadphase::build_node(std::uint32_t begin, std::uint32_t end, double pad_scale) {
  const std::uint32_t me = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  Vec3 clo = lo, chi = hi;
  for (std::uint32_t k = begin; k < end; ++k) {
    const std::uint32_t e = perm_[k];
    const Vec3 g{grow_[e], grow_[e], grow_[e]};
    lo = vmin(lo, lo_[e] - g);
    hi = vmax(hi, hi_[e] + g);
    clo = vmin(clo, centroid_[e]);
    chi = vmax(chi, centroid_[e]);
  }
  const auto pad = [pad_scale](double v) { return kPadRel * (std::abs(v) + pad_scale); };
  nodes_[me].lo = {lo.x - pad(lo.x), lo.y - pad(lo.y), lo.z - pad(lo.z)};
  nodes_[me].hi = {hi.x + pad(hi.x), hi.y + pad(hi.y), hi.z + pad(hi.z)};
  if (end - begin <= kLeafSize) {
    nodes_[me].first = begin;
    nodes_[me].count = end - begin;
    return me;
  }
  // Median split along the longest axis of the centroids; ties broken by element index so the
  // tree (and thus nothing observable, but also the work) is deterministic.
  const Vec3 ext = chi - clo;
  const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(perm_.begin() + begin, perm_.begin() + mid, perm_.begin() + end,
                   [this, axis](std::uint32_t a, std::uint32_t b) {
                     const double ca = centroid_[a][axis], cb = centroid_[b][axis];
                     return ca != cb ? ca < cb : a < b;
                   });
  build_node(begin, mid, pad_scale);  // left child is me + 1
  const std::uint32_t right = build_node(mid, end, pad_scale);
  nodes_[me].first = right;
  nodes_[me].count = 0;
  return me;
}

void BarrierBroadphase::compact(const std::vector<char>& keep) {
  if (!built_ || keep.size() != size())
    throw std::logic_error("BarrierBroadphase::compact: not built, or keep does not match");
  compact_rows(offset_, index_, keep, [](std::uint32_t e) { return e; });
  const std::vector<std::uint32_t> to = kept_row_numbers(keep);
  std::size_t n = 0;
  for (const std::uint32_t i : active_)
    if (keep[i]) active_[n++] = to[i];
  active_.resize(n);
  ++generation_;
}

void BarrierBroadphase::release_candidates() {
  offset_ = std::vector<std::uint32_t>{0};
  release(index_);
  release(active_);
  built_ = false;
}

void BarrierBroadphase::build(std::span<const Vec3> x, std::span<const double> radius, const Barriers& barriers,
                              double skin) {
  const std::size_t n = x.size(), m = barriers.size();
  if (radius.size() != n) throw std::invalid_argument("barrier broad phase: positions and radii differ in size");
  if (!(skin >= 0.0) || !std::isfinite(skin)) throw std::invalid_argument("barrier broad phase: skin must be >= 0");
  if (m >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("barrier broad phase: too many barrier elements");
  skin_ = skin;

  lo_.resize(m);
  hi_.resize(m);
  grow_.resize(m);
  centroid_.resize(m);
  perm_.resize(m);
  offset_build_.assign(barriers.offset.begin(), barriers.offset.end());
  vertex_build_.resize(3 * m);
  rotating_build_ = barriers.rotating();
  const bool timed = barriers.timed();
  if (timed) active_build_.assign(barriers.active.begin(), barriers.active.end());
  else active_build_.clear();
  std::size_t live = 0;  // active elements, the only ones in the hierarchy
  double max_grow = 0.0;
  for (std::size_t e = 0; e < m; ++e) {
    const Vec3 a = barriers.vertex(e, 0), b = barriers.vertex(e, 1), c = barriers.vertex(e, 2);
    const double t = barriers.thickness[e];
    if (!isfinite(a) || !isfinite(b) || !isfinite(c) || !(t >= 0.0) || !std::isfinite(t))
      throw std::invalid_argument("barrier broad phase: element " + std::to_string(barriers.id[e]) +
                                  " has a non-finite vertex or an invalid thickness");
    vertex_build_[3 * e] = a, vertex_build_[3 * e + 1] = b, vertex_build_[3 * e + 2] = c;
    lo_[e] = vmin(vmin(a, b), c);
    hi_[e] = vmax(vmax(a, b), c);
    grow_[e] = 0.5 * t + skin;
    centroid_[e] = 0.5 * (lo_[e] + hi_[e]);
    if (!timed || barriers.active[e]) perm_[live++] = static_cast<std::uint32_t>(e);
    max_grow = std::max(max_grow, grow_[e]);
  }
  double rmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(radius[i] >= 0.0) || !std::isfinite(radius[i]) || !isfinite(x[i]))
      throw std::invalid_argument("barrier broad phase: particle " + std::to_string(i) +
                                  " has a non-finite position or an invalid radius");
    rmax = std::max(rmax, radius[i]);
  }
  perm_.resize(live);
  nodes_.clear();
  if (live > 0) build_node(0, static_cast<std::uint32_t>(live), rmax + max_grow);

  // One query per particle; each thread owns a contiguous block of particles (see VerletList).
  offset_.assign(n + 1, 0);
  bool too_many = false;
#pragma omp parallel if (n >= kNeighborParallelMin)
  {
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
    {
      if (thread_buf_.size() < nt) thread_buf_.resize(nt);
      if (thread_active_.size() < nt) thread_active_.resize(nt);
    }
    std::vector<std::uint32_t>& buf = thread_buf_[t];
    std::vector<std::uint32_t>& act = thread_active_[t];
    buf.clear();
    act.clear();
    const std::size_t lo = n * t / nt, hi = n * (t + 1) / nt;
    std::uint32_t stack[128];  // depth of a median-split tree is ~log2(M) < 33
    for (std::size_t i = lo; i < hi && !nodes_.empty(); ++i) {
      const std::size_t first = buf.size();
      const Vec3 p = x[i];
      const double r = radius[i];
      int top = 0;
      stack[top++] = 0;
      while (top > 0) {
        const Node& nd = nodes_[stack[--top]];
        if (!in_expanded_box(p, nd.lo, nd.hi, r)) continue;
        if (nd.count == 0) {
          stack[top++] = nd.first;                                             // right child
          stack[top++] = static_cast<std::uint32_t>(&nd - nodes_.data()) + 1;  // left child
          continue;
        }
        for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k) {
          const std::uint32_t e = perm_[k];
          const double margin = r + grow_[e];
          if (in_expanded_box(p, lo_[e], hi_[e], margin) && within_distance(p, &vertex_build_[3 * e], margin))
            buf.push_back(e);
        }
      }
      std::sort(buf.begin() + static_cast<std::ptrdiff_t>(first), buf.end());
      offset_[i + 1] = static_cast<std::uint32_t>(buf.size() - first);
      if (buf.size() > first) act.push_back(static_cast<std::uint32_t>(i));
    }
#pragma omp barrier
#pragma omp single
    {
      const std::optional<std::size_t> total = counts_to_offsets(offset_);
      too_many = !total;
      index_.resize(total.value_or(0));
      active_start_.assign(nt + 1, 0);
      for (std::size_t k = 0; k < nt; ++k) active_start_[k + 1] = active_start_[k] + thread_active_[k].size();
      active_.resize(active_start_[nt]);
    }
    if (!too_many) {
      std::copy(buf.begin(), buf.end(), index_.begin() + static_cast<std::ptrdiff_t>(offset_[lo]));
      std::copy(act.begin(), act.end(), active_.begin() + static_cast<std::ptrdiff_t>(active_start_[t]));
    }
  }
  if (too_many) {
    release_candidates();
    throw std::invalid_argument("barrier broad phase: more than 2^32 - 1 candidates for 32-bit offsets");
  }
  built_ = true;
  ++generation_;
}

double BarrierBroadphase::max_barrier_displacement(const Barriers& barriers) const {
  if (!built_ || barriers.size() != offset_build_.size()) return std::numeric_limits<double>::infinity();
  double m2 = 0.0;
  if (barriers.rotating() != rotating_build_) return std::numeric_limits<double>::infinity();
  // An element switched on or off since the build: the lists must follow (an O(M) compare, only
  // for scenes with activity windows). Otherwise inactive elements are in no list and ignored.
  const bool timed = barriers.timed();
  if (timed != !active_build_.empty()) return std::numeric_limits<double>::infinity();
  if (timed && !std::equal(active_build_.begin(), active_build_.end(), barriers.active.begin()))
    return std::numeric_limits<double>::infinity();
  const std::uint8_t* on = timed ? active_build_.data() : nullptr;  // null: all active
  if (barriers.rotating()) {
    // A rigid motion moves a triangle's points by an affine map: the largest move is a vertex's.
    for (std::size_t e = 0; e < barriers.size(); ++e)
      if (!on || on[e])
        for (int k = 0; k < 3; ++k) m2 = std::max(m2, norm2(barriers.vertex(e, k) - vertex_build_[3 * e + k]));
    return std::sqrt(m2);
  }
  for (std::size_t e = 0; e < barriers.size(); ++e)
    if (!on || on[e]) m2 = std::max(m2, norm2(barriers.offset[e] - offset_build_[e]));
  return std::sqrt(m2);
}

bool BarrierBroadphase::needs_rebuild(const Barriers& barriers, double max_particle_displacement) const {
  return max_particle_displacement + max_barrier_displacement(barriers) > 0.5 * skin_;
}

}  // namespace mpdem
