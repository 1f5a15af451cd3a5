#include "contact/barrier_contacts.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/parallel.hpp"
#include "physics/rolling.hpp"
#include "physics/tangential.hpp"
#include "contact/barrier_batch.hpp"
#include "contact/cohesive_contact.hpp"

namespace mpdem {

namespace {
// Active particles ahead whose data is prefetched: they are scattered over the particle arrays
// (only those near a wall), so each visit would otherwise wait for ~15 cache misses in turn.
constexpr std::size_t kAhead = 8;

// Brings the bytes [a, a + bytes) into the cache: every line they touch. Always inlined: GCC
// takes a function doing nothing but prefetches for pure and deletes its calls.
template <std::size_t bytes, int write>
[[gnu::always_inline]] inline void prefetch_bytes(const void* a) {
  const char* c = static_cast<const char*>(a);
  for (std::size_t o = 0; o < bytes; o += 64) __builtin_prefetch(c + o, write);
  if constexpr (bytes > 8) __builtin_prefetch(c + bytes - 1, write);  // the last line, if one more
}
template <int write = 0, class T>
[[gnu::always_inline]] inline void prefetch_item(const std::vector<T>& a, std::size_t i) {
  prefetch_bytes<sizeof(T), write>(a.data() + i);  // 8-byte items never straddle two lines
}

// Everything collect and flush read or write of particle i (its candidate list: only the
// offsets, the list itself is fetched once they have arrived, see evaluate()).
[[gnu::always_inline]] inline void prefetch_particle(const Particles& p, const BarrierBroadphase& broad,
                                                     std::size_t i) {
  prefetch_item(p.x, i);
  prefetch_item(p.v, i);
  prefetch_item(p.w, i);
  prefetch_item(p.radius, i);
  prefetch_item(p.mass, i);
  prefetch_item(p.material, i);
  prefetch_item<1>(p.force, i);
  prefetch_item<1>(p.torque, i);
  prefetch_item(broad.offsets(), i);
  prefetch_item(broad.offsets(), i + 1);
}

// The first contact record of active particle k in each record array: they are read or written
// in order, but with a stride of several lines that the hardware prefetcher does not follow.
[[gnu::always_inline]] inline void prefetch_records(BarrierContactStore& store, std::size_t k) {
  prefetch_bytes<sizeof(BarrierSlot), 0>(store.committed(k));
  prefetch_bytes<sizeof(BarrierSlot), 1>(store.tentative(k));
  prefetch_bytes<sizeof(BarrierLoad), 1>(store.loads(k));
}

}  // namespace

BarrierContacts::BarrierContacts(const ContactTable& table, const Barriers& b)
    : table_(table), topo_(BarrierTopology::build(b)) {
  for (std::size_t e = 0; e < b.size(); ++e)
    if (b.material.size() != b.size() || b.material[e] < 0 || b.material[e] >= static_cast<int>(table.materials()))
      throw std::logic_error("barrier contacts: an element without a material (resolve_material_variants)");
}

PairStats BarrierContacts::evaluate(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req) {
  if (!begin(p, b, search, req)) return {};
#pragma omp parallel if (store_.size() > kParallelThreshold)
  run_groups(p, b, search, req);
  return finish(b, req);
}

bool BarrierContacts::begin(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req) {
  const std::size_t n = p.size();
  if (b.size() == 0 || n == 0) return false;
  const BarrierBroadphase& broad = search.barrier_candidates();
  if (broad.size() != n || broad.num_elements() != b.size())
    throw std::logic_error("barrier contacts: the candidate lists do not match the scene");
  if (store_.stale(broad)) store_.relayout(broad);

  // The elements move rigidly: their triangles (normals, edge directions) once per
  // evaluation, not per candidate.
  const std::size_t m = b.size();
  tris_.resize(m);
  centres_.resize(m);
#pragma omp parallel for schedule(static) if (m > kParallelThreshold)
  for (std::size_t e = 0; e < m; ++e) {
    tris_[e] = current_triangle(b, e);
    centres_[e] = b.centre(e);
  }

  // Rotating elements: the turn of each rotation law since the committed history (the step's
  // start, req.time - req.dt), which the stored springs follow.
  const bool rotating = b.rotating();
  if (rotating) {
    step_turn_.resize(b.rotations.size());
    for (std::size_t l = 0; l < b.rotations.size(); ++l) {
      const RotationLaw& r = b.rotations[l];
      step_turn_[l] = axis_angle_matrix(r.axis, r.angle(req.time) - r.angle(req.time - req.dt));
    }
  }

  // Each group (the active particles of one block of kGroup particle indices) is summed in
  // particle order, then the groups in order: the blocked sums of deterministic_sums over all
  // particles, whatever the number of threads, without visiting the particles far from walls.
  // Within a group the particles go through batches (BarrierBatch), whose results are applied in
  // particle and contact order: the same sums as one particle after the other.
  partial_.resize(store_.groups());
  direct_ = false;
  return true;
}

void BarrierContacts::run_groups(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req) {
  const BarrierBroadphase& broad = search.barrier_candidates();
  const std::size_t m = b.size();
  const bool rotating = b.rotating();
  const std::size_t groups = store_.groups();
  const std::size_t active = store_.size();
  // One thread visits all particles in order: it can add each contact's load to its element
  // right away, in the order element_loads would (ascending particle), saving that pass.
  const bool serial = omp_get_num_threads() == 1;
  if (serial) direct_ = true;
  std::vector<BarrierContact> found;  // per thread, reused by its particles
  found.reserve(kSlots);
  const auto batch = std::make_unique<BarrierBatch>();  // per thread (~40 KB: not on the stack)
  // Runs of groups with equal numbers of active particles (those near walls cluster in index).
  const int threads = omp_get_num_threads(), r = omp_get_thread_num();
  const auto active_before = [&](std::size_t g) { return store_.group_begin(g); };
  const std::size_t g1 = balanced_split(r + 1, threads, groups, active_before);
  for (std::size_t g = balanced_split(r, threads, groups, active_before); g < g1; ++g) {
    BarrierSums acc{};
    for (std::size_t k = store_.group_begin(g); k < store_.group_begin(g + 1); ++k) {
      // Prefetch only (no effect on the results): particle data kAhead ahead, and the candidate
      // list of the particle half-way, whose offsets were prefetched kAhead / 2 visits ago.
      if (k + kAhead < active) {
        prefetch_particle(p, broad, store_.particle(k + kAhead));
        prefetch_records(store_, k + kAhead);
      }
      if (k + kAhead / 2 < active) {
        const auto c = broad.candidates(store_.particle(k + kAhead / 2));
        if (!c.empty()) __builtin_prefetch(c.data());
      }
      if (!batch->room()) flush(p, serial ? &b : nullptr, req, *batch, acc);
      if (rotating) collect<true>(k, p, b, broad, req, found, *batch, acc);
      else collect<false>(k, p, b, broad, req, found, *batch, acc);
    }
    flush(p, serial ? &b : nullptr, req, *batch, acc);
    partial_[g] = acc;
  }
  if (!serial) {
    // Each element's loads summed by one thread, over its users in particle order: the result
    // does not depend on the threads or the schedule (dynamic: a floor element may carry most).
    // In this region, after its particles: one fork and join less per evaluation.
#pragma omp barrier
#pragma omp for schedule(dynamic, 1 + m / 256)
    for (std::size_t e = 0; e < m; ++e) element_loads(b, e);
  }
}

PairStats BarrierContacts::finish(Barriers& b, const EvalRequest& req) {
  const std::size_t m = b.size();
  BarrierSums sums{};
  for (const auto& s : partial_)
    for (std::size_t c = 0; c < sums.size(); ++c) sums[c] += s[c];
  overflows_ += static_cast<std::uint64_t>(sums[4]);

  if (direct_)
    for (std::size_t e = 0; e < m; ++e) b.pressure[e] = element_pressure(b, e);
  if (req.commit) store_.commit();
  PairStats out{static_cast<std::size_t>(sums[0]), sums[1], sums[2], sums[3], sums[5], sums[6], sums[7], sums[8]};
  out.bridges = static_cast<std::size_t>(sums[9]);
  out.breaks = static_cast<std::size_t>(sums[10]);
  out.ruptures = static_cast<std::size_t>(sums[11]);
  out.cohesion_loss = sums[12];
  out.elastic_magnitude = sums[13];
  return out;
}

template <bool kRotating>
void BarrierContacts::collect(std::size_t k, const Particles& p, const Barriers& b, const BarrierBroadphase& broad,
                              const EvalRequest& req, std::vector<BarrierContact>& found, BarrierBatch& batch,
                              BarrierSums& acc) {
  const std::size_t i = store_.particle(k);
  const auto cand = broad.candidates(i);
  if (cand.empty()) {  // kept only for its records: no contact now (and no force to add)
    store_.tentative_used(k) = 0;
    store_.load_used(k) = 0;
    if (req.iteration == 1) store_.first_used(k) = 0;
    return;
  }
  const BarrierSlot* old = store_.committed(k);
  const int old_used = store_.committed_used(k);
  if (cohesive_) detect_cohesive(i, p, b, cand, old, old_used, found);
  else detect_barrier_contacts(b, topo_, tris_, p.x[i], p.radius[i], cand, found);
  const BarrierFirst* first = store_.first(k);
  const std::size_t first_used = store_.first_used(k);
  // At most one contact per candidate element, so the capacity never binds before kSlots.
  const std::size_t count = std::min({found.size(), std::size_t{kSlots}, store_.capacity(k)});
  if (found.size() > count) acc[4] += static_cast<double>(found.size() - count);
  store_.tentative_used(k) = static_cast<std::uint8_t>(count);
  store_.load_used(k) = static_cast<std::uint8_t>(count);
  if (req.iteration == 1) store_.first_used(k) = static_cast<std::uint8_t>(count);

  const Vec3 v = p.v[i], w = p.w[i];
  const double r = p.radius[i], m = p.mass[i];
  for (std::size_t c = 0; c < count; ++c) {
    const BarrierContact& bc = found[c];
    const std::size_t e = bc.element;
    // History: the same element, else a seam neighbour whose contact just ended.
    const BarrierSlot* hist = nullptr;
    double best = kInheritCos;
    for (int s = 0; s < old_used; ++s) {
      if (old[s].element == static_cast<std::int32_t>(e)) {
        hist = &old[s];
        break;
      }
    }
    if (!hist) {
      // An element switched off ends its contacts: its spring is not handed on.
      const std::uint8_t* on = b.timed() ? b.active.data() : nullptr;
      for (int s = 0; s < old_used; ++s) {
        if (old[s].element < 0 || (on && !on[old[s].element])) continue;
        bool still = false;
        for (std::size_t c2 = 0; c2 < count; ++c2)
          still |= found[c2].element == static_cast<std::uint32_t>(old[s].element);
        const double cosang = dot(old[s].normal, bc.normal);
        if (!still && cosang > best) {
          best = cosang;
          hist = &old[s];
        }
      }
    }
    // Later iterations keep the first iteration's stick/slip decision (physics/tangential.hpp).
    SlipDecision decide = SlipDecision::Free;
    if (req.iteration >= 2)
      for (std::size_t s = 0; s < first_used; ++s)
        if (first[s].element == static_cast<std::int32_t>(e))
          decide = first[s].slipped ? SlipDecision::Slip : SlipDecision::Stick;
    // Half-space of the barrier's material: its own E, nu in (51); r* = R, m* = m (76)-(79).
    const PairLaw& law = table_.barrier_pair(static_cast<std::size_t>(p.material[i]),
                                             static_cast<std::size_t>(b.material[e]));
    // No history: a zero spring, which project_spring leaves exactly zero.
    Vec3 s0 = hist ? hist->spring : Vec3{};
    Vec3 vt0 = hist ? hist->vt0 : Vec3{};
    Vec3 u = b.velocity[e];
    if constexpr (kRotating) {
      if (const std::int32_t l = b.rotation_of[e]; l >= 0) {
        // The surface's own velocity at the contact point; the spring turns with the element.
        u = b.surface_velocity(e, bc.point);
        s0 = mat_apply(step_turn_[static_cast<std::size_t>(l)], s0);
        vt0 = mat_apply(step_turn_[static_cast<std::size_t>(l)], vt0);
      }
    }
    const std::size_t t = batch.count++;
    batch.element[t] = static_cast<std::int32_t>(e);
    batch.hist[t] = hist;
    batch.decide[t] = decide;
    batch.point[t] = bc.point;
    batch.overlap[t] = bc.overlap;
    batch.nx[t] = bc.normal.x, batch.ny[t] = bc.normal.y, batch.nz[t] = bc.normal.z;
    batch.vx[t] = v.x, batch.vy[t] = v.y, batch.vz[t] = v.z;
    batch.wx[t] = w.x, batch.wy[t] = w.y, batch.wz[t] = w.z;
    batch.ux[t] = u.x, batch.uy[t] = u.y, batch.uz[t] = u.z;
    batch.s0x[t] = s0.x, batch.s0y[t] = s0.y, batch.s0z[t] = s0.z;
    batch.vt0x[t] = vt0.x, batch.vt0y[t] = vt0.y, batch.vt0z[t] = vt0.z;
    batch.set_law(t, law);
    batch.r_star[t] = r, batch.m_star[t] = m;
    if (cohesive_) {
      batch.state0[t] = static_cast<std::uint8_t>(hist ? hist->state : 0u);
      batch.bridge[t] = bridge_of(p.material[i], b.material[e]);
    }
  }
  if (cohesive_ && req.commit)
    book_undetected(p.material[i], b, r, old, old_used, batch.hist + batch.count - count, count, acc);
  batch.k[batch.particles] = static_cast<std::uint32_t>(k);
  batch.end[batch.particles] = static_cast<std::uint32_t>(batch.count);
  ++batch.particles;
}

void BarrierContacts::flush(Particles& p, Barriers* loads_to, const EvalRequest& req, BarrierBatch& batch,
                            BarrierSums& acc) {
  if (batch.particles == 0) return;
  if (batch.count > 0) barrier_contact_law(table_.barrier_laws(), req, batch, cohesive_);
  // In particle order, each particle's contacts in order: the original per-particle sums.
  const bool rolling = table_.any_rolling();
  const double dt = req.dt;
  // The sums in registers: acc could alias the records written below, as far as the compiler
  // knows, and every += would wait on the previous store.
  double sum0 = acc[0], sum1 = acc[1], sum2 = acc[2], sum3 = acc[3], sum5 = acc[5], sum6 = acc[6], sum7 = acc[7],
         sum8 = acc[8];
  std::size_t t = 0;
  for (std::size_t q = 0; q < batch.particles; ++q) {
    const std::size_t k = batch.k[q];
    const std::size_t i = store_.particle(k);
    BarrierSlot* tent = store_.tentative(k);
    BarrierLoad* load = store_.loads(k);
    BarrierFirst* first = store_.first(k);
    Vec3 force{}, torque{};
    for (std::size_t c = 0; t < batch.end[q]; ++t, ++c) {
      const BarrierSlot* hist = batch.hist[t];
      const Vec3 w{batch.wx[t], batch.wy[t], batch.wz[t]};
      // Against the rotation of the step start, like particle pairs (contact/particle_contacts.cpp).
      Vec3 roll{};
      if (rolling) {
        const Vec3 wr0 = req.iteration > 0 ? (hist ? hist->wr0 : Vec3{}) : w;
        roll = rolling_resistance_torque(wr0, batch.coefficients[kMuR][t], batch.r_star[t], batch.fn_load[t],
                                         p.inertia[i], dt);
      }
      const Vec3 f{batch.fx[t], batch.fy[t], batch.fz[t]};
      force += f;
      torque += Vec3{batch.tx[t], batch.ty[t], batch.tz[t]} + roll;
      const std::int32_t el = batch.element[t];
      const auto slipped = static_cast<std::uint32_t>(batch.slip[t]);
      // Field by field into place (a whole-record copy would reload fresh stores in other widths).
      BarrierSlot& ts = tent[c];
      ts.element = el;
      ts.slipped = slipped;
      ts.spring = {batch.sx[t], batch.sy[t], batch.sz[t]};
      ts.vt0 = {batch.vtx[t], batch.vty[t], batch.vtz[t]};
      ts.normal = {batch.nx[t], batch.ny[t], batch.nz[t]};
      ts.wr0 = w;
      ts.state = cohesive_ ? batch.next[t] : 0u;
      BarrierLoad& ls = load[c];
      ls.force = -f;
      ls.point = batch.point[t];
      ls.overlap = batch.overlap[t];
      ls.element = el;
      if (loads_to) {  // at most one contact per element and particle (detection's merge)
        const auto e = static_cast<std::size_t>(el);
        loads_to->force[e] += ls.force;
        loads_to->moment[e] += cross(ls.point - centres_[e], ls.force);
      }
      if (req.iteration == 1) first[c] = BarrierFirst{el, slipped};
      if (cohesive_) {
        sum0 += (batch.live[t] & kLawFormed) != 0 ? 1.0 : 0.0;
        acc[9] += (batch.live[t] & kBridgeFormed) != 0 ? 1.0 : 0.0;
        acc[13] += std::abs(batch.energy[t]);
        if (req.commit) {
          acc[10] += (batch.broke[t] & kLawFormed) != 0 ? 1.0 : 0.0;
          acc[11] += (batch.broke[t] & kBridgeFormed) != 0 ? 1.0 : 0.0;
          acc[12] += batch.loss[t];
        }
      } else {
        sum0 += 1.0;
      }
      sum1 += batch.energy[t];
      sum2 += batch.damping[t];
      sum3 -= dot(roll, w);
      sum5 += slipped ? 0.0 : batch.tangential_loss[t];  // selected values, not a selected address (register sums)
      sum6 += slipped ? batch.tangential_loss[t] : 0.0;
      sum7 += batch.spring_energy_before[t];
      sum8 += batch.spring_energy_after[t];
    }
    p.force[i] += force;
    p.torque[i] += torque;
  }
  acc[0] = sum0, acc[1] = sum1, acc[2] = sum2, acc[3] = sum3, acc[5] = sum5, acc[6] = sum6, acc[7] = sum7,
  acc[8] = sum8;
  batch.particles = 0;
  batch.count = 0;
}

}  // namespace mpdem
