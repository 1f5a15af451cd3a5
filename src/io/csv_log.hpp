#pragma once
// CSV logs for analysis: time series written row by row (the particle snapshots are
// io/particle_csv_writer.hpp).
// Numbers carry 17 significant digits so they round-trip exactly; integral values below 2^53
// print as integers (step counts, ids, contact counts read naturally).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <string>
#include <vector>

namespace mpdem {

// Appends v to out: an integer when v is integral and |v| < 2^53, else "%.17g" (locale free).
void append_csv_number(std::string& out, double v);

// Writes a CSV snapshot as a complete file, atomically (core/atomic_file.hpp, Durability::kill):
// `header` and a line break, then rows k = 0 .. rows-1, each appended by row(line, k) with its line
// break; the text is handed to the file in pieces of about 64 KiB (a large snapshot is not held whole).
void write_csv_snapshot(const std::filesystem::path& file, std::string_view header, std::size_t rows,
                        const std::function<void(std::string& line, std::size_t k)>& row);

// A name usable in a CSV header: non-empty, without ',', '"' or line breaks. Names that become
// log columns (inlets, sinks, barrier groups) are checked with it when the scene is read.
inline bool is_column_name(std::string_view name) {
  return !name.empty() && name.find_first_of(",\"\r\n") == std::string_view::npos;
}

// A time-series log with a fixed header. Rows are buffered and appended as whole lines
// (core/atomic_file.hpp append_complete_lines) at every flush(), when the buffer grows large,
// and in the destructor, so a killed run keeps every flushed row intact.
class CsvLog {
 public:
  enum class Open {
    replace,  // start a new file with the header (default)
    append,   // continue an existing file with the same header (resume); else start a new one
  };

  // Column names must be non-empty and free of ',', '"' and line breaks (std::invalid_argument).
  // Throws std::runtime_error if the file cannot be written, or if Open::append finds a file
  // whose header differs from `columns`.
  CsvLog(std::filesystem::path file, std::vector<std::string> columns, Open mode = Open::replace);
  ~CsvLog();
  CsvLog(const CsvLog&) = delete;
  CsvLog& operator=(const CsvLog&) = delete;

  // Buffers one row; throws std::logic_error if values.size() != number of columns.
  void row(std::span<const double> values);
  // Buffers one row of fields already formatted (a text column among numbers: numbers formatted
  // with append_csv_number), each free of ',', '"' and line breaks; std::logic_error otherwise.
  void text_row(std::span<const std::string> fields);
  // Writes the buffered rows to the file. Throws std::runtime_error on a write failure.
  void flush();

  const std::vector<std::string>& columns() const { return columns_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::vector<std::string> columns_;
  std::string buffer_;
};

}  // namespace mpdem
