#pragma once
// Rigid bodies generated from a scene's `[[particles]] generate = {...}, clump = "name"` entry
// (docs/scene.md "Generated bodies"). placement = bounding: each body is placed by its bounding
// sphere (radius ClumpTemplate::reach() about its centre of mass) with the sphere generator, so no
// member of one body overlaps a member of another or leaves the region, whatever the orientations;
// each body then gets a uniformly random orientation from the seed. placement = members (denser):
// random sequential addition of whole bodies (centre and orientation), tested member by member.
#include "model/generate_spec.hpp"
#include "model/scene.hpp"

namespace mpdem {

// Appends the bodies of template `clump` and material `material` to out.bodies and their members
// to `out`: body ids continue after the largest body id so far; a `solid_fraction` is of the
// bodies' volume (the union of the members); spec.radius is not used (the template fixes the
// size). Throws InputError (spec.origin, spec.line, "generate") when the request cannot be met.
void add_generated_bodies(const GenerateSpec& spec, const Model& model, int material, int clump, Particles& out);

}  // namespace mpdem
