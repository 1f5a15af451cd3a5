#pragma once
// Which [[particles]] or [[barriers]] entry of a scene a particle or barrier element came from
// (the sources' index ranges as loaded), and how the checks' messages name and locate it.
#include <cstddef>
#include <string>

#include "check/scene_problem.hpp"
#include "model/scene.hpp"

namespace mpdem {

struct SourceLocation {
  std::string file;      // the particle CSV, or the scene file for generated particles and barriers
  std::size_t line = 0;  // the entry's line in the scene file (0 = none)
  std::string key;       // "particles.generate", "barriers", or "" for a CSV file
  std::string
      name;  // for "particles of NAME": "'p.csv'", "[[particles]] entry 2 (generated)", "'walls.csv' (group walls)"
};

// The source holding particle i / element e as loaded, or -1 (none: a scene built in code, or
// arrays reordered since loading).
int particle_source_of(const Scene& scene, std::size_t i);
int barrier_source_of(const Scene& scene, std::size_t e);
// Source s (-1: the scene itself).
SourceLocation particle_source_location(const Scene& scene, int s);
SourceLocation barrier_source_location(const Scene& scene, int s);
// A problem located at `where` (its file, line and key).
SceneProblem problem_at(const SourceLocation& where, Severity severity, bool stops_run, std::string message);

}  // namespace mpdem
