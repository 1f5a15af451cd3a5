#pragma once
// The clump readers (docs/scene.md "Clumps"): [[clump]] templates, and the bodies of a
// [[particles]] entry with `clump = "name"` (one CSV row per body), expanded into bodies and
// their member spheres.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/toml_section.hpp"
#include "model/generate_spec.hpp"
#include "model/scene.hpp"

namespace mpdem {

// Reads every [[clump]] table of the scene into model.clumps: name, members (an array of
// [x, y, z, radius] rows, m, or a CSV file with columns x,y,z,radius resolved against `dir`),
// optional mass (kg) and inertia ([I1, I2, I3], kg m^2). Throws InputError naming file, line and key.
void read_clump_templates(const TomlSection& root, const std::filesystem::path& dir, Model& model);

// `k` of a [[particles]] or [[inlet]] entry: a template name, or an inline table of template names
// -> number fractions (each > 0, summing to 1 within 1e-9), in the order written (ClumpMix::draw).
// Throws InputError naming file, line and key (an unknown name lists the known ones).
ClumpMix read_clump_mix(const TomlSection& s, std::string_view k, const Model& model);
// "" when every template of `mix` gives bodies of material `material` a usable mass and moments,
// else what is wrong (names the template and material).
std::string clump_mix_mass_problem(const ClumpMix& mix, const Model& model, int material);

// " (known: a b)" (or that no [[clump]] is defined): the tail of an unknown clump name's message.
std::string known_clumps(const Model& model);

// Appends the bodies of the body CSV `file` (columns: id, x, y, z of the centre of mass; optional
// q0, q1, q2, q3 (unit quaternion w, x, y, z: the template's frame as written -> world; identity
// by default, so a body stands as its template is written), vx, vy, vz, wx, wy, wz, fixed,
// temperature, charge; `radius` and a body CSV snapshot's time, clump, mass, I1, I2, I3 are accepted
// and ignored: io/body_csv_writer.hpp) of template `clump` and material
// `material` to out.bodies, and their members to `out`'s particles (ids assigned later:
// assign_member_ids). Body ids must be >= 0 and unique across the body files read so far (the
// bodies already in out). Throws InputError naming file, line and column.
void read_clump_bodies(const std::filesystem::path& file, const Model& model, int material, int clump, Particles& out);

// Appends the bodies that `spec` generates (generate/generated_bodies.hpp) of the templates of
// `mix` and material spec.material (else `material`), after checking that the body's mass and moments
// are usable (the message names the entry's generate table).
void generate_clump_bodies(const GenerateSpec& spec, const Model& model, int material, const ClumpMix& mix,
                           Particles& out);

// Gives the member spheres ids after the largest id of the free spheres, in body order and then
// template order (a member's id names it in the contact output); checks that body ids are unique.
// `origin` names the scene file in messages.
void assign_member_ids(Particles& p, const std::string& origin);

}  // namespace mpdem
