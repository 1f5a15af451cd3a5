#include "state/bodies.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "state/particles.hpp"

namespace mpdem {

void Bodies::resize(std::size_t n) {
  for_each_array([n](const char*, auto& a) { a.resize(n); });
  sorted_ids_.clear();  // find() must not use the old rows
  stale = true;
}

void Bodies::compact(const std::vector<char>& keep) {
  for_each_array([&keep](const char*, auto& a) {
    std::size_t k = 0;
    for (std::size_t b = 0; b < a.size(); ++b)
      if (keep[b]) a[k++] = a[b];
    a.resize(k);
  });
  sorted_ids_.clear();  // find() must not use the old rows
  stale = true;
}

void Bodies::sort_by_id() {
  std::vector<std::uint32_t> order(size());
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  std::sort(order.begin(), order.end(), [this](std::uint32_t a, std::uint32_t b) { return id[a] < id[b]; });
  for_each_array([&order](const char*, auto& a) {
    auto old = a;
    for (std::size_t k = 0; k < order.size(); ++k) a[k] = old[order[k]];
  });
  sorted_ids_.clear();
  stale = true;
}

std::ptrdiff_t Bodies::find(std::int64_t body_id) const {
  if (sorted_ids_.size() != size()) {  // not indexed yet
    const auto it = std::find(id.begin(), id.end(), body_id);
    return it == id.end() ? -1 : it - id.begin();
  }
  const auto it = std::lower_bound(sorted_ids_.begin(), sorted_ids_.end(), body_id);
  if (it == sorted_ids_.end() || *it != body_id) return -1;
  return by_id_[static_cast<std::size_t>(it - sorted_ids_.begin())];
}

void Bodies::index_members(const Particles& p) {
  const std::size_t n = p.size(), nb = size();
  if (!stale && held.size() == n && sorted_ids_.size() == nb) return;
  // Bodies are looked up by id through a sorted copy (a member carries its body's id, which
  // survives reordering, removal and the ranks; the body's index does not).
  by_id_.resize(nb);
  std::iota(by_id_.begin(), by_id_.end(), std::uint32_t{0});
  std::sort(by_id_.begin(), by_id_.end(), [this](std::uint32_t a, std::uint32_t b) { return id[a] < id[b]; });
  sorted_ids_.resize(nb);
  for (std::size_t k = 0; k < nb; ++k) sorted_ids_[k] = id[by_id_[k]];
  // Members per body, counted, then placed at first[b] + their template index.
  first.assign(nb + 1, 0);
  held.assign(n, 0);
  owner.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    held[i] = p.fixed[i];
    if (p.body[i] == kNoBody) continue;
    const std::ptrdiff_t b = find(p.body[i]);
    if (b < 0)
      throw std::logic_error("particle " + std::to_string(p.id[i]) + " names body " + std::to_string(p.body[i]) +
                             ", which does not exist");
    owner[i] = static_cast<std::uint32_t>(b);
    held[i] = 1;
    ++first[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t b = 0; b < nb; ++b) first[b + 1] += first[b];
  constexpr std::uint32_t kUnset = ~std::uint32_t{0};
  index.assign(first[nb], kUnset);
  for (std::size_t i = 0; i < n; ++i) {
    if (p.body[i] == kNoBody) continue;
    const std::size_t b = owner[i];
    const std::size_t slot = first[b] + p.member[i];
    if (p.member[i] >= first[b + 1] - first[b] || index[slot] != kUnset)
      throw std::logic_error("body " + std::to_string(id[b]) + ": member " + std::to_string(p.member[i]) +
                             " is out of range or given twice");
    index[slot] = static_cast<std::uint32_t>(i);
  }
  stale = false;
}

}  // namespace mpdem
