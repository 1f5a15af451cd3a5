#pragma once
// Where an inlet with `clump` puts a rigid body (sim/inlets.hpp, docs/scene.md "[[inlet]]"): a
// candidate is a uniformly random centre of mass in the inlet's volume and a uniformly random
// orientation (generate/generated_bodies.hpp uniform_rotation); it is kept when every member lies
// inside the volume and overlaps nothing the InsertionSpace holds (particles, active barrier
// elements, the spheres placed since). The centre of mass of a body lies in the convex hull of
// its members, so drawing it in the (convex) volume misses no placement.
#include <cstddef>

#include "core/random.hpp"
#include "core/rotation.hpp"
#include "generate/region.hpp"
#include "model/clump_template.hpp"
#include "model/open_boundaries.hpp"
#include "sim/insertion_space.hpp"

namespace mpdem {

struct BodyPlace {
  Vec3 x;  // m, centre of mass (world)
  Quat q;  // orientation: the template as written -> world (BodyInit::q)
};

// Tries at most `attempts` candidates for a body of template t in `vol` (`region`: the volume in its
// frame coordinates); true with the body's place when one is free.
bool place_body(const ClumpTemplate& t, const InsertionVolume& vol, const Region& region, const InsertionSpace& space,
                Rng& rng, std::size_t attempts, BodyPlace& out);

}  // namespace mpdem
