#pragma once
// STL writer. ASCII keeps full double precision (shortest text that reads back exactly); binary
// stores 32-bit floats, as the format prescribes. Facet normals are written from the winding.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

enum class StlFormat { Ascii, Binary };

// Writes the triangles atomically (temporary file + rename). Throws std::runtime_error on I/O failure.
void write_stl(const std::filesystem::path& file, const std::vector<std::array<Vec3, 3>>& triangles, StlFormat format,
               const std::string& solid_name = "mpdem");

}  // namespace mpdem
