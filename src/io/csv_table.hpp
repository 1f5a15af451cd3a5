#pragma once
// CsvTable: a small generic reader for the particle and barrier CSV files. A header row of
// column names, then rows of fields; whitespace around fields is trimmed, blank lines and lines
// starting with '#' are skipped, and every row remembers its line number so that each error can
// name file, line and column. Fields are plain (no quoting): names and numbers never contain
// commas in these formats.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/value_range.hpp"

namespace mpdem {

struct CsvRow {
  std::size_t line = 0;             // 1-based line in the file
  std::vector<std::string> fields;  // trimmed, one per header column
};

class CsvTable {
 public:
  // Longest line read (characters, without the newline): a longer one is refused before it is
  // read whole, except a comment, which is skipped.
  static constexpr std::size_t kMaxLineLength = 65536;
  // Fields split beyond the header's column count (the header's: beyond `max_columns`) before
  // a line is refused: enough to report a small miscount exactly, few enough that a runaway row
  // is refused without splitting all of it.
  static constexpr std::size_t kFieldMargin = 8;

  // Reads the whole file. Throws InputError for a missing or empty file, a line longer than
  // kMaxLineLength, a header of more than max_columns + kFieldMargin columns (readers pass the
  // number of columns they know), an empty or duplicate column name, or a row whose field count
  // differs from the header's.
  static CsvTable read(const std::filesystem::path& file, std::size_t max_columns = 256);

  const std::string& file() const { return file_; }
  std::size_t header_line() const { return header_line_; }
  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<CsvRow>& rows() const { return rows_; }

  int column(std::string_view name) const;  // index of a column, -1 when absent
  // Throws InputError naming the first column not in `known` (with a spelling suggestion).
  void check_known(std::span<const std::string_view> known) const;
  // Throws InputError when a required column is absent.
  void require(std::string_view name) const;

  // True when the column is absent or the row's field is empty (the caller's default applies).
  bool missing(const CsvRow& row, int col) const { return col < 0 || row.fields[col].empty(); }
  const std::string& text(const CsvRow& row, int col) const { return row.fields[col]; }
  // Parses a finite number (std::from_chars; a leading '+' is allowed). Throws InputError.
  double number(const CsvRow& row, int col) const;
  // number() checked against `r`: "expected <what> <r>, got <field>".
  double number(const CsvRow& row, int col, Range r, std::string_view what) const;
  // The field's number, or `fallback` when the field is missing; either is checked against `r`.
  double number_or(const CsvRow& row, int col, double fallback, Range r, std::string_view what) const;
  // Parses a decimal integer. Throws InputError.
  std::int64_t integer(const CsvRow& row, int col) const;
  // Throws InputError "file:line: 'column': message".
  [[noreturn]] void fail(const CsvRow& row, int col, const std::string& message) const;

 private:
  std::string file_;
  std::size_t header_line_ = 0;
  std::vector<std::string> columns_;
  std::vector<CsvRow> rows_;
};

}  // namespace mpdem
