// run_suite: cases -> CSVs -> PNGs -> report.md (validation_suite.hpp, docs/validation.md).
#include "validate/validation_suite.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <fmt/core.h>

namespace mpdem::validate {

namespace fs = std::filesystem;

bool SuiteResult::all_pass() const {
  if (!plots_ok) return false;
  for (const CaseResult& c : cases)
    if (!c.pass) return false;
  return true;
}

std::vector<CaseSpec> select_cases(const std::vector<std::string>& names, bool quick) {
  std::vector<CaseSpec> all = all_cases(), chosen;
  if (names.empty()) {
    for (CaseSpec& c : all)
      if (!quick || c.quick) chosen.push_back(std::move(c));
    return chosen;
  }
  for (const std::string& n : names) {
    bool found = false;
    for (const CaseSpec& c : all)
      if (c.name == n) {
        chosen.push_back(c);
        found = true;
      }
    if (!found) {
      std::string known;
      for (const CaseSpec& c : all) known += (known.empty() ? "" : ", ") + c.name;
      throw std::invalid_argument(fmt::format("unknown validation case '{}' (known: {})", n, known));
    }
  }
  return chosen;
}

namespace {

std::string number(double v) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return "inf";
  return fmt::format("{:.3g}", v);
}

std::string escape(std::string s) {  // a '|' would split a Markdown table cell
  for (std::size_t k = s.find('|'); k != std::string::npos; k = s.find('|', k + 2)) s.replace(k, 1, "\\|");
  return s;
}

// Runs the plot script on the stems; true when it succeeded and every PNG exists.
bool plot(const SuiteOptions& o, const std::vector<CaseResult>& results) {
  std::string cmd = fmt::format("\"{}\" \"{}\" \"{}\"", o.python, o.plot_script.string(), o.output_dir.string());
  std::size_t n = 0;
  for (const CaseResult& c : results)
    for (const std::string& p : c.plots) {
      cmd += fmt::format(" \"{}\"", p);
      ++n;
    }
  if (n == 0) return true;
  if (std::system(cmd.c_str()) != 0) {
    fmt::print(stderr, "error: the plot script failed: {}\n", cmd);
    return false;
  }
  bool ok = true;
  for (const CaseResult& c : results)
    for (const std::string& p : c.plots)
      if (!fs::exists(o.output_dir / (p + ".png"))) {
        fmt::print(stderr, "error: plot {} was not written\n", (o.output_dir / (p + ".png")).string());
        ok = false;
      }
  return ok;
}

void write_report(const SuiteOptions& o, const SuiteResult& r) {
  std::size_t passed = 0;
  for (const CaseResult& c : r.cases) passed += c.pass ? 1 : 0;
  std::ofstream out(o.output_dir / "report.md");
  if (!out) throw std::runtime_error("cannot write " + (o.output_dir / "report.md").string());
  out << "# mpdem validation report\n\n";
  out << fmt::format("mpdem {}, `mpdem validate{}`: {} cases, {} passed, {} failed{}.\n\n", MPDEM_VERSION,
                     o.quick ? " --quick" : "", r.cases.size(), passed, r.cases.size() - passed,
                     r.plots_ok ? "" : "; PLOTTING FAILED");
  out << "Each case is a scene in `examples/validation/<case>/` (runnable with `mpdem run`) driven in-process by "
         "its oracle in `src/validate/`; see docs/validation.md.\n\n";
  out << result_table(r.cases) << "\n";
  for (const CaseResult& c : r.cases) {
    out << fmt::format("## {} ({}) - {}\n\n", c.name, c.figure, c.pass ? "PASS" : "FAIL");
    out << fmt::format("Oracle: {}.\n\nTolerance {}, measured {}. {}. ({:.1f} s)\n\n", c.oracle, number(c.tolerance),
                       number(c.error), c.note, c.seconds);
    for (const std::string& p : c.plots) out << fmt::format("![{}]({}.png)\n\n", p, p);
  }
}

}  // namespace

std::string result_table(const std::vector<CaseResult>& results) {
  std::string t =
      "| case | thesis figure | oracle | tolerance | measured error | result |\n|---|---|---|---|---|---|\n";
  for (const CaseResult& c : results)
    t += fmt::format("| {} | {} | {} | {} | {} | {} |\n", c.name, c.figure, escape(c.oracle), number(c.tolerance),
                     number(c.error), c.pass ? "PASS" : "FAIL");
  return t;
}

SuiteResult run_suite(const SuiteOptions& o) {
  const std::vector<CaseSpec> cases = select_cases(o.cases, o.quick);
  fs::create_directories(o.output_dir);
  SuiteResult r;
  for (const CaseSpec& spec : cases) {
    const auto t0 = std::chrono::steady_clock::now();
    CaseResult c;
    try {
      c = spec.run(CaseContext{o.cases_dir / spec.name, o.output_dir});
    } catch (const std::exception& e) {  // a run that stops (RunError, bad scene) is a failed case
      c.name = spec.name;
      c.oracle = "(the case stopped before its comparison)";
      c.tolerance = std::numeric_limits<double>::quiet_NaN();
      c.error = std::numeric_limits<double>::infinity();
      c.pass = false;
      c.note = std::string("the case stopped: ") + e.what();
    }
    c.figure = spec.figure;
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print("{:<24} {}  error {:<10} tolerance {:<8} ({:.1f} s)\n", c.name, c.pass ? "PASS" : "FAIL",
               number(c.error), number(c.tolerance), c.seconds);
    std::fflush(stdout);
    r.cases.push_back(std::move(c));
  }
  r.plots_ok = plot(o, r.cases);
  write_report(o, r);
  return r;
}

}  // namespace mpdem::validate
