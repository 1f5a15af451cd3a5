#include "cli/commands.hpp"
#include "cli/scene_summary.hpp"

namespace mpdem::cli {

int check_command(const std::filesystem::path& scene_file) {
  const Scene scene = load_scene(scene_file);
  print_summary(scene);
  warn_about_time_step(scene);
  return 0;
}

}  // namespace mpdem::cli
