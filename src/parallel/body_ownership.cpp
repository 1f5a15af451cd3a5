#include "parallel/body_ownership.hpp"

#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>

namespace mpdem {

std::vector<Vec3> owner_points(const Particles& p) {
  std::vector<Vec3> x(p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(p.size()));
  if (!p.has_bodies()) return x;
  const Bodies& B = p.bodies;
  std::unordered_map<std::int64_t, std::size_t> row;  // body id -> its row in B
  row.reserve(B.size());
  for (std::size_t b = 0; b < B.size(); ++b) row.emplace(B.id[b], b);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (p.body[i] == kNoBody) continue;
    const auto it = row.find(p.body[i]);
    if (it == row.end())
      throw std::logic_error("particle " + std::to_string(p.id[i]) + " is a member of body " +
                             std::to_string(p.body[i]) + ", which this rank does not hold");
    x[i] = B.x[it->second];
  }
  return x;
}

std::vector<char> owned_particles(const BrickGrid& grid, const Particles& p, int rank) {
  return grid.owned(owner_points(p), rank);
}

std::vector<char> keep_owned(const BrickGrid& grid, Particles& p, int rank) {
  std::vector<char> keep = owned_particles(grid, p, rank);
  if (p.has_bodies()) p.bodies.compact(grid.owned(p.bodies.x, rank));
  p.compact(keep);
  return keep;
}

void pack_bodies(Bodies& B, std::span<const std::uint32_t> idx, std::vector<std::byte>& out) {
  const std::uint64_t n = idx.size();
  const std::size_t at = out.size();
  out.resize(at + sizeof n);
  std::memcpy(out.data() + at, &n, sizeof n);
  B.for_each_array([&](const char*, auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t base = out.size();
    out.resize(base + idx.size() * sizeof(T));
    for (std::size_t k = 0; k < idx.size(); ++k) std::memcpy(out.data() + base + k * sizeof(T), &a[idx[k]], sizeof(T));
  });
}

std::size_t unpack_bodies(Bodies& B, std::span<const std::byte> bytes, std::size_t& pos) {
  std::uint64_t n = 0;
  if (bytes.size() - pos < sizeof n) throw std::runtime_error("truncated body message");
  std::memcpy(&n, bytes.data() + pos, sizeof n);
  pos += sizeof n;
  const std::size_t base = B.size();
  B.resize(base + static_cast<std::size_t>(n));  // marks the member index stale
  B.for_each_array([&](const char*, auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    if ((bytes.size() - pos) / sizeof(T) < n) throw std::runtime_error("truncated body message");
    for (std::size_t k = 0; k < n; ++k) std::memcpy(&a[base + k], bytes.data() + pos + k * sizeof(T), sizeof(T));
    pos += static_cast<std::size_t>(n) * sizeof(T);
  });
  return static_cast<std::size_t>(n);
}

}  // namespace mpdem
