#include "output/bond_cells.hpp"

#include <fmt/core.h>

#include <stdexcept>
#include <unordered_map>

#include "parallel/periodic_images.hpp"
#include "physics/parallel_bond.hpp"

namespace mpdem {

BondCells bond_cells(std::span<const BondRecord> bonds, const Particles& p, const Vec3& period) {
  std::unordered_map<std::int64_t, std::size_t> at;  // id -> index among the owned particles
  at.reserve(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) at.emplace(p.id[k], k);
  const auto centre = [&](std::int64_t id) {
    const auto it = at.find(id);
    if (it == at.end()) throw std::runtime_error(fmt::format("bond output: no particle of id {}", id));
    return p.x[it->second];
  };
  BondCells c;
  const std::size_t n = bonds.size();
  for (auto* v : {&c.from, &c.to, &c.shear_force, &c.bending_moment}) v->reserve(n);
  for (auto* v : {&c.normal_force, &c.twisting_moment, &c.sigma_max, &c.tau_max, &c.length}) v->reserve(n);
  for (const BondRecord& r : bonds) {
    const Vec3 xi = centre(r.id_i);
    const Vec3 d = nearest_image(centre(r.id_j) - xi, period);  // m
    const BondSection sec = bond_section(r.radius);
    c.from.push_back(xi);
    c.to.push_back(xi + d);
    c.id_i.push_back(r.id_i);
    c.id_j.push_back(r.id_j);
    c.intact.push_back(r.intact != 0 ? 1 : 0);
    c.normal_force.push_back(r.fn);
    c.shear_force.push_back(r.fs);
    c.twisting_moment.push_back(r.mn);
    c.bending_moment.push_back(r.ms);
    c.sigma_max.push_back(bond_tensile_stress(sec, r.fn, r.ms));
    c.tau_max.push_back(bond_shear_stress(sec, r.fs, r.mn));
    c.length.push_back(r.length);
  }
  return c;
}

}  // namespace mpdem
