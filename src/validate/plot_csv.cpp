// PlotCsv: the per-plot CSV of a validation case (format in plot_csv.hpp).
#include "validate/plot_csv.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/core.h>

namespace mpdem::validate {

PlotCsv::PlotCsv(std::string title, std::string xlabel, std::string ylabel)
    : title_(std::move(title)), xlabel_(std::move(xlabel)), ylabel_(std::move(ylabel)) {}

std::size_t PlotCsv::add_series(const std::string& label, bool has_analytic, const std::string& kind) {
  const std::size_t first = columns_.size();
  columns_.push_back(label + " simulated");
  if (has_analytic) columns_.push_back(label + " " + kind);
  return first;
}

void PlotCsv::add_row(double x, const std::vector<double>& values) {
  if (values.size() != columns_.size()) throw std::logic_error("PlotCsv::add_row: wrong number of values");
  std::vector<double> row{x};
  row.insert(row.end(), values.begin(), values.end());
  rows_.push_back(std::move(row));
}

void PlotCsv::write(const std::filesystem::path& file) const {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << "# title: " << title_ << "\n# xlabel: " << xlabel_ << "\n# ylabel: " << ylabel_ << "\n# xscale: " << xscale_
      << "\n# yscale: " << yscale_ << '\n';
  for (const auto& [y, label] : hlines_) out << "# hline: " << fmt::format("{:.10g}", y) << ' ' << label << '\n';
  out << xcolumn_;
  for (const std::string& c : columns_) out << ',' << c;
  out << '\n';
  for (const std::vector<double>& row : rows_) {
    for (std::size_t k = 0; k < row.size(); ++k) {
      if (k > 0) out << ',';
      if (std::isfinite(row[k])) out << fmt::format("{:.10g}", row[k]);
    }
    out << '\n';
  }
  if (!out) throw std::runtime_error("error writing " + file.string());
}

}  // namespace mpdem::validate
