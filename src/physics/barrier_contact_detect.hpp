#pragma once
// Sphere - barrier mesh contact detection, counting each physical contact once
// (physics.md section 7, Departure; rule and its rounding safeguards in docs/barrier_contacts.md).
//
// Each candidate element gives its exact closest point p to the sphere centre x (face, edge or
// vertex region). The element is in contact when delta = R + t_b/2 - |x - p| > 0 (the surface is
// offset by t_b/2 on both sides; positive delta is the overlap). Then
//   - a FACE point is always a contact;
//   - an EDGE point is kept only if x lies over no adjacent element's face, i.e. for every element F
//     on the edge, (x - p) has no positive component along F's in-plane normal to the edge pointing
//     into F;
//   - a VERTEX point is kept only if (x - p) has no positive component along any edge leaving the
//     vertex (edges of all adjacent elements);
//   - one edge or vertex reported by several elements counts once (smallest element index kept).
// The result is sorted by element index and independent of the order of the candidates.
// Geometry only: no forces. Thread safe (reads bars/topo, writes only `out`).
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "geometry/triangle_closest_point.hpp"
#include "state/barrier_topology.hpp"
#include "state/barriers.hpp"

namespace mpdem {

struct BarrierContact {
  std::uint32_t element = 0;     // barrier element index
  Feature kind = Feature::Face;  // feature of the element holding the contact point
  std::int32_t feature = 0;      // Face: element index; Edge: global edge id; Vertex: global vertex id
  Vec3 point;                    // m, contact point on the (mid-)surface at the current offset
  Vec3 normal;                   // -, unit, from the contact point towards the sphere centre
  double overlap = 0.0;          // m, R + t_b/2 - |x - p| > 0
};

// One element's triangle at the barriers' current placement, with what detection derives from its
// vertices alone. Elements move rigidly (Barriers::move_to), so a caller testing many spheres
// at one time computes these once per element (current_triangle) instead of once per candidate;
// the values are bit for bit those detection computes on its own.
struct CurrentTriangle {
  Vec3 v[3];          // m, current vertices (Barriers::vertex)
  TriangleNormal tn;  // unnormalised normal n (m^2) and its rounding scale (m^4)
  double n2 = 0.0;    // m^4, |n|^2
  Vec3 inward[3];     // m^3, n x (v[k+1] - v[k]): edge k's in-plane normal into the triangle
  double e2[3] = {};  // m^2, |v[k+1] - v[k]|^2, squared length of edge k
};

// Element e at its current placement.
CurrentTriangle current_triangle(const Barriers& bars, std::size_t e);

// Contacts of the sphere (centre x [m], radius R [m]) with the candidate elements (indices into
// bars, any order, repeats allowed). `out` is cleared and refilled; reuse it between calls so no
// allocation happens once its capacity suffices. topo must be BarrierTopology::build(bars).
void detect_barrier_contacts(const Barriers& bars, const BarrierTopology& topo, const Vec3& x, double R,
                             std::span<const std::uint32_t> candidates, std::vector<BarrierContact>& out);
// The same with the triangles precomputed: tris[e] = current_triangle(bars, e) for every element.
// Identical results, without re-deriving each candidate's triangle.
void detect_barrier_contacts(const Barriers& bars, const BarrierTopology& topo, std::span<const CurrentTriangle> tris,
                             const Vec3& x, double R, std::span<const std::uint32_t> candidates,
                             std::vector<BarrierContact>& out);

}  // namespace mpdem
