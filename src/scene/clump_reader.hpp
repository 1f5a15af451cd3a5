#pragma once
// The clump readers (docs/scene.md "Clumps"): [[clump]] templates, and the bodies of a
// [[particles]] entry with `clump = "name"` (one CSV row per body), expanded into bodies and
// their member spheres.
#include <cstdint>
#include <filesystem>

#include "io/toml_section.hpp"
#include "model/generate_spec.hpp"
#include "model/scene.hpp"

namespace mpdem {

// Reads every [[clump]] table of the scene into model.clumps: name, members (an array of
// [x, y, z, radius] rows, m, or a CSV file with columns x,y,z,radius resolved against `dir`),
// optional mass (kg) and inertia ([I1, I2, I3], kg m^2). Throws InputError naming file, line and key.
void read_clump_templates(const TomlSection& root, const std::filesystem::path& dir, Model& model);

// " (known: a b)" (or that no [[clump]] is defined): the tail of an unknown clump name's message.
std::string known_clumps(const Model& model);
// Refuses, at the first [[particles]] entry with a clump, what clumps do not run with yet
// (inlets). `root` names the scene file.
void check_clump_support(const TomlSection& root, const Scene& scene);

// Appends the bodies of the body CSV `file` (columns: id, x, y, z of the centre of mass; optional
// q0, q1, q2, q3 (unit quaternion w, x, y, z: the template's frame as written -> world; identity
// by default, so a body stands as its template is written), vx, vy, vz, wx, wy, wz, fixed,
// temperature, charge; `radius` and a body CSV snapshot's time, clump, mass, I1, I2, I3 are accepted
// and ignored: io/body_csv_writer.hpp) of template `clump` and material
// `material` to out.bodies, and their members to `out`'s particles (ids assigned later:
// assign_member_ids). Body ids must be >= 0 and unique across the body files read so far (the
// bodies already in out). Throws InputError naming file, line and column.
void read_clump_bodies(const std::filesystem::path& file, const Model& model, int material, int clump, Particles& out);

// Appends the bodies that `spec` generates (generate/generated_bodies.hpp) of template `clump`
// and material spec.material (else `material`), after checking that the body's mass and moments
// are usable (the message names the entry's generate table).
void generate_clump_bodies(const GenerateSpec& spec, const Model& model, int material, int clump, Particles& out);

// Gives the member spheres ids after the largest id of the free spheres, in body order and then
// template order (a member's id names it in the contact output); checks that body ids are unique.
// `origin` names the scene file in messages.
void assign_member_ids(Particles& p, const std::string& origin);

}  // namespace mpdem
