#include "interact/external_loads.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace mpdem {

void ExternalLoads::set(const std::vector<std::int64_t>& id, const std::vector<Vec3>& force,
                        const std::vector<Vec3>& torque) {
  std::unordered_map<std::int64_t, std::size_t> at;
  for (std::size_t k = 0; k < id_.size(); ++k) at.emplace(id_[k], k);
  for (std::size_t j = 0; j < id.size(); ++j) {
    if (const auto it = at.find(id[j]); it != at.end()) {
      force_[it->second] = force[j];
      torque_[it->second] = torque[j];
    } else {
      at.emplace(id[j], id_.size());
      id_.push_back(id[j]);
      force_.push_back(force[j]);
      torque_.push_back(torque[j]);
    }
  }
  // Ascending ids without the zero entries: the same sums whatever order the caller used.
  std::vector<std::size_t> order(id_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id_[a] < id_[b]; });
  std::vector<std::int64_t> ids;
  std::vector<Vec3> f, t;
  for (const std::size_t k : order) {
    if (norm2(force_[k]) == 0.0 && norm2(torque_[k]) == 0.0) continue;
    ids.push_back(id_[k]);
    f.push_back(force_[k]);
    t.push_back(torque_[k]);
  }
  id_ = std::move(ids);
  force_ = std::move(f);
  torque_ = std::move(t);
  index_.clear();
}

void ExternalLoads::clear() {
  id_.clear();
  force_.clear();
  torque_.clear();
  index_.clear();
}

void ExternalLoads::locate(const Particles& p) {
  bool valid = index_.size() == id_.size();
  for (std::size_t k = 0; valid && k < id_.size(); ++k) valid = index_[k] < p.size() && p.id[index_[k]] == id_[k];
  if (valid) return;  // the order did not change since the last evaluation
  std::unordered_map<std::int64_t, std::uint32_t> at;
  at.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) at.emplace(p.id[i], static_cast<std::uint32_t>(i));
  std::size_t kept = 0;
  index_.clear();
  for (std::size_t k = 0; k < id_.size(); ++k) {
    const auto it = at.find(id_[k]);
    if (it == at.end()) continue;  // removed since
    id_[kept] = id_[k];
    force_[kept] = force_[k];
    torque_[kept] = torque_[k];
    index_.push_back(it->second);
    ++kept;
  }
  id_.resize(kept);
  force_.resize(kept);
  torque_.resize(kept);
}

void ExternalLoads::add_to(Particles& p) {
  if (id_.empty()) return;
  locate(p);
  for (std::size_t k = 0; k < id_.size(); ++k) {
    p.force[index_[k]] += force_[k];
    p.torque[index_[k]] += torque_[k];
  }
}

double ExternalLoads::power(const Particles& p, double kick, bool rotation) const {
  double w = 0.0;  // W
  for (std::size_t k = 0; k < index_.size(); ++k) {
    const std::size_t i = index_[k];
    const double s = p.fixed[i] ? 0.0 : kick;  // s, a fixed particle keeps its velocity
    w += dot(force_[k], p.v[i] + p.force[i] * (s / p.mass[i]));
    if (rotation) w += dot(torque_[k], p.w[i] + p.torque[i] * (s / p.inertia[i]));
  }
  return w;
}

}  // namespace mpdem
