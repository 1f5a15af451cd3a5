#include "contact/barrier_contact_store.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace mpdem {

void BarrierContactStore::relayout(const BarrierBroadphase& broad) {
  const std::size_t n = broad.size();
  // Old positions of the records to carry, by ascending particle index (removed particles and
  // indices beyond the list - a scene that shrank without compact() - are dropped).
  std::vector<std::uint32_t> carry;
  for (std::size_t k = 0; k < active_.size(); ++k)
    if (active_[k] < n && (committed_used_[k] > 0 || first_used_[k] > 0))
      carry.push_back(static_cast<std::uint32_t>(k));
  if (!sorted_)
    std::sort(carry.begin(), carry.end(), [this](std::uint32_t a, std::uint32_t b) { return active_[a] < active_[b]; });

  // New active list: the particles with candidates merged with those carrying records.
  const std::vector<std::uint32_t>& cand = broad.active();
  std::vector<std::uint32_t> active, from, begin{0};
  active.reserve(cand.size() + carry.size());
  from.reserve(cand.size() + carry.size());
  begin.reserve(cand.size() + carry.size() + 1);
  std::size_t a = 0, c = 0;
  while (a < cand.size() || c < carry.size()) {
    const std::uint32_t ic = a < cand.size() ? cand[a] : kGone;
    const std::uint32_t ih = c < carry.size() ? active_[carry[c]] : kGone;
    const std::uint32_t i = std::min(ic, ih);
    std::size_t cap = 0;
    std::uint32_t old = kGone;
    if (ic == i) {
      cap = broad.candidates(i).size();
      ++a;
    }
    if (ih == i) {
      old = carry[c++];
      cap = std::max({cap, std::size_t{committed_used_[old]}, std::size_t{first_used_[old]}});
    }
    active.push_back(i);
    from.push_back(old);
    begin.push_back(begin.back() + static_cast<std::uint32_t>(std::min<std::size_t>(cap, kSlots)));
  }

  const std::size_t A = active.size(), S = begin.back();
  std::vector<BarrierSlot> committed(S);
  std::vector<BarrierFirst> first(S);
  std::vector<std::uint8_t> committed_used(A, 0), first_used(A, 0);
  for (std::size_t k = 0; k < A; ++k) {
    const std::uint32_t old = from[k];
    if (old == kGone) continue;
    std::copy_n(committed_.begin() + begin_[old], committed_used_[old], committed.begin() + begin[k]);
    std::copy_n(first_.begin() + begin_[old], first_used_[old], first.begin() + begin[k]);
    committed_used[k] = committed_used_[old];
    first_used[k] = first_used_[old];
  }
  active_ = std::move(active);
  begin_ = std::move(begin);
  committed_ = std::move(committed);
  first_ = std::move(first);
  committed_used_ = std::move(committed_used);
  first_used_ = std::move(first_used);
  tentative_.resize(S);
  loads_.resize(S);
  tentative_used_.assign(A, 0);
  load_used_.assign(A, 0);

  group_.clear();
  for (std::size_t k = 0; k < A; ++k)
    if (k == 0 || active_[k] / kGroup != active_[k - 1] / kGroup) group_.push_back(static_cast<std::uint32_t>(k));
  group_.push_back(static_cast<std::uint32_t>(A));

  // Element -> active particles with it as a candidate: a counting sort keeps them ascending.
  const std::size_t M = broad.num_elements();
  elem_offset_.assign(M + 1, 0);
  for (std::size_t k = 0; k < A; ++k)
    for (const std::uint32_t e : broad.candidates(active_[k])) ++elem_offset_[e + 1];
  for (std::size_t e = 0; e < M; ++e) elem_offset_[e + 1] += elem_offset_[e];
  elem_user_.resize(elem_offset_[M]);
  std::vector<std::uint32_t> next(elem_offset_.begin(), elem_offset_.end() - 1);
  for (std::size_t k = 0; k < A; ++k)
    for (const std::uint32_t e : broad.candidates(active_[k])) elem_user_[next[e]++] = static_cast<std::uint32_t>(k);

  dirty_ = false;
  sorted_ = true;
  generation_ = broad.generation();
}

void BarrierContactStore::permute(const std::vector<std::uint32_t>& order) {
  dirty_ = true;
  if (active_.empty()) return;
  std::vector<std::uint32_t> where(order.size(), kGone);  // old index -> new index
  for (std::size_t k = 0; k < order.size(); ++k)
    if (order[k] < where.size()) where[order[k]] = static_cast<std::uint32_t>(k);
  for (std::uint32_t& i : active_) i = i < where.size() ? where[i] : kGone;
  // Reordering happens between steps: no first-iteration decision is pending.
  std::fill(first_used_.begin(), first_used_.end(), 0);
  sorted_ = false;
}

void BarrierContactStore::compact(const std::vector<char>& keep) {
  dirty_ = true;
  if (active_.empty()) return;
  std::vector<std::uint32_t> renumber(keep.size(), kGone);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) renumber[i] = next++;
  for (std::size_t k = 0; k < active_.size(); ++k) {
    std::uint32_t& i = active_[k];
    i = i < renumber.size() ? renumber[i] : kGone;
    if (i == kGone) committed_used_[k] = load_used_[k] = 0;
  }
  std::fill(first_used_.begin(), first_used_.end(), 0);
}

void BarrierContactStore::commit() {
  committed_.swap(tentative_);
  committed_used_.swap(tentative_used_);
}

void BarrierContactStore::save(BinaryWriter& w) const {
  std::vector<std::uint32_t> order;  // positions with history, by ascending particle index
  for (std::size_t k = 0; k < active_.size(); ++k)
    if (active_[k] != kGone && committed_used_[k] > 0) order.push_back(static_cast<std::uint32_t>(k));
  if (!sorted_)
    std::sort(order.begin(), order.end(), [this](std::uint32_t a, std::uint32_t b) { return active_[a] < active_[b]; });
  std::vector<std::uint32_t> particles;
  std::vector<std::uint8_t> counts;
  std::vector<BarrierSlot> slots;
  for (const std::uint32_t k : order) {
    particles.push_back(active_[k]);
    counts.push_back(committed_used_[k]);
    slots.insert(slots.end(), committed_.begin() + begin_[k], committed_.begin() + begin_[k] + committed_used_[k]);
  }
  w.vector(particles);
  w.vector(counts);
  w.vector(slots);
}

void BarrierContactStore::restore(BinaryReader& r, std::size_t particles) {
  std::vector<std::uint32_t> active = r.vector<std::uint32_t>();
  std::vector<std::uint8_t> counts = r.vector<std::uint8_t>();
  std::vector<BarrierSlot> slots = r.vector<BarrierSlot>();
  const auto mismatch = [] {
    return std::runtime_error("checkpoint does not match the scene (barrier contact history)");
  };
  if (counts.size() != active.size()) throw mismatch();
  std::vector<std::uint32_t> begin{0};
  for (std::size_t k = 0; k < active.size(); ++k) {
    if (active[k] >= particles || (k > 0 && active[k] <= active[k - 1]) || counts[k] == 0 || counts[k] > kSlots)
      throw mismatch();
    begin.push_back(begin.back() + counts[k]);
  }
  if (begin.back() != slots.size()) throw mismatch();
  const std::size_t A = active.size();
  active_ = std::move(active);
  begin_ = std::move(begin);
  committed_ = std::move(slots);
  committed_used_ = std::move(counts);
  tentative_.resize(committed_.size());
  first_.resize(committed_.size());
  loads_.resize(committed_.size());
  tentative_used_.assign(A, 0);
  first_used_.assign(A, 0);
  load_used_.assign(A, 0);
  group_ = {0};
  elem_offset_ = {0};
  elem_user_.clear();
  sorted_ = true;
  dirty_ = true;
}

std::size_t BarrierContactStore::bytes() const {
  const auto cap = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return cap(active_) + cap(begin_) + cap(group_) + cap(elem_offset_) + cap(elem_user_) + cap(committed_) +
         cap(tentative_) + cap(first_) + cap(loads_) + cap(committed_used_) + cap(tentative_used_) + cap(first_used_) +
         cap(load_used_);
}

}  // namespace mpdem
