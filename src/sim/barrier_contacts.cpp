#include "sim/barrier_contacts.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/parallel.hpp"
#include "physics/contact_coefficients.hpp"
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

PairStats BarrierContacts::evaluate(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req) {
  const std::size_t n = p.size();
  if (b.size() == 0 || n == 0) return {};
  const BarrierBroadphase& broad = search.barrier_candidates();
  if (broad.size() != n || broad.num_elements() != b.size())
    throw std::logic_error("barrier contacts: the candidate lists do not match the scene");
  if (store_.stale(broad)) store_.relayout(broad);

  // Each group (the active particles of one block of kGroup particle indices) is summed in
  // particle order, then the groups in order: the blocked sums of deterministic_sums over all
  // particles, whatever the number of threads, without visiting the particles far from walls.
  const std::size_t groups = store_.groups();
  partial_.resize(groups);
#pragma omp parallel for schedule(static) if (store_.size() > kParallelThreshold)
  for (std::size_t g = 0; g < groups; ++g) {
    std::array<double, 5> acc{};
    for (std::size_t k = store_.group_begin(g); k < store_.group_begin(g + 1); ++k)
      particle_contacts(k, p, b, broad, req, acc);
    partial_[g] = acc;
  }
  std::array<double, 5> sums{};
  for (const auto& s : partial_)
    for (std::size_t c = 0; c < sums.size(); ++c) sums[c] += s[c];
  overflows_ += static_cast<std::uint64_t>(sums[4]);

  element_loads(b);
  if (req.commit) store_.commit();
  return {static_cast<std::size_t>(sums[0]), sums[1], sums[2], sums[3]};
}

void BarrierContacts::particle_contacts(std::size_t k, Particles& p, const Barriers& b, const BarrierBroadphase& broad,
                                        const EvalRequest& req, std::array<double, 5>& acc) {
  const std::size_t i = store_.particle(k);
  const auto cand = broad.candidates(i);
  if (cand.empty()) {  // kept only for its records: no contact now
    store_.tentative_used(k) = 0;
    store_.load_used(k) = 0;
    if (req.iteration == 1) store_.first_used(k) = 0;
    return;
  }
  thread_local std::vector<BarrierContact> found;
  detect_barrier_contacts(b, topo_, p.x[i], p.radius[i], cand, found);
  const BarrierSlot* old = store_.committed(k);
  const int old_used = store_.committed_used(k);
  BarrierSlot* tent = store_.tentative(k);
  BarrierLoad* load = store_.loads(k);
  BarrierFirst* first = store_.first(k);
  const std::size_t first_used = store_.first_used(k);
  // At most one contact per candidate element, so the capacity never binds before kSlots.
  const std::size_t count = std::min({found.size(), std::size_t{kSlots}, store_.capacity(k)});
  if (found.size() > count) acc[4] += static_cast<double>(found.size() - count);
  const double dt = req.dt, phi = req.phi;
  const ContactModel& law = law_;
  Vec3 force{}, torque{};
  for (std::size_t c = 0; c < count; ++c) {
    const BarrierContact& bc = found[c];
    const std::size_t e = bc.element;
    // History: the same element, else a seam neighbour whose contact just ended.
    const BarrierSlot* hist = nullptr;
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
    const double G = effective_shear_modulus(shear_modulus(p.young[i], p.poisson[i]), p.poisson[i],
                                             shear_modulus(b.young[e], b.poisson[e]), b.poisson[e]);
    // (49)-(50), (65), (67) sharing one sqrt(r* delta).
    const ContactCoefficients cc = contact_coefficients(E, G, r, m, law.xi_n, law.xi_t, bc.overlap);
    const NormalForce fn = damped_normal_force(cc.f_el, cc.d_n, vn);
    const double kt = cc.k_t, dtc = cc.d_t;
    const Vec3 s0 = hist ? project_spring(hist->spring, nrm) : Vec3{};
    const Vec3 vt0 = hist ? hist->vt0 : Vec3{};
    // Later iterations keep the first iteration's stick/slip decision (physics/tangential.hpp).
    SlipDecision decide = SlipDecision::Free;
    if (req.iteration >= 2)
      for (std::size_t s = 0; s < first_used; ++s)
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
    const auto el = static_cast<std::int32_t>(e);
    const std::uint32_t slipped = ft.slipped ? 1u : 0u;
    tent[c] = BarrierSlot{el, slipped, ft.spring, vt, nrm, p.w[i]};
    load[c] = BarrierLoad{-f, bc.point, bc.overlap, el};
    if (req.iteration == 1) first[c] = BarrierFirst{el, slipped};
    acc[0] += 1.0;
    acc[1] += hertz_energy_from_force(cc.f_el, bc.overlap) + 0.5 * kt * norm2(ft.spring);
    acc[2] += fn.dissipated_power + (ft.slipped ? 0.0 : ft.dissipated_power);
    acc[3] += (ft.slipped ? ft.dissipated_power : 0.0) - dot(roll, p.w[i]);
  }
  store_.tentative_used(k) = static_cast<std::uint8_t>(count);
  store_.load_used(k) = static_cast<std::uint8_t>(count);
  if (req.iteration == 1) store_.first_used(k) = static_cast<std::uint8_t>(count);
  p.force[i] += force;
  p.torque[i] += torque;
}

void BarrierContacts::element_loads(Barriers& b) {
  // One element's loads are summed by one thread, over its users in particle order: the result
  // does not depend on the threads or the schedule (dynamic: a floor element may carry most).
  const std::size_t m = b.size();
  const std::size_t chunk = 1 + m / 256;
#pragma omp parallel for schedule(dynamic, chunk) if (store_.size() > kParallelThreshold)
  for (std::size_t e = 0; e < m; ++e) {
    std::size_t users = 0;
    const std::uint32_t* user = store_.element_users(e, users);
    if (users > 0) {
      const auto el = static_cast<std::int32_t>(e);
      const Vec3 centre = b.centre(e);
      Vec3 force = b.force[e], moment = b.moment[e];
      for (std::size_t u = 0; u < users; ++u) {
        const BarrierLoad* l = store_.loads(user[u]);
        const std::size_t used = store_.load_used(user[u]);
        for (std::size_t c = 0; c < used; ++c)
          if (l[c].element == el) {
            force += l[c].force;
            moment += cross(l[c].point - centre, l[c].force);
            break;
          }
      }
      b.force[e] = force;
      b.moment[e] = moment;
    }
    b.pressure[e] = -dot(b.force[e], b.normal[e]) / b.area[e];
  }
}

OverlapReport BarrierContacts::max_overlap(const Particles& p, const Barriers& b) const {
  OverlapReport r;
  for (std::size_t k = 0; k < store_.size(); ++k) {
    const std::size_t i = store_.particle(k);
    if (i >= p.size()) continue;
    const BarrierLoad* l = store_.loads(k);
    for (std::size_t c = 0; c < store_.load_used(k); ++c) {
      const double ratio = l[c].overlap / p.radius[i];
      if (ratio > r.ratio) r = {ratio, p.id[i], -1, b.id[static_cast<std::size_t>(l[c].element)]};
    }
  }
  return r;
}

void BarrierContacts::save(BinaryWriter& w) const {
  store_.save(w);
  w.value(overflows_);
}

void BarrierContacts::restore(BinaryReader& r, std::size_t particles) {
  store_.restore(r, particles);
  overflows_ = r.value<std::uint64_t>();
}

}  // namespace mpdem
