#include "state/barrier_topology.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace mpdem {
namespace {

// Bit pattern for exact comparison; -0.0 and +0.0 are the same coordinate.
std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); }

using LawKey = std::array<std::uint64_t, 15>;

// The translation's fields, the rotation law's index (equal index <=> equal RotationLaw) and the
// activity window and time origin: elements that can switch on and off apart are separate bodies,
// so an edge contact is not given up to a neighbour that may be switched off.
LawKey law_key(const MotionLaw& m, std::int32_t rotation) {
  return {bits(m.a.x),         bits(m.a.y),          bits(m.a.z),
          bits(m.A.x),         bits(m.A.y),          bits(m.A.z),
          bits(m.w1),          bits(m.B.x),          bits(m.B.y),
          bits(m.B.z),         bits(m.w2),           static_cast<std::uint64_t>(static_cast<std::int64_t>(rotation)),
          bits(m.active_from), bits(m.active_until), bits(m.since)};
}

// Motion class per element: equal classes <=> identical MotionLaw fields. Sorting, not pairwise.
std::vector<std::int32_t> motion_classes(const Barriers& bars) {
  const std::size_t m = bars.size();
  std::vector<LawKey> keys(m);
  for (std::size_t e = 0; e < m; ++e) keys[e] = law_key(bars.motion[e], bars.rotation_of[e]);
  std::vector<std::int32_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::int32_t i, std::int32_t j) { return std::tie(keys[i], i) < std::tie(keys[j], j); });
  std::vector<std::int32_t> cls(m);
  std::int32_t next = -1;
  for (std::size_t r = 0; r < m; ++r) {
    if (r == 0 || keys[order[r]] != keys[order[r - 1]]) ++next;
    cls[order[r]] = next;
  }
  return cls;
}

// Turns per-item group ids (items sorted by group) into CSR offsets.
std::vector<std::int32_t> csr_start(std::size_t groups, const std::vector<std::int32_t>& count) {
  std::vector<std::int32_t> start(groups + 1, 0);
  for (std::size_t g = 0; g < groups; ++g) start[g + 1] = start[g] + count[g];
  return start;
}

}  // namespace

BarrierTopology BarrierTopology::build(const Barriers& bars) {
  const std::size_t m = bars.size();
  if (3 * m >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::length_error("BarrierTopology: too many barrier elements for 32-bit ids");
  BarrierTopology t;
  t.elem_class = motion_classes(bars);
  t.elem_size.resize(m);
  for (std::size_t e = 0; e < m; ++e)
    t.elem_size[e] = std::sqrt(
        std::max({norm2(bars.p1[e] - bars.p0[e]), norm2(bars.p2[e] - bars.p1[e]), norm2(bars.p0[e] - bars.p2[e])}));

  // --- weld corners: sort (class, x, y, z, corner slot); equal keys share a global vertex
  struct Corner {
    std::int32_t cls;
    std::uint64_t x, y, z;
    std::int32_t slot;  // 3e + k
  };
  auto corner_pos = [&](std::size_t slot) -> const Vec3& {
    const std::size_t e = slot / 3;
    const std::size_t k = slot % 3;
    return k == 0 ? bars.p0[e] : (k == 1 ? bars.p1[e] : bars.p2[e]);
  };
  std::vector<Corner> corners(3 * m);
  for (std::size_t s = 0; s < 3 * m; ++s) {
    const Vec3& p = corner_pos(s);
    corners[s] = {t.elem_class[s / 3], bits(p.x), bits(p.y), bits(p.z), static_cast<std::int32_t>(s)};
  }
  auto same_point = [](const Corner& a, const Corner& b) {
    return a.cls == b.cls && a.x == b.x && a.y == b.y && a.z == b.z;
  };
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) {
    return std::tie(a.cls, a.x, a.y, a.z, a.slot) < std::tie(b.cls, b.x, b.y, b.z, b.slot);
  });
  t.elem_vertex.resize(3 * m);
  std::vector<std::int32_t> vcount;
  for (std::size_t r = 0; r < corners.size(); ++r) {
    if (r == 0 || !same_point(corners[r], corners[r - 1])) {
      t.vertex_rest.push_back(corner_pos(static_cast<std::size_t>(corners[r].slot)));
      vcount.push_back(0);
    }
    t.elem_vertex[corners[r].slot] = static_cast<std::int32_t>(t.vertex_rest.size() - 1);
    ++vcount.back();
  }
  const std::size_t nv = t.vertex_rest.size();
  // Corners are sorted by slot within a vertex, so the element lists come out ascending.
  t.vertex_elem_start = csr_start(nv, vcount);
  t.vertex_elem.resize(3 * m);
  for (std::size_t r = 0; r < corners.size(); ++r) t.vertex_elem[r] = corners[r].slot / 3;

  // --- edges: sort (lo, hi, slot); equal vertex pairs share a global edge
  struct EdgeSlot {
    std::int32_t lo, hi, slot;
  };
  std::vector<EdgeSlot> es(3 * m);
  for (std::size_t e = 0; e < m; ++e)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t va = t.elem_vertex[3 * e + k];
      const std::int32_t vb = t.elem_vertex[3 * e + (k + 1) % 3];
      es[3 * e + k] = {std::min(va, vb), std::max(va, vb), static_cast<std::int32_t>(3 * e + k)};
    }
  std::sort(es.begin(), es.end(), [](const EdgeSlot& a, const EdgeSlot& b) {
    return std::tie(a.lo, a.hi, a.slot) < std::tie(b.lo, b.hi, b.slot);
  });
  t.elem_edge.resize(3 * m);
  std::vector<std::int32_t> ecount;
  for (std::size_t r = 0; r < es.size(); ++r) {
    if (r == 0 || es[r].lo != es[r - 1].lo || es[r].hi != es[r - 1].hi) {
      t.edge_vertex.push_back(es[r].lo);
      t.edge_vertex.push_back(es[r].hi);
      ecount.push_back(0);
    }
    t.elem_edge[es[r].slot] = static_cast<std::int32_t>(ecount.size() - 1);
    ++ecount.back();
  }
  const std::size_t ne = ecount.size();
  t.edge_elem_start = csr_start(ne, ecount);
  t.edge_elem.resize(3 * m);
  for (std::size_t r = 0; r < es.size(); ++r) t.edge_elem[r] = es[r].slot / 3;
  // An element never holds an edge twice (its three vertices differ), so lists have no repeats.

  // --- vertex -> incident edges (each edge once), filled in edge order so lists are ascending
  std::vector<std::int32_t> deg(nv, 0);
  for (std::size_t g = 0; g < ne; ++g) {
    ++deg[t.edge_vertex[2 * g]];
    ++deg[t.edge_vertex[2 * g + 1]];
  }
  t.vertex_edge_start = csr_start(nv, deg);
  t.vertex_edge.resize(2 * ne);
  std::vector<std::int32_t> fill(t.vertex_edge_start.begin(), t.vertex_edge_start.end() - 1);
  for (std::size_t g = 0; g < ne; ++g) {
    t.vertex_edge[fill[t.edge_vertex[2 * g]]++] = static_cast<std::int32_t>(g);
    t.vertex_edge[fill[t.edge_vertex[2 * g + 1]]++] = static_cast<std::int32_t>(g);
  }
  return t;
}

}  // namespace mpdem
