#include "io/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <system_error>

#include "io/closest_name.hpp"
#include "io/input_error.hpp"

namespace mpdem {

namespace {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.emplace_back(trim(line.substr(start, comma == std::string_view::npos ? line.npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& file) {
  CsvTable t;
  t.file_ = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(t.file_, 0, "", "file '" + t.file_ + "' does not exist (or is not a regular file)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(t.file_, 0, "", "cannot open file '" + t.file_ + "'");

  std::string raw;
  std::size_t line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    std::string_view line = raw;
    if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);  // UTF-8 BOM
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string> fields = split_fields(line);
    if (t.columns_.empty()) {
      t.header_line_ = line_no;
      for (std::size_t c = 0; c < fields.size(); ++c) {
        if (fields[c].empty())
          throw InputError(t.file_, line_no, "",
                           "empty column name in the header (column " + std::to_string(c + 1) + ")");
        for (std::size_t k = 0; k < c; ++k)
          if (fields[k] == fields[c]) throw InputError(t.file_, line_no, fields[c], "duplicate column in the header");
      }
      t.columns_ = std::move(fields);
      continue;
    }
    if (fields.size() != t.columns_.size())
      throw InputError(t.file_, line_no, "",
                       "expected " + std::to_string(t.columns_.size()) + " fields as in the header (line " +
                           std::to_string(t.header_line_) + "), got " + std::to_string(fields.size()));
    t.rows_.push_back({line_no, std::move(fields)});
  }
  if (t.columns_.empty()) throw InputError(t.file_, 0, "", "empty file: expected a header row of column names");
  return t;
}

int CsvTable::column(std::string_view name) const {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c] == name) return static_cast<int>(c);
  return -1;
}

void CsvTable::check_known(std::span<const std::string_view> known) const {
  for (const std::string& name : columns_) {
    bool ok = false;
    for (std::string_view k : known) ok = ok || k == name;
    if (!ok) throw InputError(file_, header_line_, name, "unknown column" + did_you_mean(name, known));
  }
}

void CsvTable::require(std::string_view name) const {
  if (column(name) < 0)
    throw InputError(file_, header_line_, std::string(name), "missing required column in the header");
}

double CsvTable::number(const CsvRow& row, int col) const {
  const std::string& s = row.fields[col];
  if (s.empty()) fail(row, col, "expected a number, got an empty field");
  const char* first = s.data() + (s.front() == '+' ? 1 : 0);
  const char* last = s.data() + s.size();
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec == std::errc::result_out_of_range) fail(row, col, "number '" + s + "' is out of range");
  if (ec != std::errc() || ptr != last) fail(row, col, "expected a number, got '" + s + "'");
  if (!std::isfinite(v)) fail(row, col, "expected a finite number, got '" + s + "'");
  return v;
}

double CsvTable::number(const CsvRow& row, int col, Range r, std::string_view what) const {
  const double v = number(row, col);
  if (!r.contains(v)) fail(row, col, "expected " + std::string(what) + " " + r.text() + ", got " + row.fields[col]);
  return v;
}

double CsvTable::number_or(const CsvRow& row, int col, double fallback, Range r, std::string_view what) const {
  if (!missing(row, col)) return number(row, col, r, what);
  // Defaults come from validated materials, but a hand-built Model may still hold bad values.
  if (!r.contains(fallback))
    throw InputError(file_, row.line, std::string(what),
                     "expected " + std::string(what) + " " + r.text() + ", got the default " + number_text(fallback));
  return fallback;
}

std::int64_t CsvTable::integer(const CsvRow& row, int col) const {
  const std::string& s = row.fields[col];
  if (s.empty()) fail(row, col, "expected an integer, got an empty field");
  const char* first = s.data() + (s.front() == '+' ? 1 : 0);
  const char* last = s.data() + s.size();
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec == std::errc::result_out_of_range) fail(row, col, "integer '" + s + "' is out of range");
  if (ec != std::errc() || ptr != last) fail(row, col, "expected an integer, got '" + s + "'");
  return v;
}

void CsvTable::fail(const CsvRow& row, int col, const std::string& message) const {
  throw InputError(file_, row.line, col >= 0 ? columns_[col] : std::string(), message);
}

}  // namespace mpdem
