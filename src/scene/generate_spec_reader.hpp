#pragma once
// Reads a scene's inline generator table, `[[particles]] generate = { ... }` (docs/scene.md
// "Generated particles"), into a GenerateSpec. Every problem is an InputError naming the file,
// the line and the dotted key.
#include <cstdint>
#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "model/generate_spec.hpp"
#include "io/toml_section.hpp"

namespace mpdem {

// Random positions tried per particle, at most: a sphere that finds no room in 1e8 tries (seconds)
// will not find it in more, and a larger count only turns a jammed packing into a hang.
inline constexpr std::int64_t kMaxAttempts = 100'000'000;

// The pieces of a generator table that other tables share ([[inlet]], [[sink]]: scene/inlet_reader.hpp),
// g being the table (its known keys already checked) and t its raw TOML:
//   `radius`: a number (constant radius, m) or a distribution table;
RadiusDistribution read_radius(const TomlSection& g, const toml::table& t);
//   `min`, `max` of a box (max > min in every component);
RegionSpec read_box_region(const TomlSection& g);
//   `base`, `axis` (base centre -> top centre), `cylinder_radius` of a cylinder.
RegionSpec read_cylinder_region(const TomlSection& g);
// What the run derives from a region's size must be usable (docs/scene.md "Derived limits"):
// a box's extents finite and its volume finite and > 0 (else fails at `key`); a cylinder's
// squared axis length (at `axis_key`), squared radius and volume (at `radius_key`) too.
void check_box_sizes(const TomlSection& g, const Vec3& extent, std::string_view key);
void check_cylinder_sizes(const TomlSection& g, const Vec3& axis, double radius, std::string_view axis_key,
                          std::string_view radius_key);

// `path` is the table's dotted key ("particles.generate"); a relative `mesh` file is resolved
// against `dir` (the scene file's folder) and must exist. `clump`: the entry places clump bodies,
// whose template fixes their size, so a `radius` is refused instead of required.
GenerateSpec read_generate_spec(const std::string& file, const toml::table& table, const std::string& path,
                                const std::filesystem::path& dir, bool clump = false);

}  // namespace mpdem
