#pragma once
// `mpdem plot OUTPUT_DIR`: PNG plots of a run's outputs (log.csv, barrier_groups.csv, profile CSVs)
// in OUTPUT_DIR/plots/ (docs/output.md, "Plots"). They are drawn by python/mpdem/plot.py (numpy and
// matplotlib), whose text the binary carries (built into generated/plot_script.hpp), so an
// installed mpdem needs no file besides itself; the command runs it with a Python interpreter.
#include <filesystem>
#include <string>
#include <vector>

#include "cli/tool_commands.hpp"

namespace mpdem::cli {

struct PlotArgs {
  std::filesystem::path output_dir;  // the run's output folder
  std::string python;                // interpreter; empty: /usr/bin/python3 if it exists, else python3 on PATH
};

// The interpreter `mpdem plot` runs when --python is not given.
std::string default_plot_python();

// The interpreter's argument list: python -c SCRIPT -- OUTPUT_DIR.
std::vector<std::string> plot_command_line(const PlotArgs& args);

// Runs the plot script (no shell: the words go to the interpreter as they are) and waits for it.
// Returns its exit status (0 done, 1 a plot failed, 2 bad folder or no matplotlib), 2 when the
// interpreter cannot be started (with one message on stderr), 128 + N when signal N killed it.
int plot_command(const PlotArgs& args);

// Registers `mpdem plot` on the app (the pattern of tool_commands.hpp).
void add_plot_command(CLI::App& app, ToolAction& action);

}  // namespace mpdem::cli
