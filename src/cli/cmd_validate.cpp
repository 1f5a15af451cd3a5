// `mpdem validate [CASE...] [--quick] [--output DIR]`: runs the thesis's validation cases and
// writes a Markdown report with one plot per case (docs/validation.md). Exit status 0 when every
// case passes, 1 when any fails (or its plot could not be drawn), 2 for bad arguments.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/core.h>

#include "cli/output_folder.hpp"
#include "io/output_folder.hpp"
#include "cli/tool_commands.hpp"
#include "core/input_error.hpp"
#include "validate/validation_suite.hpp"

namespace mpdem::cli {

namespace {

namespace fs = std::filesystem;

struct ValidateArgs {
  std::vector<std::string> cases;
  bool quick = false;
  bool list = false;
  fs::path output = "validation";
  fs::path cases_dir;  // "" = found from the working directory or the executable
  std::string python = "/usr/bin/python3";
};

fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path{} : exe.parent_path();
}

// examples/validation in the working directory, the executable's folder or one of their parents.
fs::path find_cases_dir() {
  for (const fs::path& start : {fs::current_path(), executable_dir()}) {
    for (fs::path d = start; !d.empty(); d = d.parent_path()) {
      if (fs::is_directory(d / "examples" / "validation")) return d / "examples" / "validation";
      if (d == d.parent_path()) break;
    }
  }
  return {};
}

int validate(const ValidateArgs& a) {
  if (a.list) {
    for (const validate::CaseSpec& c : validate::all_cases()) fmt::print("{}{}\n", c.name, c.quick ? "  (quick)" : "");
    return 0;
  }
  validate::SuiteOptions o;
  o.cases = a.cases;
  o.quick = a.quick;
  o.output_dir = fs::absolute(a.output);
  o.cases_dir = a.cases_dir.empty() ? find_cases_dir() : fs::absolute(a.cases_dir);
  if (o.cases_dir.empty() || !fs::is_directory(o.cases_dir))
    throw InputError("mpdem validate", 0, "--cases-dir",
                     "the folder examples/validation of the mpdem sources (not found from the working directory or "
                     "the executable; give it with --cases-dir)");
  o.plot_script = o.cases_dir.parent_path().parent_path() / "scripts" / "plot_validation.py";
  if (!fs::exists(o.plot_script))
    throw InputError("mpdem validate", 0, "--cases-dir",
                     "scripts/plot_validation.py beside examples/ (not found at " + o.plot_script.string() + ")");
  o.python = a.python;
  try {
    validate::select_cases(o.cases, o.quick);
  } catch (const std::invalid_argument& e) {
    throw InputError("mpdem validate", 0, "CASE", e.what());
  }
  ensure_output_folder(o.output_dir);
  const validate::SuiteResult r = validate::run_suite(o);
  std::size_t passed = 0;
  for (const auto& c : r.cases) passed += c.pass ? 1 : 0;
  fmt::print("\n{}\nreport: {}\nvalidation: {} passed, {} failed\n", validate::result_table(r.cases),
             (o.output_dir / "report.md").string(), passed, r.cases.size() - passed);
  return r.all_pass() ? 0 : 1;
}

}  // namespace

void add_validate_command(CLI::App& app, ToolAction& action) {
  auto a = std::make_shared<ValidateArgs>();
  auto* c = app.add_subcommand("validate", "run the thesis's validation cases; write a report with plots");
  c->add_option("case", a->cases, "cases to run (default: all; see --list)");
  c->add_flag("--quick", a->quick, "only the quick set (for CI)");
  c->add_flag("--list", a->list, "list the cases and exit");
  c->add_option("--output,-o", a->output, "report folder (default: ./validation)");
  c->add_option("--cases-dir", a->cases_dir, "folder of the case scenes (default: examples/validation, searched)");
  c->add_option("--python", a->python, "Python with matplotlib for the plots (default: /usr/bin/python3)");
  c->callback([a, &action] { action = [a] { return validate(*a); }; });
}

}  // namespace mpdem::cli
