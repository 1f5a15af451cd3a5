#pragma once
// STL reader (ASCII and binary). Binary is recognised by its size (84 + 50 n bytes for the n
// triangles its header announces) before the "solid" keyword, because many binary writers start
// their 80-byte header with "solid" too.
#include <array>
#include <cstddef>
#include <filesystem>
#include <vector>

#include "core/vec3.hpp"
#include "model/scene.hpp"

namespace mpdem {

struct StlMesh {
  std::vector<std::array<Vec3, 3>> triangles;  // in file units, winding as stored
  std::vector<std::size_t> number;             // each triangle's 1-based position in the file (facet or record)
  std::vector<std::size_t> line;               // ASCII: the line of each triangle's 'facet'; binary: 0
  std::size_t degenerate = 0;                  // zero-area triangles dropped (|n| <= 1e-12 x longest edge^2)
  bool binary = false;
};

// Reads `file`. The facet normals stored in the file are ignored: the winding defines the normal
// (counter-clockwise seen from the normal side, as STL requires). An ASCII file may start with a
// UTF-8 byte order mark. Throws InputError naming the file and the problem - truncated binary
// data, a bad ASCII keyword (with its line), a non-numeric or non-finite coordinate, a triangle
// whose area overflows, an empty file.
StlMesh read_stl(const std::filesystem::path& file);

// True when the triangle has (relatively) zero area.
bool is_degenerate_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

// ---- STL barrier sources of a scene ----
// Reads src.stl, applies scale, then rotate_deg (x, y, z), then translate, and appends the
// triangles to `out` with the source's group (default: the file stem), material, motion law,
// thickness and temperature. Dropped degenerate triangles are counted in a warning on stderr. A
// triangle that a step of the placement (or the motion's offset B) makes non-finite or collapses
// to zero area is an InputError naming the step's key (barriers.scale, ...) at src.origin's
// src.line, the STL file and the triangle.
void read_stl_barriers(const BarrierSource& src, const Model& model, Barriers& out);

}  // namespace mpdem
