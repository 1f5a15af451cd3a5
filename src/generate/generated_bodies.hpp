#pragma once
// Rigid bodies generated from a scene's `[[particles]] generate = {...}, clump = "name"` entry
// (docs/scene.md "Generated bodies"). placement = bounding: each body is placed by its bounding
// sphere (radius ClumpTemplate::reach() about its centre of mass) with the sphere generator, so no
// member of one body overlaps a member of another or leaves the region, whatever the orientations;
// each body then gets a uniformly random orientation from the seed. placement = members (denser):
// random sequential addition of whole bodies (centre and orientation), tested member by member.
#include "core/random.hpp"
#include "core/rotation.hpp"
#include "model/clump_mix.hpp"
#include "model/generate_spec.hpp"
#include "model/scene.hpp"

namespace mpdem {

// Appends the bodies of the templates of `mix` and material `material` to out.bodies and their
// members to `out`: body ids continue after the largest body id so far; each body draws its
// template (ClumpMix::draw) from its own stream of the seed, in body order; a `solid_fraction` is
// of the bodies' volume (the union of the members; the mean over the mix); spec.radius is not
// used (the templates fix the size). With a mix, placement = bounding gives every body the
// bounding sphere of the largest reach. Throws InputError (spec.origin, spec.line, "generate")
// when the request cannot be met.
void add_generated_bodies(const GenerateSpec& spec, const Model& model, int material, const ClumpMix& mix,
                          Particles& out);

// A uniformly random rotation: the normalised quaternion of four standard normals.
Quat uniform_rotation(Rng& rng);

}  // namespace mpdem
