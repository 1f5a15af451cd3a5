#include "sim/barrier_contacts.hpp"

#include <stdexcept>

#include "core/deterministic_sum.hpp"
#include "physics/contact_geometry.hpp"
#include "physics/hertz.hpp"
#include "physics/rolling.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

namespace {
constexpr double kInheritCos = 0.9;  // a seam neighbour's normal within ~25 degrees
}

BarrierContacts::BarrierContacts(const ContactModel& law, const Barriers& b)
    : law_(law), topo_(BarrierTopology::build(b)) {}

void BarrierContacts::resize(std::size_t n) {
  if (counts_valid_ && committed_.size() == n * kSlots && committed_used_.size() == n) return;
  committed_.resize(n * kSlots);
  tentative_.resize(n * kSlots);
  loads_.resize(n * kSlots);
  first_.resize(n * kSlots);
  recount();
}

void BarrierContacts::recount() {
  const std::size_t n = committed_.size() / kSlots;
  committed_used_.assign(n, 0);
  tentative_used_.assign(n, static_cast<std::uint8_t>(kSlots));  // unknown: clear all once
  first_used_.assign(n, 0);
  load_used_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    int used = 0;
    for (int s = 0; s < kSlots; ++s)
      if (committed_[i * kSlots + static_cast<std::size_t>(s)].element >= 0) used = s + 1;
    committed_used_[i] = static_cast<std::uint8_t>(used);
  }
  counts_valid_ = true;
}

PairStats BarrierContacts::evaluate(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req) {
  const std::size_t n = p.size();
  if (b.size() == 0 || n == 0) return {};
  resize(n);
  const BarrierBroadphase& broad = search.barrier_candidates();
  const double dt = req.dt, phi = req.phi;
  const ContactModel law = law_;
  std::uint64_t dropped = 0;

  const auto sums = deterministic_sums<5>(n, [&](std::size_t i, std::array<double, 5>& acc) {
    const auto cand = broad.candidates(i);
    Slot* tent = &tentative_[i * kSlots];
    if (cand.empty()) {  // away from the walls: only forget what the buffer held
      for (std::size_t c = 0; c < tentative_used_[i]; ++c) tent[c] = Slot{};
      tentative_used_[i] = 0;
      load_used_[i] = 0;
      if (req.iteration == 1) first_used_[i] = 0;
      return;
    }
    thread_local std::vector<BarrierContact> found;
    detect_barrier_contacts(b, topo_, p.x[i], p.radius[i], cand, found);
    const Slot* old = &committed_[i * kSlots];
    const int old_used = committed_used_[i];
    Load* load = &loads_[i * kSlots];
    FirstSlot* first = &first_[i * kSlots];
    const std::size_t count = std::min<std::size_t>(found.size(), kSlots);
    if (found.size() > count) acc[4] += static_cast<double>(found.size() - count);
    Vec3 force{}, torque{};
    for (std::size_t c = 0; c < count; ++c) {
      const BarrierContact& bc = found[c];
      const std::size_t e = bc.element;
      // History: the same element, else a seam neighbour whose contact just ended.
      const Slot* hist = nullptr;
      double best = kInheritCos;
      for (int s = 0; s < old_used; ++s) {
        if (old[s].element == static_cast<std::int32_t>(e)) { hist = &old[s]; break; }
      }
      if (!hist) {
        for (int s = 0; s < old_used; ++s) {
          if (old[s].element < 0) continue;
          bool still = false;
          for (std::size_t c2 = 0; c2 < count; ++c2) still |= found[c2].element == static_cast<std::uint32_t>(old[s].element);
          const double cosang = dot(old[s].normal, bc.normal);
          if (!still && cosang > best) { best = cosang; hist = &old[s]; }
        }
      }
      const Vec3& nrm = bc.normal;
      // Half-space of the barrier's material: its own E, nu in (51); r* = R, m* = m (76)-(79).
      const double E = effective_modulus(p.young[i], p.poisson[i], b.young[e], b.poisson[e]);
      const double r = p.radius[i], m = p.mass[i];
      const Vec3 rP = -r * nrm;
      const Vec3 vrel = contact_relative_velocity_barrier(p.v[i], p.w[i], rP, b.velocity[e]);
      const double vn = normal_rate(vrel, nrm);
      const Vec3 vt = tangential_part(vrel, nrm);
      const NormalForce fn = normal_contact_force(E, r, m, law.xi_n, bc.overlap, vn);
      const double G = effective_shear_modulus(shear_modulus(p.young[i], p.poisson[i]), p.poisson[i],
                                               shear_modulus(b.young[e], b.poisson[e]), b.poisson[e]);
      const double kt = tangential_stiffness(G, r, bc.overlap);
      const double dtc = tangential_damping_coefficient(law.xi_t, m, kt);
      const Vec3 s0 = hist ? project_spring(hist->spring, nrm) : Vec3{};
      const Vec3 vt0 = hist ? hist->vt0 : Vec3{};
      // Later iterations keep the first iteration's stick/slip decision (physics/tangential.hpp).
      SlipDecision decide = SlipDecision::Free;
      if (req.iteration >= 2)
        for (std::size_t s = 0; s < first_used_[i]; ++s)
          if (first[s].element == static_cast<std::int32_t>(e))
            decide = first[s].slipped ? SlipDecision::Slip : SlipDecision::Stick;
      const TangentialResult ft = tangential_force(s0, dt * ((1.0 - phi) * vt0 + phi * vt), vt, kt, dtc, law.mu_s,
                                                   law.mu_d, fn.magnitude, decide);
      // Against the rotation of the step start, like particle pairs (sim/particle_contacts.cpp).
      const Vec3 wr0 = req.iteration > 0 ? (hist ? hist->wr0 : Vec3{}) : p.w[i];
      const Vec3 roll = rolling_resistance_torque(wr0, law.mu_r, r, fn.magnitude, p.inertia[i], dt);
      const Vec3 f = fn.magnitude * nrm + ft.force;
      force += f;
      torque += cross(rP, ft.force) + roll;
      tent[c] = Slot{static_cast<std::int32_t>(e), ft.spring, vt, nrm, ft.slipped, p.w[i]};
      load[c] = Load{static_cast<std::int32_t>(e), -f, bc.point, bc.overlap};
      if (req.iteration == 1) first[c] = FirstSlot{static_cast<std::int32_t>(e), ft.slipped};
      acc[0] += 1.0;
      acc[1] += hertz_elastic_energy(E, r, bc.overlap) + 0.5 * kt * norm2(ft.spring);
      acc[2] += fn.dissipated_power + (ft.slipped ? 0.0 : ft.dissipated_power);
      acc[3] += (ft.slipped ? ft.dissipated_power : 0.0) - dot(roll, p.w[i]);
    }
    for (std::size_t c = count; c < tentative_used_[i]; ++c) tent[c] = Slot{};
    tentative_used_[i] = static_cast<std::uint8_t>(count);
    load_used_[i] = static_cast<std::uint8_t>(count);
    if (req.iteration == 1) first_used_[i] = static_cast<std::uint8_t>(count);
    p.force[i] += force;
    p.torque[i] += torque;
  });
  dropped = static_cast<std::uint64_t>(sums[4]);
  overflows_ += dropped;

  // Loads on the elements, accumulated in particle order (deterministic).
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < load_used_[i]; ++c) {
      const Load& l = loads_[i * kSlots + c];
      const std::size_t e = static_cast<std::size_t>(l.element);
      b.force[e] += l.force;
      b.moment[e] += cross(l.point - b.centre(e), l.force);
    }
  for (std::size_t e = 0; e < b.size(); ++e) b.pressure[e] = -dot(b.force[e], b.normal[e]) / b.area[e];

  if (req.commit) {
    committed_.swap(tentative_);
    committed_used_.swap(tentative_used_);
  }
  return {static_cast<std::size_t>(sums[0]), sums[1], sums[2], sums[3]};
}

OverlapReport BarrierContacts::max_overlap(const Particles& p, const Barriers& b) const {
  OverlapReport r;
  if (loads_.size() != p.size() * kSlots || load_used_.size() != p.size()) return r;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t c = 0; c < load_used_[i]; ++c) {
      const Load& l = loads_[i * kSlots + c];
      const double ratio = l.overlap / p.radius[i];
      if (ratio > r.ratio) r = {ratio, p.id[i], -1, b.id[static_cast<std::size_t>(l.element)]};
    }
  return r;
}

void BarrierContacts::save(BinaryWriter& w) const {
  w.vector(committed_);
  w.value(overflows_);
}

void BarrierContacts::restore(BinaryReader& r, std::size_t particles) {
  committed_ = r.vector<Slot>();
  overflows_ = r.value<std::uint64_t>();
  counts_valid_ = false;
  if (!committed_.empty() && committed_.size() != particles * kSlots)
    throw std::runtime_error("checkpoint does not match the scene (barrier contact history)");
}

void BarrierContacts::permute(const std::vector<std::uint32_t>& order) {
  if (committed_.size() != order.size() * kSlots) return;
  std::vector<Slot> old = committed_;
  for (std::size_t k = 0; k < order.size(); ++k)
    for (int s = 0; s < kSlots; ++s) committed_[k * kSlots + s] = old[order[k] * kSlots + s];
  counts_valid_ = false;
}

void BarrierContacts::compact(const std::vector<char>& keep) {
  if (committed_.size() != keep.size() * kSlots) return;
  std::size_t k = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) continue;
    for (int s = 0; s < kSlots; ++s) committed_[k * kSlots + s] = committed_[i * kSlots + s];
    ++k;
  }
  committed_.resize(k * kSlots);
  counts_valid_ = false;
}

}  // namespace mpdem
