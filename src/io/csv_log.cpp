#include "io/csv_log.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/atomic_file.hpp"

namespace mpdem {

namespace {

constexpr std::size_t kFlushBytes = 1 << 16;      // bounds memory between explicit flushes
constexpr double kTwoPow53 = 9007199254740992.0;  // integers above lose exactness in a double

std::string header_line(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (c) line += ',';
    line += columns[c];
  }
  line += '\n';
  return line;
}

// Reads the first line of `file`; returns false if the file is missing or empty.
bool first_line(const std::filesystem::path& file, std::string& line) {
  std::ifstream in(file);
  if (!in) return false;
  return static_cast<bool>(std::getline(in, line));
}

// A killed run may have cut the last appended line; drop it so new rows start on a fresh line.
void drop_partial_last_line(const std::filesystem::path& file, const std::string& header) {
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.empty() || text.back() == '\n') return;
  const auto last = text.rfind('\n');
  if (last == std::string::npos) text = header;  // only a cut header line was there
  else text.resize(last + 1);
  write_file_atomically(file, [&text](std::ostream& os) { os << text; });
}

}  // namespace

void write_csv_snapshot(const std::filesystem::path& file, std::string_view header, std::size_t rows,
                        const std::function<void(std::string& line, std::size_t k)>& row) {
  constexpr std::size_t kFlushBytes = 1 << 16;  // bounds the buffered text of a large snapshot
  write_file_atomically(
      file,
      [&](std::ostream& os) {
        std::string line(header);
        line += '\n';
        for (std::size_t k = 0; k < rows; ++k) {
          row(line, k);
          if (line.size() >= kFlushBytes) {
            os << line;
            line.clear();
          }
        }
        os << line;
      },
      Durability::kill);
}

void append_csv_number(std::string& out, double v) {
  char buf[32];
  std::to_chars_result r;
  if (std::trunc(v) == v && std::fabs(v) < kTwoPow53)
    r = std::to_chars(buf, buf + sizeof buf, static_cast<std::int64_t>(v));
  else r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  out.append(buf, r.ptr);
}

CsvLog::CsvLog(std::filesystem::path file, std::vector<std::string> columns, Open mode)
    : file_(std::move(file)), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("CSV log '" + file_.string() + "' has no columns");
  for (const std::string& c : columns_)
    if (!is_column_name(c))
      throw std::invalid_argument("CSV log '" + file_.string() + "': bad column name '" + c + "'");
  const std::string header = header_line(columns_);
  std::string existing;
  if (mode == Open::append && first_line(file_, existing)) {
    if (existing + '\n' != header)
      throw std::runtime_error("cannot append to '" + file_.string() + "': its header '" + existing +
                               "' differs from '" + header.substr(0, header.size() - 1) + "'");
    drop_partial_last_line(file_, header);
    return;
  }
  write_file_atomically(file_, [&header](std::ostream& os) { os << header; });
}

CsvLog::~CsvLog() {
  try {
    flush();
  } catch (...) {
    // A destructor must not throw; the rows are lost only if the disk refuses them.
  }
}

void CsvLog::row(std::span<const double> values) {
  if (values.size() != columns_.size())
    throw std::logic_error("CSV log '" + file_.string() + "': row has " + std::to_string(values.size()) +
                           " values, header has " + std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (c) buffer_ += ',';
    append_csv_number(buffer_, values[c]);
  }
  buffer_ += '\n';
  if (buffer_.size() >= kFlushBytes) flush();
}

void CsvLog::text_row(std::span<const std::string> fields) {
  if (fields.size() != columns_.size())
    throw std::logic_error("CSV log '" + file_.string() + "': row has " + std::to_string(fields.size()) +
                           " fields, header has " + std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < fields.size(); ++c) {
    if (!is_column_name(fields[c])) throw std::logic_error("CSV log '" + file_.string() + "': bad field");
    if (c) buffer_ += ',';
    buffer_ += fields[c];
  }
  buffer_ += '\n';
  if (buffer_.size() >= kFlushBytes) flush();
}

void CsvLog::flush() {
  if (buffer_.empty()) return;
  append_complete_lines(file_, buffer_);
  buffer_.clear();
}

}  // namespace mpdem
