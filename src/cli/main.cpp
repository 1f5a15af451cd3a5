// mpdem: command-line entry point. Parses the command line and dispatches to a subcommand;
// maps errors to exit statuses (2 bad input, 1 run failure).
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "cli/commands.hpp"
#include "cli/tool_commands.hpp"
#include "io/input_error.hpp"
#include "sim/run_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mpdem - multiphysics soft-sphere Discrete Element Method engine"};
  app.set_version_flag("--version", std::string("mpdem ") + MPDEM_VERSION);
  app.require_subcommand(1);

  mpdem::cli::RunArgs run;
  auto* run_cmd = app.add_subcommand("run", "run a scene");
  run_cmd->add_option("scene", run.scene, "scene file (TOML)")->required();
  run_cmd->add_option("--output,-o", run.output, "output folder (default: the scene's [output] dir)");
  run_cmd->add_option("--threads,-t", run.threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run_cmd->add_flag("--quiet,-q", run.quiet, "no progress on stderr");
  run_cmd->add_flag("--overwrite", run.overwrite, "replace the outputs of an earlier run in the output folder");

  std::filesystem::path check_scene;
  auto* check_cmd = app.add_subcommand("check", "validate a scene; print a summary and the recommended time step");
  check_cmd->add_option("scene", check_scene, "scene file (TOML)")->required();

  mpdem::cli::ToolAction tool;  // set by `generate` / `mesh` when selected
  mpdem::cli::add_generate_command(app, tool);
  mpdem::cli::add_mesh_command(app, tool);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*run_cmd) return mpdem::cli::run_command(run);
    if (*check_cmd) return mpdem::cli::check_command(check_scene);
    if (tool) return tool();
  } catch (const mpdem::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const mpdem::RunError& e) {
    fmt::print(stderr, "\nerror: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "\nerror: {}\n", e.what());
    return 1;
  }
  return 0;
}
