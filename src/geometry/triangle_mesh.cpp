// TriangleMesh helpers: welding, area, edge census, enclosed volume.
#include "geometry/triangle_mesh.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <utility>

namespace mpdem {

Vec3 TriangleMesh::normal(std::size_t t) const {
  const Vec3 n = cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0));
  return n / norm(n);
}

double TriangleMesh::area(std::size_t t) const {
  return 0.5 * norm(cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0)));
}

void TriangleMesh::append(const TriangleMesh& other) {
  const int base = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) add_triangle(t[0] + base, t[1] + base, t[2] + base);
}

void TriangleMesh::flip() {
  for (auto& t : triangles) std::swap(t[1], t[2]);
}

TriangleMesh weld(const std::vector<std::array<Vec3, 3>>& tris) {
  TriangleMesh mesh;
  std::map<std::tuple<double, double, double>, int> index;  // exact coordinates -> vertex
  for (const auto& tri : tris) {
    std::array<int, 3> ids{};
    for (int k = 0; k < 3; ++k) {
      const auto key = std::make_tuple(tri[k].x, tri[k].y, tri[k].z);
      const auto [it, inserted] = index.emplace(key, static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back(tri[k]);
      ids[k] = it->second;
    }
    mesh.triangles.push_back(ids);
  }
  return mesh;
}

std::vector<std::array<Vec3, 3>> soup(const TriangleMesh& mesh) {
  std::vector<std::array<Vec3, 3>> out;
  out.reserve(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t)
    out.push_back({mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)});
  return out;
}

double total_area(const TriangleMesh& mesh) {
  double a = 0.0;
  for (std::size_t t = 0; t < mesh.size(); ++t) a += mesh.area(t);
  return a;
}

EdgeCounts count_edges(const TriangleMesh& mesh) {
  // Per undirected edge (lo, hi): uses in direction lo->hi and hi->lo.
  std::map<std::pair<int, int>, std::pair<int, int>> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      auto& u = uses[{std::min(a, b), std::max(a, b)}];
      (a < b ? u.first : u.second) += 1;
    }
  EdgeCounts c;
  for (const auto& [edge, u] : uses) {
    const int n = u.first + u.second;
    if (n == 1) ++c.boundary;
    else if (n == 2 && u.first == 1) ++c.manifold;
    else if (n == 2) ++c.inconsistent;
    else ++c.non_manifold;
  }
  return c;
}

std::string closed_surface_problem(const TriangleMesh& mesh) {
  const EdgeCounts e = count_edges(mesh);
  if (e.boundary > 0 || e.non_manifold > 0)
    return "not closed: " + std::to_string(e.boundary) + " edge(s) belong to one triangle only and " +
           std::to_string(e.non_manifold) + " to three or more (every edge must join exactly two triangles)";
  if (e.inconsistent > 0)
    return "not consistently oriented: " + std::to_string(e.inconsistent) +
           " edge(s) are traversed in the same direction by both their triangles";
  return "";
}

double signed_volume(const TriangleMesh& mesh) {
  double v = 0.0;
  for (std::size_t t = 0; t < mesh.size(); ++t)
    v += dot(mesh.corner(t, 0), cross(mesh.corner(t, 1), mesh.corner(t, 2)));
  return v / 6.0;
}

}  // namespace mpdem
