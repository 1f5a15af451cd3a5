#include "state/particles.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace mpdem {

namespace {
void refuse_ghosts(const Particles& p, const char* what) {
  if (p.n_ghost > 0) throw std::logic_error(std::string("particles: ") + what + " with ghost particles present");
}
}  // namespace

void Particles::drop_ghosts() {
  const std::size_t n = size();
  for_each_array([n](const char*, auto& a) { a.resize(n); });
  n_ghost = 0;
}

void Particles::resize(std::size_t n) {
  refuse_ghosts(*this, "resize");
  body.resize(n, kNoBody);  // new particles are free spheres
  bodies.stale = true;
  for_each_array([n](const char*, auto& a) { a.resize(n); });
}

void Particles::reserve(std::size_t n) {
  for_each_array([n](const char*, auto& a) { a.reserve(n); });
}

void Particles::update_mass(std::size_t i, double rho) {
  const double r = radius[i];
  mass[i] = sphere_mass(r, rho);
  inertia[i] = sphere_inertia(mass[i], r);
}

void Particles::add(std::int64_t pid, int mat, double r, double rho, const Vec3& pos, const Vec3& vel) {
  refuse_ghosts(*this, "add");
  const std::size_t i = size();
  resize(i + 1);
  id[i] = pid;
  material[i] = mat;
  radius[i] = r;
  x[i] = pos;
  v[i] = vel;
  q[i] = Quat{};
  update_mass(i, rho);
}

void Particles::sort_by_id() {
  std::vector<std::uint32_t> order(size());
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  std::sort(order.begin(), order.end(), [this](std::uint32_t a, std::uint32_t b) { return id[a] < id[b]; });
  permute(order);
}

void Particles::permute(const std::vector<std::uint32_t>& order) {
  refuse_ghosts(*this, "permute");
  if (order.empty()) return;
  // One scratch block for every array, sized for the widest element, instead of a copy of each
  // array: a rebuild's reordering then allocates (and first touches) one array's worth.
  std::size_t widest = 0;
  for_each_array([&widest](const char*, auto& a) { widest = std::max(widest, sizeof(a[0])); });
  const std::size_t n = order.size();
  const std::unique_ptr<std::byte[]> scratch(new std::byte[widest * n]);
  for_each_array([&](const char*, auto& a) {
    using Item = typename std::decay_t<decltype(a)>::value_type;
    static_assert(std::is_trivially_copyable_v<Item>);
    std::byte* out = scratch.get();
    for (std::size_t k = 0; k < n; ++k) std::memcpy(out + k * sizeof(Item), &a[order[k]], sizeof(Item));
    std::memcpy(a.data(), out, n * sizeof(Item));
  });
  bodies.stale = true;
}

bool Particles::any_fixed() const {
  // An OR over all of them rather than a search that stops early: it vectorises, and most scenes
  // have none.
  std::uint8_t any = 0;
  for (std::size_t i = 0; i < size(); ++i) any |= fixed[i];
  return any != 0;
}

void Particles::compact(const std::vector<char>& keep) {
  refuse_ghosts(*this, "compact");
  for_each_array([&keep](const char*, auto& a) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (keep[i]) a[k++] = a[i];
    a.resize(k);
  });
  bodies.stale = true;
}

}  // namespace mpdem
