// Generated clump bodies (docs/scene.md "Clumps").
#include "generate/generated_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.hpp"
#include "core/random.hpp"
#include "core/rotation.hpp"
#include "core/value_range.hpp"
#include "generate/generator.hpp"
#include "generate/region.hpp"
#include "model/body_members.hpp"

namespace mpdem {

namespace {

// A uniformly random rotation: four standard normals are isotropic in R^4, so their direction is
// uniform on the unit 3-sphere, which is the Haar measure on the rotations (q and -q alike).
Quat uniform_rotation(Rng& rng) {
  for (;;) {
    const Quat q{rng.normal(), rng.normal(), rng.normal(), rng.normal()};
    if (q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z > 1e-12) return quat_normalized(q);
  }
}

}  // namespace

void add_generated_bodies(const GenerateSpec& spec, const Model& model, int material, int clump, Particles& out) {
  const auto fail = [&](const std::string& msg) { throw InputError(spec.origin, spec.line, "generate", msg); };
  const ClumpTemplate& t = model.clumps.at(static_cast<std::size_t>(clump));
  const Material& m = model.materials.at(static_cast<std::size_t>(material));
  GenerateSpec bounding = spec;
  bounding.radius = RadiusDistribution{};
  bounding.radius.value = t.reach();
  if (spec.count == 0) {
    // A solid fraction of the bodies' own volume: the count whose volume is closest to it.
    if (!(spec.solid_fraction > 0.0 && spec.solid_fraction < 1.0))
      fail("give a count >= 1 or a solid_fraction in (0, 1)");
    const double n = spec.solid_fraction * Region(spec.region, spec.origin, spec.line).volume() / t.shape.volume;
    if (!(n >= 0.5)) fail("the requested solid fraction is smaller than one body of clump '" + t.name + "'");
    if (!(n < 5e7)) fail("the solid fraction needs more than 5e7 bodies of clump '" + t.name + "'; check units");
    bounding.count = static_cast<std::size_t>(std::llround(n));
    bounding.solid_fraction = 0.0;
  }
  const GenerateResult placed = generate_particles(bounding);

  std::int64_t next_id = 0;
  for (const std::int64_t b : out.bodies.id) next_id = std::max(next_id, b + 1);
  // Orientations from their own stream: the positions are the sphere generator's for the same seed.
  Rng qrng(spec.seed ^ 0xD1B54A32D192ED03ull);
  for (const GeneratedParticle& g : placed.particles) {
    BodyInit init;
    init.id = next_id++;
    init.x = g.x;
    init.v = g.v;
    init.q = uniform_rotation(qrng);
    init.T = m.temperature;
    init.charge = m.charge;
    init.fixed = spec.fixed;
    add_body(model, material, clump, init, out);
  }
}

}  // namespace mpdem
