#pragma once
// Connectivity of the barrier triangles (physics.md section 7, Departure: each physical contact
// with a triangle mesh is counted once). Built once from the rest geometry.
//
// Vertices with bit-identical rest coordinates are welded into one global vertex, but only
// between elements whose motion laws are identical field by field (a "motion class"), so a moving
// mesh is never stitched to a fixed one. Edges are unordered pairs of global vertices. All
// adjacency lists are CSR arrays, each list ascending.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "state/barriers.hpp"

namespace mpdem {

struct BarrierTopology {
  // --- per element [M] (local vertex k = p0, p1, p2; local edge k joins local vertices k, k+1 mod 3)
  std::vector<std::int32_t> elem_vertex;  // [3M] global vertex id of local vertex k at 3e+k
  std::vector<std::int32_t> elem_edge;    // [3M] global edge id of local edge k at 3e+k
  std::vector<std::int32_t> elem_class;   // [M] motion class (elements with identical MotionLaw, rotation included)
  std::vector<double> elem_size;          // [M] m, longest edge at rest
  // --- per global vertex [V]
  std::vector<Vec3> vertex_rest;                // [V] m, rest position
  std::vector<std::int32_t> vertex_elem_start;  // [V+1] CSR offsets into vertex_elem
  std::vector<std::int32_t> vertex_elem;        // elements having the vertex, ascending per vertex
  std::vector<std::int32_t> vertex_edge_start;  // [V+1] CSR offsets into vertex_edge
  std::vector<std::int32_t> vertex_edge;        // edges incident to the vertex, ascending per vertex
  // --- per global edge [E]
  std::vector<std::int32_t> edge_vertex;      // [2E] end vertices (lower id first) at 2g, 2g+1
  std::vector<std::int32_t> edge_elem_start;  // [E+1] CSR offsets into edge_elem
  std::vector<std::int32_t> edge_elem;        // elements having the edge, ascending per edge

  // O(M log M). Throws std::length_error when 3M does not fit the 32-bit ids.
  static BarrierTopology build(const Barriers& bars);

  std::size_t num_elements() const { return elem_class.size(); }
  std::size_t num_vertices() const { return vertex_rest.size(); }
  std::size_t num_edges() const { return edge_vertex.size() / 2; }

  std::span<const std::int32_t> elements_of_vertex(std::int32_t v) const {
    return {vertex_elem.data() + vertex_elem_start[v],
            static_cast<std::size_t>(vertex_elem_start[v + 1] - vertex_elem_start[v])};
  }
  std::span<const std::int32_t> edges_of_vertex(std::int32_t v) const {
    return {vertex_edge.data() + vertex_edge_start[v],
            static_cast<std::size_t>(vertex_edge_start[v + 1] - vertex_edge_start[v])};
  }
  std::span<const std::int32_t> elements_of_edge(std::int32_t g) const {
    return {edge_elem.data() + edge_elem_start[g],
            static_cast<std::size_t>(edge_elem_start[g + 1] - edge_elem_start[g])};
  }
  // The end of edge g that is not v (v must be an end of g).
  std::int32_t other_end(std::int32_t g, std::int32_t v) const {
    return edge_vertex[2 * g] == v ? edge_vertex[2 * g + 1] : edge_vertex[2 * g];
  }
};

}  // namespace mpdem
