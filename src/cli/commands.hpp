#pragma once
// The subcommands of the `mpdem` executable. Each returns the process exit status:
// 0 success, 1 run failure (instability, non-convergence, domain stop), 2 bad input.
#include <filesystem>

namespace mpdem::cli {

struct RunArgs {
  std::filesystem::path scene;
  std::filesystem::path output;  // empty = scene's [output] dir
  int threads = 0;               // 0 = OpenMP default
  bool quiet = false;
  bool overwrite = false;        // replace the outputs of an earlier run in the output folder
  std::filesystem::path resume;  // checkpoint to continue from (empty = fresh run)
};

int run_command(const RunArgs& args);
int check_command(const std::filesystem::path& scene);

}  // namespace mpdem::cli
