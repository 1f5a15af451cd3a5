// `mpdem plot OUTPUT_DIR`: runs the plot script built into the binary (python/mpdem/plot.py,
// generated/plot_script.hpp) as `python -c SCRIPT -- OUTPUT_DIR` (docs/output.md, "Plots").
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <fmt/core.h>

#include "cli/plot_command.hpp"
#include "plot_script.hpp"  // kPlotScript, generated from python/mpdem/plot.py by CMakeLists.txt

extern char** environ;

namespace mpdem::cli {

std::string default_plot_python() { return ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3"; }

std::vector<std::string> plot_command_line(const PlotArgs& args) {
  const std::string python = args.python.empty() ? default_plot_python() : args.python;
  // "--" ends the script's options: a folder named like an option stays the folder.
  return {python, "-c", kPlotScript, "--", args.output_dir.string()};
}

int plot_command(const PlotArgs& args) {
  std::vector<std::string> words = plot_command_line(args);
  std::vector<char*> argv;
  argv.reserve(words.size() + 1);
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::fflush(stdout);  // the script's lines come after anything printed before
  std::fflush(stderr);
  pid_t pid = 0;
  // posix_spawnp searches PATH for a name without '/'; glibc reports a failed exec here.
  const int err = ::posix_spawnp(&pid, words[0].c_str(), nullptr, nullptr, argv.data(), environ);
  if (err != 0) {
    fmt::print(stderr,
               "error: mpdem plot: cannot run the Python interpreter '{}': {} (it needs python3 with numpy and "
               "matplotlib; give another one with --python PATH)\n",
               words[0], std::strerror(err));
    return 2;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      fmt::print(stderr, "error: mpdem plot: waiting for '{}' failed: {}\n", words[0], std::strerror(errno));
      return 1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) {
    fmt::print(stderr, "error: mpdem plot: '{}' was stopped by signal {}\n", words[0], WTERMSIG(status));
    return 128 + WTERMSIG(status);
  }
  return 1;
}

void add_plot_command(CLI::App& app, ToolAction& action) {
  auto a = std::make_shared<PlotArgs>();
  auto* c = app.add_subcommand("plot", "PNG plots of a run's log.csv, barrier_groups.csv and profile CSVs, written to "
                                       "output_dir/plots/ (needs python3 with numpy and matplotlib)");
  c->add_option("output_dir", a->output_dir, "the run's output folder (holds log.csv)")->required();
  c->add_option("--python", a->python,
                "Python with numpy and matplotlib (default: /usr/bin/python3 if it exists, else python3 on PATH)");
  c->callback([a, &action] { action = [a] { return plot_command(*a); }; });
}

}  // namespace mpdem::cli
