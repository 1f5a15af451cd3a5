#include "io/particle_csv_writer.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <type_traits>
#include <vector>

#include "io/csv_log.hpp"
#include "state/particle_columns.hpp"

namespace mpdem {

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

bool in_csv(CsvRole role, bool periodic) {
  return role == CsvRole::input || role == CsvRole::output || (periodic && role == CsvRole::periodic);
}

// Appends v and a comma. Integers (ids, indices, flags, image counts) are printed directly: a
// double would round ids beyond 2^53.
template <class S>
void append_value(std::string& line, S v) {
  if constexpr (std::is_integral_v<S>) {
    char buf[24];
    line.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  } else {
    append_csv_number(line, v);
  }
  line += ',';
}

}  // namespace

std::string particle_csv_header(bool periodic) {
  std::string line = kCsvTime;
  for_each_particle_column([&](const auto& c) {
    if (!in_csv(c.csv_role, periodic)) return;
    for (std::size_t k = 0; k < c.components; ++k) (line += ',') += c.csv[k];
    if (c.csv_role == CsvRole::periodic)
      for (const char* name : kCsvUnwrapped) (line += ',') += name;
  });
  return line;
}

void write_particles_csv(const std::filesystem::path& file, const Particles& p, double time, const Vec3& period) {
  const bool periodic = period.x > 0.0 || period.y > 0.0 || period.z > 0.0;
  const std::vector<std::size_t> order = ascending_ids(p);
  write_csv_snapshot(file, particle_csv_header(periodic), order.size(), [&](std::string& line, std::size_t r) {
    const std::size_t i = order[r];
    append_value(line, time);
    for_each_particle_column([&](const auto& c) {
      if (!in_csv(c.csv_role, periodic)) return;
      const auto& v = (p.*c.array)[i];
      for (std::size_t k = 0; k < c.components; ++k) append_value(line, component(v, k));
      if (c.csv_role == CsvRole::periodic) {  // the image counts: the unwrapped centre follows
        const auto& im = p.image[i];
        const Vec3 unwrapped = p.x[i] + Vec3{im[0] * period.x, im[1] * period.y, im[2] * period.z};  // m
        for (std::size_t k = 0; k < 3; ++k) append_value(line, component(unwrapped, k));
      }
    });
    line.back() = '\n';
  });
}

}  // namespace mpdem
