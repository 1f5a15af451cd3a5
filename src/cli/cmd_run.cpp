#include <fmt/core.h>
#include <omp.h>

#include "check/scene_checks.hpp"
#include "cli/commands.hpp"
#include "cli/output_folder.hpp"
#include "cli/run_paths.hpp"
#include "cli/scene_summary.hpp"
#include "sim/simulation.hpp"

namespace mpdem::cli {

int run_command(const RunArgs& args) {
  if (args.threads > 0) omp_set_num_threads(args.threads);
  Scene scene = load_scene(args.scene);  // InputError propagates to main: exit 2, nothing written
  warn_about_time_step(scene);
  // A resumed run continues from the checkpoint's state, not the scene's initial one.
  if (args.resume.empty()) {
    const std::size_t stopping = print_problems(check_scene(scene), true);
    if (stopping > 0) {
      fmt::print(stderr, "error: the run would stop at its first step ({} problem{} above); nothing was run\n",
                 stopping, stopping == 1 ? "" : "s");
      return 2;
    }
  }
  RunOptions opt;
  opt.output_dir = args.output;
  opt.progress = !args.quiet;
  // A resumed run continues in its own (non-empty) output folder.
  if (args.resume.empty()) prepare_output_folder(output_dir_for(scene, opt), args.overwrite);
  Simulation sim(std::move(scene), opt);
  if (!args.resume.empty()) sim.resume_from(args.resume);
  const RunSummary s = sim.run();
  if (!args.quiet) {
    fmt::print(stderr, "{} steps, {} interaction evaluations, {} particles removed\n", s.steps, s.evaluations,
               s.removed);
    fmt::print(stderr, "{}\n", summary_line(s));
  }
  // Even with --quiet: the run is complete but its results are suspect. The exit status stays 0
  // (every output was written; 1 means the run could not finish); warnings.txt keeps the warning
  // beside the results.
  if (const std::string w = drift_warning(s); !w.empty()) fmt::print(stderr, "\n{}\n", w);
  return 0;
}

}  // namespace mpdem::cli
