#include <fmt/core.h>

#include <cstdio>

#include "check/scene_checks.hpp"
#include "cli/commands.hpp"
#include "cli/scene_summary.hpp"

namespace mpdem::cli {

int check_command(const std::filesystem::path& scene_file) {
  const Scene scene = load_scene(scene_file);
  print_summary(scene);
  warn_about_time_step(scene);
  std::fflush(stdout);  // the summary before the problems (stderr) also when both go to one pipe
  const SceneProblems problems = check_scene(scene);
  const std::size_t errors = print_problems(problems, false);
  if (!problems.empty())
    fmt::print(stderr, "check: {} error{}, {} warning{} before step 1\n", errors, errors == 1 ? "" : "s",
               problems.size() - errors, problems.size() - errors == 1 ? "" : "s");
  return errors > 0 ? 2 : 0;
}

}  // namespace mpdem::cli
