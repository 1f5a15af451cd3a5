#pragma once
// The physics beds of `mpdem bench` (docs/benchmark.md "Physics beds"): the settled bed's spheres
// as tetrahedral clumps (--clumps), with adhesion or liquid bridges (--cohesion), or bonded to
// their neighbours (--bonds). Each changes the reference scene only when its option is given.
#include <string>

#include "cli/bench_command.hpp"
#include "io/lammps_data.hpp"
#include "model/scene.hpp"

namespace mpdem::cli {

// The bed's name in the results: "plain", or the options' parts joined by '+' ("clumps+jkr").
std::string bench_bed_name(const BenchArgs& a);

// --clumps: at every sphere of the data file a tetrahedral clump of four spheres (members' ids
// from "bench"), into s.particles; s.model.materials must hold the bed's material.
void add_clump_bed(const LammpsData& d, Scene& s);

// --cohesion and --bonds: the contact laws' cohesion, [liquid_bridge] and [bonds] of the scene.
void add_bed_physics(const BenchArgs& a, Params& prm);

// One line on what --cohesion and --bonds added, with their values ("" for neither).
std::string bed_physics_summary(const BenchArgs& a);

}  // namespace mpdem::cli
