#include "integrate/rate_history.hpp"

#include <algorithm>
#include <utility>

namespace mpdem {

void RateHistory::remember(std::span<const std::int64_t> id, std::vector<Vec3>& a0, std::vector<Vec3>& b0, double dt) {
  id_.assign(id.begin(), id.end());
  std::swap(a_, a0);
  std::swap(b_, b0);
  a_.resize(id.size());
  b_.resize(id.size());
  carried_.clear();
  dt_ = dt;
}

bool RateHistory::align(std::span<const std::int64_t> id, std::span<const Vec3> a0, std::span<const Vec3> b0) {
  a_prev_ = b_prev_ = nullptr;
  if (!(dt_ > 0.0)) return false;
  const std::size_t n = id.size();
  // The common case: no particle changed index since the remembered step.
  if (carried_.empty() && id_.size() == n && std::equal(id.begin(), id.end(), id_.begin())) {
    a_prev_ = a_.data();
    b_prev_ = b_.data();
    return true;
  }
  // Otherwise by id: the remembered step's particles, then the records set from outside.
  std::vector<std::pair<std::int64_t, std::uint32_t>> by_id(id_.size());
  for (std::size_t k = 0; k < id_.size(); ++k) by_id[k] = {id_[k], static_cast<std::uint32_t>(k)};
  std::sort(by_id.begin(), by_id.end());
  aligned_a_.resize(n);
  aligned_b_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    aligned_a_[i] = a0[i];
    aligned_b_[i] = b0[i];
    const auto k = std::lower_bound(by_id.begin(), by_id.end(), std::pair{id[i], std::uint32_t{0}});
    if (k != by_id.end() && k->first == id[i]) {
      aligned_a_[i] = a_[k->second];
      aligned_b_[i] = b_[k->second];
      continue;
    }
    const auto r = std::lower_bound(carried_.begin(), carried_.end(), id[i],
                                    [](const RateRecord& c, std::int64_t v) { return c.id < v; });
    if (r != carried_.end() && r->id == id[i]) {
      aligned_a_[i] = r->a;
      aligned_b_[i] = r->b;
    }
  }
  a_prev_ = aligned_a_.data();
  b_prev_ = aligned_b_.data();
  return true;
}

std::vector<RateRecord> RateHistory::records() const {
  std::vector<RateRecord> r(carried_);
  r.reserve(carried_.size() + id_.size());
  for (std::size_t k = 0; k < id_.size(); ++k) r.push_back({id_[k], a_[k], b_[k]});
  std::sort(r.begin(), r.end(), [](const RateRecord& x, const RateRecord& y) { return x.id < y.id; });
  return r;
}

void RateHistory::set_records(std::vector<RateRecord> records, double dt) {
  std::sort(records.begin(), records.end(), [](const RateRecord& x, const RateRecord& y) { return x.id < y.id; });
  carried_ = std::move(records);
  id_.clear();
  a_.clear();
  b_.clear();
  dt_ = dt;
}

}  // namespace mpdem
