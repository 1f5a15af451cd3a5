#pragma once
// TriangleMesh: an indexed triangle surface, the common currency of the mesh builder, the STL
// reader/writer and mesh-bounded generator regions. Triangles are counter-clockwise seen from the
// side their normal points to, as in the barrier CSV.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

struct TriangleMesh {
  std::vector<Vec3> vertices;                 // m
  std::vector<std::array<int, 3>> triangles;  // vertex indices, counter-clockwise about the normal

  std::size_t size() const { return triangles.size(); }
  int add_vertex(const Vec3& p) {
    vertices.push_back(p);
    return static_cast<int>(vertices.size()) - 1;
  }
  void add_triangle(int a, int b, int c) { triangles.push_back({a, b, c}); }
  // Two triangles (a, b, c) and (a, c, d) of the quad a-b-c-d (counter-clockwise).
  void add_quad(int a, int b, int c, int d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }
  Vec3 corner(std::size_t t, int k) const { return vertices[triangles[t][k]]; }
  Vec3 normal(std::size_t t) const;  // unit normal of triangle t
  double area(std::size_t t) const;  // m^2
  void append(const TriangleMesh& other);
  void flip();  // reverses every triangle: normals point the other way
};

struct EdgeCounts {
  std::size_t boundary = 0;      // undirected edges used by one triangle
  std::size_t manifold = 0;      // used by exactly two, in opposite directions
  std::size_t inconsistent = 0;  // used by two in the same direction (orientation flips)
  std::size_t non_manifold = 0;  // used by three or more
};

// Merges vertices with bitwise-equal coordinates (STL and CSV give triangle soups).
TriangleMesh weld(const std::vector<std::array<Vec3, 3>>& soup);
std::vector<std::array<Vec3, 3>> soup(const TriangleMesh& mesh);
double total_area(const TriangleMesh& mesh);  // m^2
// Edge census by vertex index; a closed, consistently oriented surface has only manifold edges.
EdgeCounts count_edges(const TriangleMesh& mesh);
// "" for a closed, consistently oriented surface; else what is wrong, to follow "the surface is "
// ("not closed: 3 edge(s) belong to one triangle only ...").
std::string closed_surface_problem(const TriangleMesh& mesh);
// Signed enclosed volume sum (a . (b x c)) / 6, m^3: positive when normals point outward.
double signed_volume(const TriangleMesh& mesh);

}  // namespace mpdem
