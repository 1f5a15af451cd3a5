#pragma once
// Barrier CSV reader (docs/scene.md "Barrier CSV"): one triangle per row, named header, any
// column order; missing optional columns take the barrier source's defaults.
#include <filesystem>

#include "model/scene.hpp"

namespace mpdem {

// Appends the triangles of `file` to `out`, using `source` (group, material, motion law,
// thickness, temperature) for columns the file lacks. Degenerate triangles are an error naming
// the line. Throws InputError.
void read_barrier_csv(const std::filesystem::path& file, const BarrierSource& source, const Model& model,
                      Barriers& out);

}  // namespace mpdem
