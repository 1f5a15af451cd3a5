#pragma once
// The scene file's reader (docs/scene.md): TOML onto the model's data, then the particle and
// barrier sources into the scene's arrays.
#include <filesystem>
#include <string>

#include "model/scene.hpp"

namespace mpdem {

// Parses a TOML scene (parameters, materials, sources) without reading the sources.
// Throws InputError naming file, line and key for every problem.
Scene parse_scene_file(const std::filesystem::path& file);
// parse_scene_file + reads every particle and barrier source into the scene's arrays.
Scene load_scene(const std::filesystem::path& file);
// The same for a scene given as text (the Python module's scenes): `file` stands for the scene
// file (relative paths and the output folder resolve against its folder; it need not exist) and
// `name` is what messages call it.
Scene parse_scene_text(const std::string& text, const std::filesystem::path& file, const std::string& name);
Scene load_scene_text(const std::string& text, const std::filesystem::path& file, const std::string& name);
// Reads every particle and barrier source of a parsed scene into its arrays.
Scene load_sources(Scene scene);

}  // namespace mpdem
