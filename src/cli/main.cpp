// mpdem: command-line entry point. Parses the command line and dispatches to a subcommand;
// maps errors to exit statuses (2 bad input, 1 run failure).
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <new>

#include "cli/bench_command.hpp"
#include "cli/commands.hpp"
#include "cli/mpi_launcher.hpp"
#include "cli/openmp_environment.hpp"
#include "cli/plot_command.hpp"
#include "cli/run_paths.hpp"
#include "cli/tool_commands.hpp"
#include "core/input_error.hpp"
#include "parallel/communicator.hpp"
#include "core/run_error.hpp"

namespace {

int dispatch(int argc, char** argv) {
  CLI::App app{"mpdem - multiphysics soft-sphere Discrete Element Method engine"};
  app.set_version_flag("--version", std::string("mpdem ") + MPDEM_VERSION);
  app.require_subcommand(1);
  // Command-line errors read like the other errors (set before the subcommands, which inherit it).
  app.failure_message(
      [](const CLI::App* a, const CLI::Error& e) { return "error: " + CLI::FailureMessage::simple(a, e); });
  const CLI::Validator thread_count([](std::string& text) { return mpdem::cli::check_thread_count(text); },
                                    "1.." + std::to_string(mpdem::cli::kMaxThreads));

  mpdem::cli::RunArgs run;
  auto* run_cmd = app.add_subcommand("run", "run a scene");
  run_cmd->add_option("scene", run.scene, "scene file (TOML)")->required();
  run_cmd->add_option("--output,-o", run.output, "output folder (default: the scene's [output] dir)");
  run_cmd->add_option("--threads,-t", run.threads, "OpenMP threads (default: all cores)")->check(thread_count);
  run_cmd->add_flag("--quiet,-q", run.quiet, "no progress on stderr");
  run_cmd->add_flag("--overwrite", run.overwrite, "replace the outputs of an earlier run in the output folder");
  run_cmd->add_option("--resume", run.resume, "continue from a checkpoint written by an earlier run of this scene");

  std::filesystem::path check_scene;
  auto* check_cmd = app.add_subcommand(
      "check", "validate a scene; print a summary, the recommended time step and every problem found before step 1");
  check_cmd->add_option("scene", check_scene, "scene file (TOML)")->required();

  mpdem::cli::BenchArgs bench;
  auto* bench_cmd = app.add_subcommand("bench", "settled-bed benchmark (docs/benchmark.md)");
  bench_cmd->add_option("data", bench.data, "LAMMPS/LIGGGHTS data file (plain text)")
      ->required()
      ->check(CLI::ExistingFile);
  bench_cmd->add_option("--integrator", bench.integrator, "verlet or trapezoidal")
      ->check(CLI::IsMember({"verlet", "trapezoidal"}));
  bench_cmd->add_option("--phi", bench.phi, "trapezoidal weight")->check(CLI::Range(0.0, 1.0));
  bench_cmd->add_option("--threads,-t", bench.threads, "OpenMP threads")->check(thread_count);
  bench_cmd->add_option("--steps", bench.steps, "timed steps (0: 5000 for <= 50k particles, else 2000)")
      ->check(CLI::NonNegativeNumber);
  bench_cmd->add_option("--relax", bench.relax, "untimed steps first")->check(CLI::NonNegativeNumber);
  bench_cmd->add_option("--dt", bench.dt, "time step [s]")->check(CLI::PositiveNumber);
  bench_cmd->add_option("--skin", bench.skin, "Verlet skin [m]")->check(CLI::NonNegativeNumber);
  bench_cmd->add_option("--output", bench.output, "write the run's files there (a fresh or empty folder)");
  bench_cmd->add_flag("--clumps", bench.clumps,
                      "each sphere becomes a clump of 4 overlapping spheres (tetrahedron) inscribed in the bed's "
                      "smallest sphere; particles = members");
  bench_cmd
      ->add_option("--cohesion", bench.cohesion,
                   "none, jkr or sjkr (adhesion of spheres and walls) or bridges (capillary liquid bridges)")
      ->check(CLI::IsMember(mpdem::cli::kBenchCohesions));
  bench_cmd->add_flag("--bonds", bench.bonds,
                      "parallel bonds between the spheres (or members) closer than 10 um at the start");
  bench_cmd->add_flag("--no-energy-ledger{false}", bench.energy_ledger,
                      "the contacts' energies only for the logged steps, no energy checks ([checks] energy_ledger)");
  bench_cmd->add_option("--snapshot-every", bench.snapshot_every, "steps between particle VTU snapshots (0: none)")
      ->check(CLI::NonNegativeNumber);
  bench_cmd->add_option("--format", bench.format, "VTK format of the snapshots")
      ->check(CLI::IsMember({"ascii", "binary", "compressed"}));

  mpdem::cli::ToolAction tool;  // set by `generate` / `mesh` / `clump` when selected
  mpdem::cli::add_generate_command(app, tool);
  mpdem::cli::add_agglomerate_command(app, tool);
  mpdem::cli::add_mesh_command(app, tool);
  mpdem::cli::add_clump_command(app, tool);
  mpdem::cli::add_validate_command(app, tool);
  mpdem::cli::add_plot_command(app, tool);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  const mpdem::Communicator& comm = mpdem::Communicator::world();
  if (!comm.serial() && !*run_cmd && !*bench_cmd) {
    if (comm.rank() == 0)
      fmt::print(stderr, "error: only `mpdem run` and `mpdem bench` run on several ranks (mpirun -np {})\n",
                 comm.size());
    return 2;
  }
  // Several ranks: bad input is found by every rank alike (each reads the whole scene): rank 0
  // reports it and every rank exits 2. A RunError is decided on every rank alike too (from values
  // reduced over the ranks; its message names the rank that holds the culprit): rank 0 reports
  // it and every rank exits 1. Any other failure may be one rank's alone; it is reported with the
  // rank and stops all ranks (MPI_Abort), so none waits forever for the others.
  const auto fail = [&](int code, const std::string& text) {
    if (comm.serial()) {
      fmt::print(stderr, "\nerror: {}\n", text);
      return code;
    }
    fmt::print(stderr, "\nerror (rank {} of {}): {}\n", comm.rank(), comm.size(), text);
    std::fflush(stderr);
    comm.abort(code);
  };
  try {
    if (*run_cmd) return mpdem::cli::run_command(run);
    if (*check_cmd) return mpdem::cli::check_command(check_scene);
    if (*bench_cmd) return mpdem::cli::bench_command(bench);
    if (tool) return tool();
  } catch (const mpdem::InputError& e) {
    if (comm.rank() == 0) fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const mpdem::Interrupted& e) {
    if (comm.rank() != 0) return 128 + e.signal;  // every rank stops at the same step
    fmt::print(stderr, "\nstopped by signal {} at t = {:.9g} s (step {}).\n", e.signal, e.time, e.step);
    if (!e.checkpoint.empty())
      fmt::print(stderr, "checkpoint written to {}\nresume with: {}{}\n", e.checkpoint.string(),
                 mpdem::cli::launcher_command(comm.size()),
                 mpdem::cli::resume_command(argc > 0 ? argv[0] : "mpdem", run, e.checkpoint));
    return 128 + e.signal;
  } catch (const mpdem::RunError& e) {
    if (comm.serial()) return fail(1, e.what());
    if (comm.rank() == 0) fmt::print(stderr, "\nerror: {}\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {  // no library text: what ran out and what to do
    return fail(1, "out of memory: the run needs more memory than this machine has; use a smaller scene or "
                   "fewer coarse-grained points, or run on more nodes");
  } catch (const std::filesystem::filesystem_error& e) {
    return fail(1, fmt::format("cannot access '{}': {}", e.path1().string(), e.code().message()));
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
  return 0;
}

}  // namespace

// Nothing escapes: setting up the command line or reporting an error may itself throw (out of
// memory, a closed stderr); the exit status then still says "failed".
int main(int argc, char** argv) {
  mpdem::cli::apply_openmp_defaults(argv);  // first: it may re-execute the program
  try {
    const mpdem::MpiSession mpi(argc, argv);
    return dispatch(argc, argv);
  } catch (...) {
    std::fputs("error: unexpected failure\n", stderr);
    return 1;
  }
}
