#pragma once
// Reads a scene's `[[coarse_grain]]` entries (docs/scene.md "[[coarse_grain]]") into
// Params::coarse_grain. Every problem is an InputError naming the file, the line and the dotted
// key ("coarse_grain.width"); unknown keys are rejected with the closest known key suggested.
#include "io/toml_section.hpp"
#include "model/scene.hpp"

namespace mpdem {

// `root` is the scene file's root table; [domain] must have been read (a profile's default extent).
void read_coarse_grain(const TomlSection& root, Model& model);

}  // namespace mpdem
