#include <fmt/core.h>

#include <cstdio>

#include "check/scene_checks.hpp"
#include "cli/commands.hpp"
#include "cli/scene_summary.hpp"
#include "scene/scene_reader.hpp"

namespace mpdem::cli {

int check_command(const std::filesystem::path& scene_file) {
  const Scene scene = load_scene(scene_file);
  print_summary(scene);
  const std::size_t dt_warning = warn_about_time_step(scene) ? 1 : 0;
  std::fflush(stdout);  // the summary before the problems (stderr) also when both go to one pipe
  const SceneProblems problems = check_scene(scene);
  const std::size_t errors = print_problems(problems, false);
  const std::size_t warnings = problems.size() - errors + dt_warning;
  // Always the closing count, also "0 errors, 0 warnings": a script can rely on the line.
  fmt::print(stderr, "check: {} error{}, {} warning{} before step 1\n", errors, errors == 1 ? "" : "s", warnings,
             warnings == 1 ? "" : "s");
  return errors > 0 ? 2 : 0;
}

}  // namespace mpdem::cli
