#pragma once
// The CSV a validation case writes for one plot, read by scripts/plot_validation.py:
//   # title: ...            comment lines carry the plot's metadata
//   # xlabel: time t [s]
//   # ylabel: speed v_x [m/s]
//   # xscale: log           (optional; also yscale)
//   # hline: 0 plate        (optional, repeatable: a horizontal line at y = 0 labelled "plate")
//   time,<series> simulated,<series> analytic,...
// Columns ending in " simulated" are drawn as markers, the following "<series> analytic" (or
// "<series> reference") column as a line of the same colour; an empty field is a missing value.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mpdem::validate {

class PlotCsv {
 public:
  PlotCsv(std::string title, std::string xlabel, std::string ylabel);
  void set_log_x() { xscale_ = "log"; }
  void set_log_y() { yscale_ = "log"; }
  // A horizontal reference line (e.g. the plate a sphere falls through): `# hline: value label`.
  void add_hline(double y, const std::string& label) { hlines_.emplace_back(y, label); }
  void set_x_column(std::string name) { xcolumn_ = std::move(name); }  // header of column 1 (default "time")
  // Adds a series; returns its first column for add_row values (simulated, then the comparison).
  // `has_analytic` false: a simulated-only series (e.g. the adaptive step size). `kind` names the
  // comparison column: "analytic" (closed form) or "reference" (an independent fine run).
  std::size_t add_series(const std::string& label, bool has_analytic = true, const std::string& kind = "analytic");
  // One row: x, then per series its simulated (and analytic) value; NaN writes an empty field.
  void add_row(double x, const std::vector<double>& values);
  void write(const std::filesystem::path& file) const;

 private:
  std::string title_, xlabel_, ylabel_, xscale_ = "linear", yscale_ = "linear", xcolumn_ = "time";
  std::vector<std::string> columns_;
  std::vector<std::pair<double, std::string>> hlines_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace mpdem::validate
