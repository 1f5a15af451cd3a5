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
  std::size_t degenerate = 0;                  // zero-area triangles dropped (|n| <= 1e-12 x longest edge^2)
  bool binary = false;
};

// Reads `file`. The facet normals stored in the file are ignored: the winding defines the normal
// (counter-clockwise seen from the normal side, as STL requires). Throws InputError naming the
// file and the problem - truncated binary data, a bad ASCII keyword (with its line), a
// non-numeric or non-finite coordinate, an empty file.
StlMesh read_stl(const std::filesystem::path& file);

// True when the triangle has (relatively) zero area.
bool is_degenerate_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

// ---- STL barrier sources of a scene ----
// Reads src.stl, applies scale, then rotate_deg (x, y, z), then translate, and appends the
// triangles to `out` with the source's group (default: the file stem), material, motion law,
// thickness and temperature. Dropped degenerate triangles are counted in a warning on stderr.
void read_stl_barriers(const BarrierSource& src, const Model& model, Barriers& out);

}  // namespace mpdem
