#include "state/particles.hpp"

#include <numbers>

namespace mpdem {

namespace {
// Applies f to every per-particle array, so resize/permute/compact cannot forget one.
template <class P, class F>
void for_each_array(P& p, F&& f) {
  f(p.id); f(p.material); f(p.radius); f(p.density); f(p.mass); f(p.inertia);
  f(p.young); f(p.poisson); f(p.charge); f(p.heat_capacity); f(p.conductivity);
  f(p.emissivity); f(p.x); f(p.v); f(p.w); f(p.q); f(p.T); f(p.force); f(p.torque); f(p.heat);
}
}  // namespace

void Particles::resize(std::size_t n) {
  for_each_array(*this, [n](auto& a) { a.resize(n); });
}

void Particles::reserve(std::size_t n) {
  for_each_array(*this, [n](auto& a) { a.reserve(n); });
}

void Particles::update_mass(std::size_t i) {
  const double r = radius[i];
  mass[i] = 4.0 / 3.0 * std::numbers::pi * r * r * r * density[i];
  inertia[i] = 0.4 * mass[i] * r * r;
}

void Particles::add(std::int64_t pid, int mat, double r, double rho, const Vec3& pos, const Vec3& vel) {
  const std::size_t i = size();
  resize(i + 1);
  id[i] = pid;
  material[i] = mat;
  radius[i] = r;
  density[i] = rho;
  x[i] = pos;
  v[i] = vel;
  q[i] = Quat{};
  update_mass(i);
}

void Particles::permute(const std::vector<std::uint32_t>& order) {
  for_each_array(*this, [&order](auto& a) {
    auto old = a;
    for (std::size_t k = 0; k < order.size(); ++k) a[k] = old[order[k]];
  });
}

void Particles::compact(const std::vector<char>& keep) {
  for_each_array(*this, [&keep](auto& a) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (keep[i]) a[k++] = a[i];
    a.resize(k);
  });
}

}  // namespace mpdem
