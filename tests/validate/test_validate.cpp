// `mpdem validate` end to end: the quick set passes, report.md lists every quick case as PASS
// with its plots, every PNG exists, the CSVs carry simulated and analytic/reference columns; a
// case whose scene is broken on purpose (a step far too large to resolve the contact) fails with
// exit status 1; an unknown case name is bad input (exit status 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "support/run_command.hpp"
#include "validate/validation_suite.hpp"

using namespace mpdem;
namespace fs = std::filesystem;

namespace {
const fs::path kSource = MPDEM_SOURCE_DIR;
const std::string kCasesDir = "--cases-dir '" + (kSource / "examples" / "validation").string() + "'";

// The report's table row of a case, or "" when the case is not in the table.
std::string table_row(const std::string& report, const std::string& name) {
  const std::string start = "| " + name + " |";
  const std::size_t k = report.find(start);
  if (k == std::string::npos) return "";
  return report.substr(k, report.find('\n', k) - k);
}
}  // namespace

TEST(Validate, QuickSetPassesWithReportAndPlots) {
  const fs::path dir = test::fresh_dir("validate_quick");
  const test::CommandResult r = test::run_mpdem("validate --quick --output report " + kCasesDir, dir);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const std::string report = test::slurp(dir / "report" / "report.md");
  const auto quick = validate::select_cases({}, true);
  ASSERT_GE(quick.size(), 8u);  // every family is represented
  for (const validate::CaseSpec& c : quick) {
    const std::string row = table_row(report, c.name);
    ASSERT_FALSE(row.empty()) << c.name << " missing from report.md";
    EXPECT_TRUE(row.ends_with("| PASS |")) << row;
  }
  // Every image the report shows exists, and every quick case shows at least one.
  const std::regex image(R"(!\[([^\]]+)\]\(([^)]+\.png)\))");
  std::size_t images = 0;
  for (auto it = std::sregex_iterator(report.begin(), report.end(), image); it != std::sregex_iterator(); ++it) {
    const fs::path png = dir / "report" / (*it)[2].str();
    EXPECT_TRUE(fs::exists(png) && fs::file_size(png) > 1000) << png;
    const fs::path csv = fs::path(png).replace_extension(".csv");
    const std::string text = test::slurp(csv);
    EXPECT_NE(text.find(" simulated"), std::string::npos) << csv;
    ++images;
  }
  for (const validate::CaseSpec& c : quick)
    EXPECT_NE(report.find("![" + c.name), std::string::npos) << c.name << " has no plot in the report";
  EXPECT_GE(images, quick.size());
  EXPECT_NE(r.out.find("validation: " + std::to_string(quick.size()) + " passed, 0 failed"), std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

TEST(Validate, FailingCaseGivesExitStatusOne) {
  // A copy of one case with dt = 1e-4 s, a fifth of the contact time: the velocity curve misses
  // the Hertz reference by ~5 % of the impact speed, beyond the 1 % tolerance.
  const fs::path dir = test::fresh_dir("validate_fail");
  const fs::path cases = dir / "examples" / "validation", src = kSource / "examples" / "validation";
  fs::create_directories(cases);
  fs::create_directories(dir / "scripts");
  fs::copy(src / "two_particle_contact", cases / "two_particle_contact");
  fs::copy_file(kSource / "scripts" / "plot_validation.py", dir / "scripts" / "plot_validation.py");
  std::string scene = test::slurp(cases / "two_particle_contact" / "scene.toml");
  const std::size_t k = scene.find("dt = 1e-6");
  ASSERT_NE(k, std::string::npos);
  scene.replace(k, 9, "dt = 1e-4");
  test::write_text(cases / "two_particle_contact" / "scene.toml", scene);
  const test::CommandResult r = test::run_mpdem(
      "validate two_particle_contact --output report --cases-dir '" + cases.string() + "'", dir);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(table_row(test::slurp(dir / "report" / "report.md"), "two_particle_contact").ends_with("| FAIL |"));
  fs::remove_all(dir);
}

TEST(Validate, UnknownCaseIsBadInput) {
  const fs::path dir = test::fresh_dir("validate_unknown");
  const test::CommandResult r = test::run_mpdem("validate no_such_case --output report " + kCasesDir, dir);
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("two_particle_contact"), std::string::npos) << r.err;  // lists the known cases
  EXPECT_FALSE(fs::exists(dir / "report" / "report.md"));
  fs::remove_all(dir);
}
