#pragma once
// Reads a scene's `[[inlet]]` and `[[sink]]` entries (docs/scene.md) into Params::inlets and
// Params::sinks. Every problem is an InputError naming the file, the line and the dotted key
// ("inlet.mass_rate"); unknown keys are rejected with the closest known key suggested.
#include <toml++/toml.h>

#include "io/toml_section.hpp"
#include "model/scene.hpp"

namespace mpdem {

// `root` is the scene file's root table, `doc` its raw TOML (the radius distribution tables);
// the materials must have been read (an inlet names one).
void read_inlets_and_sinks(const TomlSection& root, const toml::table& doc, Model& model);

}  // namespace mpdem
