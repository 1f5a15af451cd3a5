#pragma once
// Writes a built mesh as a barrier CSV (docs/scene.md "Barrier CSV") or an STL file.
#include <filesystem>
#include <string>

#include "io/stl_writer.hpp"
#include "tools/triangle_mesh.hpp"

namespace mpdem {

enum class MeshFileFormat { Csv, StlAscii, StlBinary };

// Barrier CSV: id, x1..z3 and, when `group` is not empty, a group column. Shortest exact numbers.
void write_mesh_csv(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& group);
void write_mesh(const std::filesystem::path& file, const TriangleMesh& mesh, MeshFileFormat format,
                const std::string& group);

}  // namespace mpdem
