#include "io/csv_log.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <numeric>
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

void CsvLog::flush() {
  if (buffer_.empty()) return;
  append_complete_lines(file_, buffer_);
  buffer_.clear();
}

namespace {
// Storage indices in ascending id order: a snapshot's rows are in the same order whatever the
// engine's storage order (it reorders at rebuilds) and however many ranks gathered them.
std::vector<std::size_t> ascending_ids(const Particles& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto by_id = [&p](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; };
  if (!std::is_sorted(order.begin(), order.end(), by_id)) std::sort(order.begin(), order.end(), by_id);
  return order;
}
}  // namespace

void write_particles_csv(const std::filesystem::path& file, const Particles& p, double time, const Vec3& period) {
  const bool periodic = period.x > 0.0 || period.y > 0.0 || period.z > 0.0;
  write_file_atomically(
      file,
      [&](std::ostream& os) {
        std::string line = "time,id,x,y,z,vx,vy,vz,wx,wy,wz,radius,material,temperature,charge,fx,fy,fz,fixed";
        line += periodic ? ",ix,iy,iz,xu,yu,zu\n" : "\n";
        auto num = [&line](double v) {
          append_csv_number(line, v);
          line += ',';
        };
        auto vec = [&num](const Vec3& v) {
          num(v.x);
          num(v.y);
          num(v.z);
        };
        for (const std::size_t i : ascending_ids(p)) {
          num(time);
          // Ids are printed as integers directly: a double would round ids beyond 2^53.
          char buf[24];
          line.append(buf, std::to_chars(buf, buf + sizeof buf, p.id[i]).ptr);
          line += ',';
          vec(p.x[i]);
          vec(p.v[i]);
          vec(p.w[i]);
          num(p.radius[i]);
          line.append(buf, std::to_chars(buf, buf + sizeof buf, p.material[i]).ptr);
          line += ',';
          num(p.T[i]);
          num(p.charge[i]);
          vec(p.force[i]);
          line += p.fixed[i] ? '1' : '0';  // 1: prescribed motion (a rough base, a driven plate)
          line += ',';
          if (periodic) {
            const auto& im = p.image[i];
            for (int c = 0; c < 3; ++c) {
              line.append(buf, std::to_chars(buf, buf + sizeof buf, im[static_cast<std::size_t>(c)]).ptr);
              line += ',';
            }
            vec(p.x[i] + Vec3{im[0] * period.x, im[1] * period.y, im[2] * period.z});  // m, unwrapped
          }
          line.back() = '\n';
          if (line.size() >= kFlushBytes) {
            os << line;
            line.clear();
          }
        }
        os << line;
      },
      Durability::kill);
}

}  // namespace mpdem
