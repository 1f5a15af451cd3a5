#pragma once
// Particle generator: random non-overlapping spheres in a region by random sequential addition
// (RSA). Radii are drawn first (all of them, from the seed), sorted largest first - big spheres
// are the hard ones to fit - and each is then tried at up to max_attempts uniform random centres;
// a cell grid keeps every overlap check to the 27 cells around the candidate.
#include <filesystem>
#include <vector>

#include "core/random.hpp"
#include "core/vec3.hpp"
#include "model/generate_spec.hpp"

namespace mpdem {

struct GeneratedParticle {
  Vec3 x;         // m, centre
  double radius;  // m
  Vec3 v;         // m/s, initial velocity
};

struct GenerateResult {
  std::vector<GeneratedParticle> particles;
  double region_volume = 0.0;   // m^3
  double solid_fraction = 0.0;  // -, sum of sphere volumes / region volume
  std::size_t attempts = 0;     // random centres tried in total
};

// The radii to place (m): spec.count draws from spec.radius, or (count 0) draws until their
// volume is closest to spec.solid_fraction x region_volume (m^3). Throws InputError (spec.origin,
// spec.line, "generate") beyond 5e7 particles.
std::vector<double> draw_radii(const GenerateSpec& spec, double region_volume, Rng& rng);

// Deterministic for a given spec (seed included). Throws InputError (spec.origin, spec.line,
// "generate") for an impossible request: bad parameters, a sphere larger than the region, or a
// count / solid fraction that RSA cannot reach within max_attempts per particle.
GenerateResult generate_particles(const GenerateSpec& spec);

// Particle CSV (docs/scene.md "Particle CSV"): id, x, y, z, vx, vy, vz, radius [, material].
// Numbers are written as the shortest text that reads back exactly.
void write_generated_csv(const std::filesystem::path& file, const GenerateSpec& spec,
                         const std::vector<GeneratedParticle>& particles);

}  // namespace mpdem
