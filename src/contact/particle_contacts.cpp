#include "contact/particle_contacts.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/release.hpp"
#include "core/parallel.hpp"
#include "physics/tangential.hpp"
#include "contact/id_pair_index.hpp"
#include "contact/pair_batch.hpp"

namespace mpdem {

bool ParticleContacts::holds_history(std::size_t k) const {
  return norm2(spring_[k]) > 0.0 || (!vt0_.empty() && norm2(vt0_[k]) > 0.0) ||
         (!wr0_.empty() && norm2(wr0_[k]) > 0.0) || (!state_.empty() && state_[k] != 0);
}

bool ParticleContacts::cohesive() const {
  return any_hysteresis(table_.particle_laws()) || table_.any_particle_bridges();
}

void ParticleContacts::ensure_history(std::size_t pairs) {
  const bool rolling = step_start_ && table_.any_rolling();
  const bool cohesion = cohesive();
  // Rolling resistance switched on between steps needs the step-start rotations from then on,
  // and cohesion its state.
  if (rolling && spring_.size() == pairs && wr0_.size() != pairs) wr0_.assign(pairs, Vec3{});
  if (cohesion && spring_.size() == pairs && state_.size() != pairs) state_.assign(pairs, 0);
  if (!cohesion && !state_.empty() && spring_.size() == pairs) state_.clear();
  if (spring_.size() == pairs) return;  // first use: no history yet
  spring_.assign(pairs, Vec3{});
  vt0_.assign(step_start_ ? pairs : 0, Vec3{});
  wr0_.assign(rolling ? pairs : 0, Vec3{});
  slipped_.assign(step_start_ ? pairs : 0, 0);
  state_.assign(cohesion ? pairs : 0, 0);
}

void ParticleContacts::refresh_terms(const Particles& p, std::uint64_t generation) {
  const std::size_t n = p.size_with_ghosts();  // ghosts are second members
  terms_.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) terms_[i] = {p.radius[i], 1.0 / p.mass[i]};  // (52), (53)
  terms_generation_ = generation;
  // Which materials the particles have changes only with the particles themselves (a rebuild);
  // the laws' values are looked up afresh at every evaluation.
  const int materials = static_cast<int>(table_.materials());
  for (std::size_t i = 0; i < n; ++i)
    if (p.material[i] < 0 || p.material[i] >= materials)
      throw std::logic_error("particle contacts: a particle without a material (resolve_material_variants)");
  const auto other = [&](int m) { return m != p.material[0]; };
  single_material_ = n > 0 && std::none_of(p.material.begin(), p.material.end(), other) ? p.material[0] : -1;
}

void ParticleContacts::record_contacts(bool on) {
  recording_ = on;
  records_.clear();
}

PairStats ParticleContacts::evaluate(Particles& p, const NeighborSearch& search, const EvalRequest& req) {
  begin(p, search, req);
#pragma omp parallel if (pass_.n > kParallelThreshold)
  run_blocks(p, search);
  return finish();
}

void ParticleContacts::begin(Particles& p, const NeighborSearch& search, const EvalRequest& req) {
  if (!step_start_ && req.phi != 1.0)
    throw std::logic_error("particle contacts: phi < 1 needs the step-start history (trapezoidal integrator)");
  const VerletList& list = search.pairs();
  const PairBlocks& blocks = search.blocks();
  const std::size_t n = p.size_with_ghosts();  // the blocks span the ghosts, which get the second members' shares
  ensure_history(list.num_pairs());
  slipped_.resize(step_start_ ? list.num_pairs() : 0);
  cross_force_.resize(blocks.num_cross());
  cross_torque_.resize(blocks.num_cross());
  if (recording_) records_.assign(list.num_pairs(), PairRecord{});  // slots apart stay at overlap 0

  // Per-particle terms: refreshed only when the particles may have been reordered or changed.
  if (terms_.size() != n || terms_generation_ != search.generation()) refresh_terms(p, search.generation());
  const bool uniform = single_material_ >= 0;
  const auto m0 = static_cast<std::size_t>(uniform ? single_material_ : 0);

  pass_ = PairPass{p.x.data(),
                   p.v.data(),
                   p.w.data(),
                   p.id.data(),
                   terms_.data(),
                   p.inertia.data(),
                   p.material.data(),
                   table_.particle_pairs(),
                   list.offsets().data(),
                   list.indices().data(),
                   blocks.first_members().data(),
                   p.force.data(),
                   p.torque.data(),
                   spring_.data(),
                   vt0_.empty() ? nullptr : vt0_.data(),
                   wr0_.empty() ? nullptr : wr0_.data(),
                   slipped_.empty() ? nullptr : slipped_.data(),
                   cross_force_.data(),
                   cross_torque_.data(),
                   table_.materials(),
                   uniform,
                   n > 0 ? table_.particle_pair(m0, m0) : PairLaw{},
                   table_.particle_laws(),
                   table_.any_rolling(),
                   req.dt,
                   req.phi,
                   req.iteration,
                   req.commit,
                   n,
                   list.num_pairs(),
                   vector_select_,
                   recording_ ? records_.data() : nullptr,
                   state_.empty() ? nullptr : state_.data(),
                   table_.any_particle_bridges() ? table_.particle_bridges() : nullptr,
                   state_.empty() ? 0.0 : gap_};
  // Only a commit books energies (Interactions::book_evaluation): an iteration's are never read.
  // The cohesive kernel computes them always (pair_batch.cpp), so its pass says so.
  pass_.energies = (energies_ && req.commit) || pass_.state != nullptr;

  // 1. Blocks of particles, each by one thread in index order (pair_blocks.hpp, pair_batch.hpp).
  const std::size_t nb = blocks.num_blocks();
  // Each thread takes a run of consecutive blocks of about equal cost, as measured at the last
  // evaluation: blocks differ (the base of a bed has more contacts per slot than its top), and so
  // may the threads' cores on a shared machine. Which thread evaluates a block does not change
  // its sums. Until a block count has been timed, a block's cost is taken as its number of slots
  // (scaled to about a nanosecond each; only the ratios matter).
  const auto& off = list.offsets();
  if (block_seconds_.size() != nb) {
    block_seconds_.resize(nb);
    for (std::size_t b = 0; b < nb; ++b)
      block_seconds_[b] = 1e-9 * static_cast<double>(off[blocks.block_end(blocks.block_begin(b))] -
                                                     off[blocks.block_begin(b)]);
  }
  block_cost_.resize(nb + 1);
  block_cost_[0] = 0.0;
  for (std::size_t b = 0; b < nb; ++b) block_cost_[b + 1] = block_cost_[b] + block_seconds_[b];
  block_sums_.resize(nb);
}

void ParticleContacts::run_blocks(Particles& p, const NeighborSearch& search) {
  const PairBlocks& blocks = search.blocks();
  const std::size_t nb = blocks.num_blocks();
  const auto cost_before = [&](std::size_t b) { return block_cost_[b]; };
  const int threads = omp_get_num_threads(), r = omp_get_thread_num();
  const std::size_t b1 = balanced_split(r + 1, threads, nb, cost_before);
  double t0 = omp_get_wtime();
  for (std::size_t b = balanced_split(r, threads, nb, cost_before); b < b1; ++b) {
    block_sums_[b] = contact_block(pass_, blocks.block_begin(b), blocks.block_end(blocks.block_begin(b)),
                                   blocks.cross_base(b), blocks.cross_base(b + 1));
    const double t1 = omp_get_wtime();
    block_seconds_[b] = t1 - t0;
    t0 = t1;
  }
  // 2. Once every block is done: the second members' shares of the cross pairs, each in
  // ascending cross index (in the same region as the blocks: one fork and join less).
  const auto& members = blocks.cross_particles();
#pragma omp barrier
#pragma omp for schedule(static)
  for (std::size_t mb = 0; mb < members.size(); ++mb) {
    Vec3 f{}, t{};
    for (std::uint32_t c : blocks.entries(mb)) {
      f += cross_force_[c];
      t += cross_torque_[c];
    }
    p.force[members[mb]] += f;
    p.torque[members[mb]] += t;
  }
}

PairStats ParticleContacts::finish() {
  // 3. Totals in block order (independent of the thread count).
  PairStats st;
  st.energies = pass_.energies;
  deepest_ = OverlapReport{};
  for (const PairBlockSums& s : block_sums_) {
    st.contacts += static_cast<std::size_t>(s.contacts);
    st.elastic_energy += s.elastic_energy;
    st.damping_power += s.damping_power;
    st.rolling_power += s.rolling_power;
    st.sticking_loss += s.sticking_loss;
    st.sliding_loss += s.sliding_loss;
    st.spring_before += s.spring_before;
    st.spring_after += s.spring_after;
    st.bridges += static_cast<std::size_t>(s.bridges);
    st.breaks += static_cast<std::size_t>(s.breaks);
    st.ruptures += static_cast<std::size_t>(s.ruptures);
    st.cohesion_loss += s.cohesion_loss;
    st.elastic_magnitude += s.elastic_magnitude;
    if (s.deepest.ratio > deepest_.ratio) deepest_ = {s.deepest.ratio, s.deepest.first, s.deepest.second, -1};
  }
  return st;
}

std::size_t ParticleContacts::memory_bytes() const {
  return (spring_.capacity() + vt0_.capacity() + wr0_.capacity() + cross_force_.capacity() + cross_torque_.capacity()) *
             sizeof(Vec3) +
         slipped_.capacity() + state_.capacity() + terms_.capacity() * sizeof(Terms) +
         block_sums_.capacity() * sizeof(PairBlockSums) +
         (block_seconds_.capacity() + block_cost_.capacity()) * sizeof(double);
}

ParticleContacts::CarriedHistory ParticleContacts::carry_history(const NeighborSearch& search) {
  CarriedHistory h;
  // The per-particle terms and the cross-pair shares are recomputed at the next evaluation: free
  // them before the history is copied out, which is the rebuild's largest transient.
  release(cross_force_);
  release(cross_torque_);
  release(terms_);
  const VerletList& list = search.pairs();
  if (spring_.size() != list.num_pairs()) return h;
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const std::size_t n = list.owned();
  const PeriodicImages& images = search.images();
  const bool vt = !vt0_.empty(), wr = !wr0_.empty(), st = !state_.empty();
  // Keyed by the owned members' old indices, the smaller first (a ghost stands for its source,
  // and a pair with one may have its source first: the history is then flipped).
  const auto members = [&](std::size_t i, std::size_t k) {
    const std::uint32_t j = idx[k] < n ? idx[k] : images.source(idx[k] - n);
    return std::pair<std::uint32_t, std::uint32_t>{static_cast<std::uint32_t>(i), j};
  };
  h.offset.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k)
      if (holds_history(k)) {
        const auto [a, b] = members(i, k);
        ++h.offset[std::min(a, b) + 1];
      }
  for (std::size_t i = 0; i < n; ++i) h.offset[i + 1] += h.offset[i];
  const std::size_t total = h.offset[n];
  h.second.resize(total);
  h.spring.resize(total);
  if (vt) h.vt0.resize(total);
  if (wr) h.wr0.resize(total);
  if (st) h.state.resize(total);
  std::vector<std::uint32_t> fill(h.offset.begin(), h.offset.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      if (!holds_history(k)) continue;
      const auto [a, b] = members(i, k);
      const bool flip = b < a;
      const std::uint32_t c = fill[flip ? b : a]++;
      h.second[c] = flip ? a : b;
      h.spring[c] = flip ? -spring_[k] : spring_[k];
      if (vt) h.vt0[c] = flip ? -vt0_[k] : vt0_[k];
      if (wr) h.wr0[c] = flip ? -wr0_[k] : wr0_[k];
      if (st) h.state[c] = state_[k];
    }
  // The slot arrays are rebuilt for the new list; free them now (peak memory).
  release(spring_);
  release(vt0_);
  release(wr0_);
  release(slipped_);
  release(state_);
  return h;
}

void ParticleContacts::restore_history(const NeighborSearch& search, CarriedHistory h,
                                       const std::vector<std::uint32_t>& old_index) {
  const VerletList& list = search.pairs();
  spring_.clear();
  ensure_history(list.num_pairs());
  if (h.second.empty()) return;
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const std::size_t n = list.owned();
  const PeriodicImages& images = search.images();
  const bool vt = !vt0_.empty() && !h.vt0.empty(), wr = !wr0_.empty() && !h.wr0.empty();
  const bool st = !state_.empty() && !h.state.empty();
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      // The old pair was stored under its smaller old index; the spring acts on that member.
      const std::uint32_t j = idx[k] < n ? idx[k] : images.source(idx[k] - n);
      const std::uint32_t a = old_index[i], b = old_index[j];
      const bool flip = a > b;
      const std::uint32_t first = flip ? b : a, second = flip ? a : b;
      if (static_cast<std::size_t>(second) + 1 >= h.offset.size()) continue;  // not in the old list
      for (std::uint32_t c = h.offset[first]; c < h.offset[first + 1]; ++c) {
        if (h.second[c] != second) continue;
        spring_[k] = flip ? -h.spring[c] : h.spring[c];
        if (vt) vt0_[k] = flip ? -h.vt0[c] : h.vt0[c];
        if (wr) wr0_[k] = flip ? -h.wr0[c] : h.wr0[c];
        if (st) state_[k] = h.state[c];
        break;
      }
    }
}

void ParticleContacts::compact_slots(const std::vector<std::uint32_t>& from, std::size_t old_pairs) {
  if (spring_.size() != old_pairs) {  // no history for the old list: none for the new one either
    spring_.clear();
    return;
  }
  // A kept slot never moves up (from ascending, from[k] >= k): in place, front to back.
  const auto move = [&](auto& v) {
    if (v.size() != old_pairs) return;
    for (std::size_t k = 0; k < from.size(); ++k) v[k] = v[from[k]];
    v.resize(from.size());
  };
  move(spring_);
  move(vt0_);
  move(wr0_);
  move(slipped_);
  move(state_);
  move(records_);
}

void ParticleContacts::save(BinaryWriter& w, const Particles& p, const NeighborSearch& search) const {
  w.vector(export_history(p, search));
}

void ParticleContacts::restore(BinaryReader& r, const Particles& p, const NeighborSearch& search) {
  import_history(p, search, r.vector<PairHistory>());
}

std::vector<PairHistory> ParticleContacts::export_history(const Particles& p, const NeighborSearch& search) const {
  std::vector<PairHistory> h;
  const VerletList& list = search.pairs();
  if (spring_.size() != list.num_pairs() || list.size() != p.size_with_ghosts()) return h;
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const bool vt = !vt0_.empty(), wr = !wr0_.empty(), st = !state_.empty();
  for (std::size_t i = 0; i < list.owned(); ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k)
      if (holds_history(k))
        h.push_back({p.id[i], p.id[idx[k]], spring_[k], vt ? vt0_[k] : Vec3{}, wr ? wr0_[k] : Vec3{},
                     st ? std::uint64_t{state_[k]} : 0u});
  return h;
}

void ParticleContacts::import_history(const Particles& p, const NeighborSearch& search, std::vector<PairHistory> h) {
  const VerletList& list = search.pairs();
  spring_.clear();
  ensure_history(list.num_pairs());
  if (h.empty()) return;
  const bool vt = !vt0_.empty(), wr = !wr0_.empty(), st = !state_.empty();
  // Orient every record as (smaller id, larger id); look slots up by hash.
  for (PairHistory& r : h)
    if (r.id_first > r.id_second) {
      std::swap(r.id_first, r.id_second);
      r.spring = -r.spring;
      r.vt0 = -r.vt0;
      r.wr0 = -r.wr0;
    }
  const auto key = [&h](std::size_t r) { return std::pair{h[r].id_first, h[r].id_second}; };
  IdPairIndex index;
  index.build(h.size(), key);
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const std::size_t n = list.owned();
  // Each slot is written from the records alone: any thread count gives the same slots.
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      const std::int64_t a = p.id[i], b = p.id[idx[k]];  // a ghost carries its source's id
      const bool flip = a > b;
      const std::size_t r = index.find(flip ? b : a, flip ? a : b, key);
      if (r == IdPairIndex::npos) continue;
      spring_[k] = flip ? -h[r].spring : h[r].spring;
      if (vt) vt0_[k] = flip ? -h[r].vt0 : h[r].vt0;
      if (wr) wr0_[k] = flip ? -h[r].wr0 : h[r].wr0;
      if (st) state_[k] = static_cast<std::uint8_t>(h[r].state);
    }
}

Vec3 ParticleContacts::spring_between(const NeighborSearch& search, std::size_t i, std::size_t j) const {
  const bool flip = j < i;
  const std::size_t a = flip ? j : i, b = flip ? i : j;
  const auto& off = search.pairs().offsets();
  const auto& idx = search.pairs().indices();
  for (std::size_t k = off[a]; k < off[a + 1]; ++k)
    if (idx[k] == b && k < spring_.size()) return flip ? -spring_[k] : spring_[k];
  return {};
}

}  // namespace mpdem
