#include "io/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/closest_name.hpp"
#include "core/input_error.hpp"
#include "core/input_file.hpp"

namespace mpdem {

namespace {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// The fields of `line`, at most `max_fields` of them; `more` tells whether the line has more.
std::vector<std::string> split_fields(std::string_view line, std::size_t max_fields, bool& more) {
  std::vector<std::string> out;
  std::size_t start = 0;
  more = false;
  for (;;) {
    if (out.size() == max_fields) {
      more = true;
      return out;
    }
    const std::size_t comma = line.find(',', start);
    out.emplace_back(trim(line.substr(start, comma == std::string_view::npos ? line.npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

// Reads the next line into `buf` without reading more than CsvTable::kMaxLineLength characters
// of it: Line::TooLong leaves the rest of the line unread.
enum class Line { Read, End, TooLong };
Line next_line(std::istream& in, std::string& buf, std::string_view& line) {
  buf.resize(CsvTable::kMaxLineLength + 1);  // + the terminating NUL getline stores
  in.getline(buf.data(), static_cast<std::streamsize>(buf.size()));
  const auto n = static_cast<std::size_t>(in.gcount());
  if (in.eof()) {
    line = std::string_view(buf.data(), n);
    return n == 0 ? Line::End : Line::Read;
  }
  if (in.fail()) {  // the buffer filled up before the newline
    line = std::string_view(buf.data(), n);
    return Line::TooLong;
  }
  line = std::string_view(buf.data(), n - 1);  // the newline was counted, not stored
  return Line::Read;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& file, std::size_t max_columns) {
  CsvTable t;
  t.file_ = file.string();
  if (const std::string why = input_file_problem(file); !why.empty())
    throw InputError(t.file_, 0, "", "file '" + t.file_ + "' " + why);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(t.file_, 0, "", "cannot open file '" + t.file_ + "'");

  std::string buf;
  std::string_view line;
  std::size_t line_no = 0;
  for (;;) {
    const Line got = next_line(in, buf, line);
    if (got == Line::End) break;
    ++line_no;
    if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);  // UTF-8 BOM
    line = trim(line);
    if (got == Line::TooLong) {
      if (!line.starts_with('#'))
        throw InputError(t.file_, line_no, "",
                         "line longer than the limit of " + std::to_string(kMaxLineLength) + " characters");
      in.clear();  // a long comment: skip the rest of it
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      continue;
    }
    if (line.empty() || line.front() == '#') continue;
    bool more = false;
    if (t.columns_.empty()) {
      std::vector<std::string> fields = split_fields(line, max_columns + kFieldMargin, more);
      if (more)
        throw InputError(t.file_, line_no, "",
                         "more than " + std::to_string(fields.size()) + " columns in the header; at most " +
                             std::to_string(max_columns) + " columns are known");
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
    std::vector<std::string> fields = split_fields(line, t.columns_.size() + kFieldMargin, more);
    if (more || fields.size() != t.columns_.size())
      throw InputError(t.file_, line_no, "",
                       "expected " + std::to_string(t.columns_.size()) + " fields as in the header (line " +
                           std::to_string(t.header_line_) + "), got " + (more ? "more than " : "") +
                           std::to_string(fields.size()));
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
