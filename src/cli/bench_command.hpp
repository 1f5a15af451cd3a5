#pragma once
// `mpdem bench`: the settled-bed benchmark (docs/benchmark.md, shared bench/README.md). Reads a
// LAMMPS/LIGGGHTS data file, builds the reference scene (five flat walls, gravity, Hertz-Mindlin
// with e = 0.5, mu = 0.5, no rolling friction), runs untimed relaxation steps, then times steps.
#include <filesystem>
#include <string>
#include <vector>

namespace mpdem::cli {

// The values of --cohesion, "none" first.
inline const std::vector<std::string> kBenchCohesions = {"none", "jkr", "sjkr", "bridges"};

struct BenchArgs {
  std::filesystem::path data;         // LAMMPS data file (plain text)
  std::string integrator = "verlet";  // "verlet" or "trapezoidal"
  double phi = 0.5;                   // -, trapezoidal weight
  int threads = 1;                    // OpenMP threads (>= 1)
  long steps = 0;                     // timed steps; 0 = 5000 for N <= 50,000 particles, else 2000
  long relax = 1000;                  // untimed steps before the timed window
  double dt = 4e-6;                   // s
  double skin = 2e-4;                 // m, Verlet skin
  // Output cost: empty, no files (steps via Simulation::advance); else a fresh or empty folder the
  // run writes to as `mpdem run` would (steps via Simulation::step: global log rows, snapshots).
  std::filesystem::path output;
  long snapshot_every = 0;        // steps between particle VTU snapshots (0: none; needs output)
  std::string format = "binary";  // their VTK format: "ascii", "binary" or "compressed"
  // Each sphere of the bed becomes a rigid tetrahedral clump of four overlapping spheres inscribed
  // in the bed's smallest sphere, turned at random (from its id): the clumps' cost per member-step.
  bool clumps = false;
  // The physics beds (docs/benchmark.md "Physics beds"): "none", "jkr" or "sjkr" (adhesion of the
  // spheres and walls) or "bridges" (capillary liquid bridges); --bonds: parallel bonds between
  // the spheres closer than a small gap at the start.
  std::string cohesion = "none";
  bool bonds = false;
  // The contacts' energy ledger ([checks] energy_ledger); --no-energy-ledger: off, the energy checks
  // with it, as LIGGGHTS computes no dissipation.
  bool energy_ledger = true;
};

// Runs the benchmark and prints the results on stdout (a human-readable block and one
// `BENCH_RESULT key=value ...` line for scripts). Returns the exit status (0).
// Throws InputError for a bad data file or arguments.
int bench_command(const BenchArgs& args);

}  // namespace mpdem::cli
