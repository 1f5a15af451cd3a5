#include "physics/barrier_contact_detect.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <tuple>

namespace mpdem {
namespace {

// Sign tests treat |s| or |q| below this relative rounding allowance as "on the boundary" (see
// docs/barrier_contacts.md): the decision is then made generously (contact kept) and a possible
// duplicate is removed by the coincident-point merge below, so rounding never drops a contact.
constexpr double kRound = 64.0 * std::numeric_limits<double>::epsilon();
constexpr double kRound2 = kRound * kRound;
// Two kept contacts of one motion class closer than kMergeRel * (R + t_b/2 + element size) are the
// same physical contact (rounding-level duplicates only: real ones differ by far more).
constexpr double kMergeRel = 1e-9;

constexpr int next(int k) { return k == 2 ? 0 : k + 1; }
constexpr int prev(int k) { return k == 0 ? 2 : k - 1; }

using Tri = CurrentTriangle;

// Where detection gets an element's triangle: derived on the spot, or read from an array computed
// once per evaluation (same values either way).
struct DerivedTriangles {
  const Barriers& bars;
  Tri operator()(std::size_t e) const { return current_triangle(bars, e); }
};
struct StoredTriangles {
  std::span<const Tri> tris;  // [M]
  const Tri& operator()(std::size_t e) const { return tris[e]; }
};

struct Side {
  double s = 0.0;   // m^4, edge side (triangle_closest_point.hpp)
  double e2 = 0.0;  // m^2, squared edge length
  int sign = 0;     // +1 / -1: x clearly on the inner / outer side; 0: within rounding of the line
};

Side side_of(const Tri& t, int k, const Vec3& x) {
  const Vec3 d = x - t.v[k];
  Side r;
  r.s = dot(d, t.inward[k]);  // edge_side(x, v[k], v[k+1], n), its cross product precomputed
  r.e2 = t.e2[k];
  // |error of s| <~ 10 eps |x - a| |b - a| |e_i||e_j|; kRound leaves a wide margin.
  const double tol2 = kRound2 * norm2(d) * r.e2 * t.tn.scale2;
  r.sign = r.s * r.s <= tol2 ? 0 : (r.s > 0.0 ? 1 : -1);
  return r;
}
int side_sign(const Tri& t, int k, const Vec3& x) { return side_of(t, k, x).sign; }

// +1 / -1: x clearly beyond / behind v along v -> w; 0: within rounding of the plane through v.
int ray_sign(const Vec3& x, const Vec3& v, const Vec3& w) {
  const double q = vertex_ray(x, v, w);
  const double tol2 = kRound2 * norm2(x - v) * norm2(w - v);
  if (q * q <= tol2) return 0;
  return q > 0.0 ? 1 : -1;
}

// Edge rule: no element on edge g has x clearly over its side of the edge.
template <class TriOf>
bool edge_kept(const TriOf& tri_of, const BarrierTopology& topo, const Vec3& x, std::int32_t g) {
  for (const std::int32_t f : topo.elements_of_edge(g)) {
    const std::size_t fe = static_cast<std::size_t>(f);
    int k = 0;
    while (k < 2 && topo.elem_edge[3 * fe + k] != g) ++k;
    if (side_sign(tri_of(fe), k, x) > 0) return false;
  }
  return true;
}

// Vertex rule: x is clearly beyond v along no edge leaving v. Element e places the rest vertices
// (its motion class, identical for all elements sharing v).
bool vertex_kept(const Barriers& bars, const BarrierTopology& topo, const Vec3& x, std::int32_t v, std::size_t e) {
  const Vec3 pv = bars.place(e, topo.vertex_rest[v]);
  for (const std::int32_t g : topo.edges_of_vertex(v)) {
    const Vec3 pw = bars.place(e, topo.vertex_rest[topo.other_end(g, v)]);
    if (ray_sign(x, pv, pw) > 0) return false;
  }
  return true;
}

// Boundary point of element e: applies the edge/vertex rule to the reported feature and, when the
// point is within rounding of a neighbouring feature (edge end / vertex with an edge nearly
// interior), to that feature too. Sets c.kind/c.feature of the first feature kept.
template <class TriOf>
bool boundary_kept(const Barriers& bars, const TriOf& tri_of, const BarrierTopology& topo, const Vec3& x, std::size_t e,
                   const Tri& t, const TriangleClosestPoint& cp, BarrierContact& c) {
  auto try_edge = [&](int k) {
    const std::int32_t g = topo.elem_edge[3 * e + k];
    if (!edge_kept(tri_of, topo, x, g)) return false;
    c.kind = Feature::Edge;
    c.feature = g;
    return true;
  };
  auto try_vertex = [&](int k) {
    const std::int32_t v = topo.elem_vertex[3 * e + k];
    if (!vertex_kept(bars, topo, x, v, e)) return false;
    c.kind = Feature::Vertex;
    c.feature = v;
    return true;
  };
  const int k = cp.index;
  if (cp.kind == Feature::Edge) {
    const int k1 = next(k);
    return try_edge(k) || (ray_sign(x, t.v[k], t.v[k1]) <= 0 && try_vertex(k)) ||
           (ray_sign(x, t.v[k1], t.v[k]) <= 0 && try_vertex(k1));
  }
  // Vertex k: local edge k leaves it towards k+1, local edge k-1 arrives from k-1.
  return try_vertex(k) || (ray_sign(x, t.v[k], t.v[next(k)]) >= 0 && try_edge(k)) ||
         (ray_sign(x, t.v[k], t.v[prev(k)]) >= 0 && try_edge(prev(k)));
}

// Counts each feature once, orders by element, merges rounding-level duplicates.
void finish(const Barriers& bars, const BarrierTopology& topo, double R, std::vector<BarrierContact>& out) {
  if (out.size() < 2) return;  // nothing to order or merge (the common case: one flat wall)
  auto feature_key = [](const BarrierContact& c) { return std::tie(c.kind, c.feature, c.element); };
  std::sort(out.begin(), out.end(),
            [&](const BarrierContact& a, const BarrierContact& b) { return feature_key(a) < feature_key(b); });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const BarrierContact& a, const BarrierContact& b) {
                          return a.kind == b.kind && a.feature == b.feature;
                        }),
            out.end());
  std::sort(out.begin(), out.end(), [](const BarrierContact& a, const BarrierContact& b) {
    return std::tie(a.element, a.kind, a.feature) < std::tie(b.element, b.kind, b.feature);
  });
  if (out.size() < 2) return;  // the feature merge left one
  auto merge_tol = [&](const BarrierContact& c) {
    return kMergeRel * (R + 0.5 * bars.thickness[c.element] + topo.elem_size[c.element]);
  };
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    bool duplicate = false;
    for (std::size_t j = 0; j < kept && !duplicate; ++j) {
      if (topo.elem_class[out[j].element] != topo.elem_class[out[i].element]) continue;
      const double tol = std::max(merge_tol(out[i]), merge_tol(out[j]));
      duplicate = norm2(out[i].point - out[j].point) <= tol * tol;
    }
    if (!duplicate) out[kept++] = out[i];
  }
  out.resize(kept);
}

template <class TriOf>
void detect(const Barriers& bars, const BarrierTopology& topo, const TriOf& tri_of, const Vec3& x, double R,
            std::span<const std::uint32_t> candidates, std::vector<BarrierContact>& out) {
  assert(topo.num_elements() == bars.size());
  out.clear();
  for (const std::uint32_t ei : candidates) {
    const std::size_t e = ei;
    assert(e < bars.size());
    const double reach = R + 0.5 * bars.thickness[e];  // m, contact distance (110)
    if (!(reach > 0.0)) continue;
    const Tri& t = tri_of(e);  // a temporary (DerivedTriangles) lives until the end of the iteration
    const double n2 = t.n2;
    if (!(n2 > 0.0)) continue;  // degenerate triangles are rejected by Barriers::add
    // The plane distance bounds the triangle distance from below: cheap rejection.
    const double h = dot(x - t.v[0], t.tn.n);
    if (h * h >= reach * reach * n2) continue;

    BarrierContact c;
    c.element = ei;
    // Sides of x: clearly inside all edges -> face; clearly outside one -> boundary point; else x
    // is within rounding of the boundary: the boundary feature if its rule keeps it, otherwise the
    // face (never neither, so rounding cannot lose a contact).
    // One edge out of reach rejects the candidate: the remaining edges are then not needed.
    Side sd[3];
    bool outside = false;
    bool out_of_reach = false;
    for (int k = 0; k < 3 && !out_of_reach; ++k) {
      sd[k] = side_of(t, k, x);
      if (sd[k].sign >= 0) continue;
      outside = true;
      // Distance to the triangle >= distance to the strip on the inner side of this edge's line.
      out_of_reach = (h * h + sd[k].s * sd[k].s / sd[k].e2) >= reach * reach * n2;
    }
    if (out_of_reach) continue;
    const bool inside = sd[0].sign > 0 && sd[1].sign > 0 && sd[2].sign > 0;
    bool face = inside;
    if (!inside) {
      const TriangleClosestPoint cp = closest_point_on_triangle_boundary(x, t.v[0], t.v[1], t.v[2]);
      c.point = cp.point;
      if (norm2(x - cp.point) >= reach * reach || !boundary_kept(bars, tri_of, topo, x, e, t, cp, c)) {
        if (outside) continue;
        face = true;
      }
    }
    if (face) {
      c.point = project_on_plane(x, t.v[0], t.tn.n);
      c.kind = Feature::Face;
      c.feature = static_cast<std::int32_t>(e);
    }
    const Vec3 d = x - c.point;
    const double dist = norm(d);
    if (!(dist < reach)) continue;
    // Written field by field into place: a copy of c would reload the fields just stored, in
    // wider pieces than they were stored in, and wait for the stores to drain.
    BarrierContact& o = out.emplace_back();
    o.element = c.element;
    o.kind = c.kind;
    o.feature = c.feature;
    o.point = c.point;
    o.overlap = reach - dist;
    // Centre on the mid-surface: the direction is undefined, take the element normal.
    o.normal = dist > 0.0 ? d / dist : t.tn.n / std::sqrt(n2);
  }
  finish(bars, topo, R, out);
}

}  // namespace

CurrentTriangle current_triangle(const Barriers& bars, std::size_t e) {
  CurrentTriangle t{{bars.vertex(e, 0), bars.vertex(e, 1), bars.vertex(e, 2)}, {}, 0.0, {}, {}};
  t.tn = triangle_normal(t.v[0], t.v[1], t.v[2]);
  t.n2 = norm2(t.tn.n);
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = t.v[next(k)] - t.v[k];
    t.inward[k] = cross(t.tn.n, edge);
    t.e2[k] = norm2(edge);
  }
  return t;
}

void detect_barrier_contacts(const Barriers& bars, const BarrierTopology& topo, const Vec3& x, double R,
                             std::span<const std::uint32_t> candidates, std::vector<BarrierContact>& out) {
  detect(bars, topo, DerivedTriangles{bars}, x, R, candidates, out);
}

void detect_barrier_contacts(const Barriers& bars, const BarrierTopology& topo, std::span<const CurrentTriangle> tris,
                             const Vec3& x, double R, std::span<const std::uint32_t> candidates,
                             std::vector<BarrierContact>& out) {
  assert(tris.size() == bars.size());
  detect(bars, topo, StoredTriangles{tris}, x, R, candidates, out);
}

}  // namespace mpdem
