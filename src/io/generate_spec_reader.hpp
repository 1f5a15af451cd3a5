#pragma once
// Reads a scene's inline generator table, `[[particles]] generate = { ... }` (docs/scene.md
// "Generated particles"), into a GenerateSpec. Every problem is an InputError naming the file,
// the line and the dotted key.
#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "generate/generate_spec.hpp"

namespace mpdem {

// `path` is the table's dotted key ("particles.generate"); a relative `mesh` file is resolved
// against `dir` (the scene file's folder) and must exist.
GenerateSpec read_generate_spec(const std::string& file, const toml::table& table, const std::string& path,
                                const std::filesystem::path& dir);

}  // namespace mpdem
