#pragma once
// The validation suite behind `mpdem validate`: selects cases, runs each oracle, renders the
// plots (scripts/plot_validation.py) and writes <output>/report.md with the pass/fail table.
#include <filesystem>
#include <string>
#include <vector>

#include "validate/validation_case.hpp"

namespace mpdem::validate {

struct SuiteOptions {
  std::vector<std::string> cases;     // names to run; empty = all (or the quick set)
  bool quick = false;                 // only the cases marked quick
  std::filesystem::path output_dir;   // report folder (created)
  std::filesystem::path cases_dir;    // examples/validation
  std::filesystem::path plot_script;  // scripts/plot_validation.py
  std::string python = "/usr/bin/python3";
};

struct SuiteResult {
  std::vector<CaseResult> cases;
  bool plots_ok = true;  // the plot script ran and every PNG exists
  bool all_pass() const;
};

// Throws std::invalid_argument naming the known cases when a requested name is unknown.
std::vector<CaseSpec> select_cases(const std::vector<std::string>& names, bool quick);

// Runs the cases (printing one line per case on stdout), plots, writes report.md.
SuiteResult run_suite(const SuiteOptions& options);

// The Markdown pass/fail table of the results.
std::string result_table(const std::vector<CaseResult>& results);

}  // namespace mpdem::validate
