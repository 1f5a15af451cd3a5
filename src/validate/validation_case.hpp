#pragma once
// One validation case of `mpdem validate` (docs/validation.md): a scene folder
// examples/validation/<name>/ that `mpdem run` can also run, and an oracle that drives the scene
// in-process, compares it with a closed form (or an independent reference integration) and
// writes one CSV per plot. The cases are grouped by family: mechanical, thermal,
// electromagnetic and time stepping.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace mpdem::validate {

// Where a case reads its scene and writes its CSVs.
struct CaseContext {
  std::filesystem::path case_dir;    // examples/validation/<name>
  std::filesystem::path output_dir;  // the report folder; CSVs go here as <plot>.csv
};

struct CaseResult {
  std::string name;                // case name = folder name
  std::string figure;              // the thesis figure(s) it reproduces (set by the suite)
  std::string oracle;              // what the simulation is compared with, and the error metric
  double tolerance = 0.0;          // the metric's limit
  double error = 0.0;              // the measured metric
  bool pass = false;               // error <= tolerance (and any extra condition in `oracle`)
  std::string note;                // extra measured numbers, for the report
  std::vector<std::string> plots;  // CSV stems written to the output folder (one PNG each)
  double seconds = 0.0;            // wall time of the case
};

struct CaseSpec {
  std::string name;
  std::string figure;  // thesis figure(s), also reported when the case stops early
  bool quick = false;  // part of `mpdem validate --quick`
  std::function<CaseResult(const CaseContext&)> run;
};

// The families (one file each).
std::vector<CaseSpec> mechanical_cases();
std::vector<CaseSpec> thermal_cases();
std::vector<CaseSpec> electromagnetic_cases();
std::vector<CaseSpec> time_stepping_cases();

// All cases in report order.
std::vector<CaseSpec> all_cases();

}  // namespace mpdem::validate
