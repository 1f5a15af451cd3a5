#pragma once
// Scene: everything a run starts from. The model (constant: parameters, materials) and the
// initial state (particles, barriers), assembled from the TOML scene file and the particle and
// barrier files it names.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/clump_mix.hpp"
#include "model/clump_template.hpp"
#include "model/material.hpp"
#include "model/params.hpp"
#include "state/barriers.hpp"
#include "state/motion_law.hpp"
#include "state/particles.hpp"
#include "model/generate_spec.hpp"

namespace mpdem {

// [[particles]] entry: a particle CSV file, or particles generated in a region (`generate`).
// Columns the file lacks take `material`'s defaults.
struct ParticleSource {
  std::filesystem::path file;            // absolute (resolved against the scene file's folder), or empty
  std::optional<GenerateSpec> generate;  // set instead of `file` for generated particles
  std::string material;                  // default material name ("" = first material)
  ClumpMix clump;                        // clump templates: the file's rows are bodies (empty = spheres)
  bool fixed = false;                    // every particle of the entry fixed (Particles::fixed)
  std::size_t line = 0;                  // line of the entry in the scene file, for messages
  std::size_t first = 0, count = 0;      // its particles [first, first + count) as loaded (before any reordering)
};

// [[barriers]] entry: a barrier CSV file or an STL file, with defaults for its elements.
struct BarrierSource {
  std::filesystem::path file;         // barrier CSV (absolute), or empty
  std::filesystem::path stl;          // STL file (absolute), or empty
  std::string group;                  // group name ("" = file stem)
  std::string material;               // material giving young/poisson when the CSV has none
  bool rigid = false;                 // infinitely stiff: elements get E = kRigidYoung (material.hpp)
  MotionLaw motion;                   // default motion law for elements without motion columns
  double thickness = 0.0;             // m, fictitious thickness t_b
  std::optional<double> temperature;  // K, fixed temperature (none = insulated)
  double scale = 1.0;                 // STL only: vertex scale factor
  Vec3 rotate_deg{};                  // STL only: rotation about x, then y, then z, degrees
  Vec3 translate{};                   // STL only: m, translation after scale and rotation
  std::string origin;                 // the scene file, for messages about the entry's keys ("" = none)
  std::size_t line = 0;               // line of the entry in `origin`
  std::size_t first = 0, count = 0;   // its elements [first, first + count) of the scene's barriers
};

struct Model {
  Params params;
  std::vector<Material> materials;
  std::vector<ClumpTemplate> clumps;                  // [[clump]] templates, in file order
  int material_index(const std::string& name) const;  // -1 when unknown
  int clump_index(const std::string& name) const;     // -1 when unknown
};

struct Scene {
  std::filesystem::path file;  // the scene file
  std::filesystem::path dir;   // its folder; relative paths resolve against it
  Model model;
  std::vector<ParticleSource> particle_sources;
  std::vector<BarrierSource> barrier_sources;
  Particles particles;
  Barriers barriers;
};

}  // namespace mpdem
