#include <fmt/core.h>
#include <omp.h>

#include <algorithm>
#include <exception>
#include <functional>

#include "check/scene_checks.hpp"
#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/run_paths.hpp"
#include "cli/scene_summary.hpp"
#include "core/input_error.hpp"
#include "io/output_folder.hpp"
#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "scene/scene_reader.hpp"

namespace mpdem::cli {

namespace {

// Runs `f` (a step on the output folder) on rank 0 alone; its refusal stops every rank: rank 0
// rethrows the InputError (main prints it), the others throw one that main does not print, and
// all exit 2 (a rank left waiting for the others would hang).
void on_rank_0(const Communicator& comm, const std::function<void()>& f) {
  std::exception_ptr refused;
  if (comm.rank() == 0) {
    try {
      f();
    } catch (const InputError&) {
      refused = std::current_exception();
    }
  }
  if (!comm.any(refused != nullptr)) return;
  if (refused) std::rethrow_exception(refused);
  throw InputError("", 0, "", "the output folder was refused on rank 0");
}

}  // namespace

int run_command(const RunArgs& args) {
  if (args.threads > 0) omp_set_num_threads(args.threads);
  // On several ranks every rank loads and checks the whole scene and takes the same decisions;
  // rank 0 alone speaks and prepares the output folder.
  const Communicator& comm = Communicator::world();
  const bool speaks = comm.rank() == 0;
  Scene scene = load_scene(args.scene);  // InputError propagates to main: exit 2, nothing written
  if (speaks) warn_about_time_step(scene);
  // A resumed run continues from the checkpoint's state, not the scene's initial one.
  if (args.resume.empty()) {
    const auto problems = check_scene(scene);
    const std::size_t stopping = speaks ? print_problems(problems, true)
                                        : static_cast<std::size_t>(
                                              std::count_if(problems.begin(), problems.end(),
                                                            [](const SceneProblem& p) { return p.stops_run; }));
    if (stopping > 0) {
      if (speaks)
        fmt::print(stderr, "error: the run would stop at its first step ({} problem{} above); nothing was run\n",
                   stopping, stopping == 1 ? "" : "s");
      return 2;
    }
  }
  RunOptions opt;
  opt.output_dir = args.output;
  opt.progress = !args.quiet;
  // A resumed run continues in its own (non-empty) output folder.
  const std::filesystem::path dir = output_dir_for(scene, opt);
  if (args.resume.empty()) on_rank_0(comm, [&] { prepare_output_folder(dir, args.overwrite); });
  Simulation sim(std::move(scene), opt);
  if (!args.resume.empty()) {
    sim.resume_from(args.resume);
    on_rank_0(comm, [&] { ensure_output_folder(dir); });  // once the checkpoint is read: a refused one writes nothing
  }
  const RunSummary s = sim.run();
  if (!speaks) return 0;
  if (!args.quiet) {
    fmt::print(stderr, "{}\n", counts_line(s));
    fmt::print(stderr, "{}\n", summary_line(s));
  }
  // Even with --quiet: the run is complete but its results are suspect. The exit status stays 0
  // (every output was written; 1 means the run could not finish); warnings.txt keeps the warning
  // beside the results.
  if (const std::string w = drift_warning(s); !w.empty()) fmt::print(stderr, "\n{}\n", w);
  return 0;
}

}  // namespace mpdem::cli
