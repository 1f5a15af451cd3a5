#pragma once
// Writes a built mesh as a barrier CSV (docs/scene.md "Barrier CSV") or an STL file.
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/stl_writer.hpp"
#include "geometry/triangle_mesh.hpp"

namespace mpdem {

enum class MeshFileFormat { Csv, StlAscii, StlBinary };

// Barrier CSV: id, x1..z3 and, when `group` is not empty, a group column. Shortest exact numbers.
// first_id: id of the first triangle, so several meshes can share one scene without id clashes.
void write_mesh_csv(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& group,
                    std::int64_t first_id = 0);
void write_mesh(const std::filesystem::path& file, const TriangleMesh& mesh, MeshFileFormat format,
                const std::string& group, std::int64_t first_id = 0);

}  // namespace mpdem
