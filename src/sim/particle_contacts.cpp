#include "sim/particle_contacts.hpp"

#include <algorithm>

#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"
#include "physics/contact_geometry.hpp"
#include "physics/hertz.hpp"
#include "physics/rolling.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

PairStats ParticleContacts::evaluate(Particles& p, const NeighborSearch& search, const EvalRequest& req) {
  const VerletList& list = search.pairs();
  const std::size_t n = p.size();
  const std::size_t pairs = list.num_pairs();
  if (spring_.size() != pairs) {  // first use: no history yet
    spring_.assign(pairs, Vec3{});
    vt0_.assign(pairs, Vec3{});
    wr0_.assign(pairs, Vec3{});
  }
  spring_tent_.resize(pairs);
  vt_tent_.resize(pairs);
  if (req.commit) wr_tent_.resize(pairs);
  force_.resize(pairs);
  torque_first_.resize(pairs);
  torque_second_.resize(pairs);
  touching_.resize(pairs);
  overlap_.resize(pairs);
  slipped_.resize(pairs);
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const double dt = req.dt, phi = req.phi;
  const ContactModel law = law_;
  const bool commit = req.commit;

  // Per-particle halves of (51)-(53) and the Mindlin G*: each effective value is then one
  // division per pair, 1/(a_i + a_j), instead of eight divisions per contact and evaluation.
  compliance_.resize(n);
  shear_compliance_.resize(n);
  inv_radius_.resize(n);
  inv_mass_.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    const double nu = p.poisson[i];
    compliance_[i] = (1.0 - nu * nu) / p.young[i];                           // 1/Pa, (51)
    shear_compliance_[i] = (2.0 - nu) / shear_modulus(p.young[i], nu);       // 1/Pa, Mindlin G*
    inv_radius_[i] = 1.0 / p.radius[i];                                      // 1/m, (52)
    inv_mass_[i] = 1.0 / p.mass[i];                                          // 1/kg, (53)
  }

  // 1. Pair laws, one slot at a time; each slot is written by exactly one thread.
  const auto sums = deterministic_sums<4>(n, [&](std::size_t i, std::array<double, 4>& acc) {
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      const std::size_t j = idx[k];
      // Cheap rejection of clearly separated listed pairs (about a third at skin 0.1 d) before
      // the square root and division; the margin leaves the exact decision to pair_geometry.
      const double reach = p.radius[i] + p.radius[j];
      const bool apart = norm2(p.x[i] - p.x[j]) > reach * reach * (1.0 + 1e-9);
      const PairGeometry g = apart ? PairGeometry{} : pair_geometry(p.x[i], p.radius[i], p.x[j], p.radius[j]);
      if (!(g.overlap > 0.0)) {
        // Zero tentative history, so that a commit is a swap of the arrays.
        touching_[k] = 0;
        force_[k] = torque_first_[k] = torque_second_[k] = Vec3{};  // the gather needs no branch
        spring_tent_[k] = Vec3{};
        vt_tent_[k] = Vec3{};
        if (commit) wr_tent_[k] = Vec3{};
        continue;
      }
      touching_[k] = 1;
      overlap_[k] = g.overlap;
      const double E = 1.0 / (compliance_[i] + compliance_[j]);                               // (51)
      const double r = 1.0 / (inv_radius_[i] + inv_radius_[j]);                               // (52)
      const double m = 1.0 / (inv_mass_[i] + inv_mass_[j]);                                   // (53)
      const Vec3 vrel = contact_relative_velocity(p.v[i], p.w[i], g.r_Pi, p.v[j], p.w[j], g.r_Pj);  // (60)
      const double vn = normal_rate(vrel, g.normal);
      const Vec3 vt = tangential_part(vrel, g.normal);                                         // (61)
      const NormalForce fn = normal_contact_force(E, r, m, law.xi_n, g.overlap, vn);          // (49)-(50)
      // Tangential spring (57)-(70): the stored spring on the current tangent plane plus the
      // trapezoidal increment (64).
      const double G = 1.0 / (shear_compliance_[i] + shear_compliance_[j]);
      const double kt = tangential_stiffness(G, r, g.overlap);                                 // (65)
      const double dtc = tangential_damping_coefficient(law.xi_t, m, kt);                      // (67)
      const Vec3 ds = dt * ((1.0 - phi) * vt0_[k] + phi * vt);
      const SlipDecision decide = req.iteration >= 2 ? (slipped_[k] ? SlipDecision::Slip : SlipDecision::Stick)
                                                     : SlipDecision::Free;
      const TangentialResult ft = tangential_force(project_spring(spring_[k], g.normal), ds, vt, kt, dtc, law.mu_s,
                                                   law.mu_d, fn.magnitude, decide);
      if (req.iteration == 1) slipped_[k] = ft.slipped;
      // Torques: tangential force at the contact point (62) and rolling resistance (71).
      // Rolling resistance (71) acts against the relative rotation of the step start (the state
      // itself at a commit evaluation, which starts the next step): a torque that is constant
      // during the iteration, since its direction flips where w_rel = 0 (docs/contact_model.md).
      const Vec3 wrel = p.w[i] - p.w[j];
      const Vec3 roll = rolling_resistance_torque(req.iteration > 0 ? wr0_[k] : wrel, law.mu_r, r, fn.magnitude,
                                                  rolling_inertia_pair(p.inertia[i], p.inertia[j]), dt);
      force_[k] = fn.magnitude * g.normal + ft.force;
      torque_first_[k] = cross(g.r_Pi, ft.force) + roll;
      torque_second_[k] = cross(g.r_Pj, -ft.force) - roll;
      spring_tent_[k] = ft.spring;
      vt_tent_[k] = vt;
      if (commit) wr_tent_[k] = wrel;
      acc[0] += 1.0;
      acc[1] += hertz_elastic_energy(E, r, g.overlap) + 0.5 * kt * norm2(ft.spring);
      acc[2] += fn.dissipated_power + (ft.slipped ? 0.0 : ft.dissipated_power);
      acc[3] += (ft.slipped ? ft.dissipated_power : 0.0) - dot(roll, wrel);
    }
  });

  // 2. Gather per particle in a fixed order: own slots, then incoming slots.
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 f{}, t{};
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      f += force_[k];
      t += torque_first_[k];
    }
    for (std::uint32_t k : search.incoming(i)) {
      f -= force_[k];
      t += torque_second_[k];
    }
    p.force[i] += f;
    p.torque[i] += t;
  }

  // 3. Commit: springs of touching pairs are kept, opened contacts forget theirs.
  // The tentative arrays hold zeros for open slots, so committing is swapping.
  if (commit) {
    spring_.swap(spring_tent_);
    vt0_.swap(vt_tent_);
    wr0_.swap(wr_tent_);
  }
  return {static_cast<std::size_t>(sums[0]), sums[1], sums[2], sums[3]};
}

OverlapReport ParticleContacts::max_overlap(const Particles& p, const NeighborSearch& search) const {
  OverlapReport r;
  const auto& idx = search.pairs().indices();
  if (touching_.size() != idx.size()) return r;
  std::size_t best = idx.size();
  const auto& off = search.pairs().offsets();
  for (std::size_t i = 0; i + 1 < off.size(); ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      if (!touching_[k]) continue;
      // Divide only for a candidate deeper than the best so far (checked every step).
      const double rmin = std::min(p.radius[i], p.radius[idx[k]]);
      if (!(overlap_[k] > r.ratio * rmin)) continue;
      const double ratio = overlap_[k] / rmin;
      if (ratio > r.ratio) {
        r.ratio = ratio;
        best = k;
      }
    }
  if (best < idx.size()) {
    r.particle = p.id[search.first_of(best)];
    r.other = p.id[idx[best]];
  }
  return r;
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
  if (spring_.size() != list.num_pairs() || list.size() != p.size()) return h;
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k)
      if (norm2(spring_[k]) > 0.0 || norm2(vt0_[k]) > 0.0 || norm2(wr0_[k]) > 0.0)
        h.push_back({p.id[i], p.id[idx[k]], spring_[k], vt0_[k], wr0_[k]});
  return h;
}

void ParticleContacts::import_history(const Particles& p, const NeighborSearch& search, std::vector<PairHistory> h) {
  const VerletList& list = search.pairs();
  spring_.assign(list.num_pairs(), Vec3{});
  vt0_.assign(list.num_pairs(), Vec3{});
  wr0_.assign(list.num_pairs(), Vec3{});
  if (h.empty()) return;
  // Orient every record as (smaller id, larger id); look slots up by binary search.
  for (PairHistory& r : h)
    if (r.id_first > r.id_second) {
      std::swap(r.id_first, r.id_second);
      r.spring = -r.spring;
      r.vt0 = -r.vt0;
      r.wr0 = -r.wr0;
    }
  auto key_less = [](const PairHistory& a, const PairHistory& b) {
    return a.id_first != b.id_first ? a.id_first < b.id_first : a.id_second < b.id_second;
  };
  std::sort(h.begin(), h.end(), key_less);
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      const std::int64_t a = p.id[i], b = p.id[idx[k]];
      const bool flip = a > b;
      PairHistory key{flip ? b : a, flip ? a : b, {}, {}, {}};
      auto it = std::lower_bound(h.begin(), h.end(), key, key_less);
      if (it == h.end() || it->id_first != key.id_first || it->id_second != key.id_second) continue;
      spring_[k] = flip ? -it->spring : it->spring;
      vt0_[k] = flip ? -it->vt0 : it->vt0;
      wr0_[k] = flip ? -it->wr0 : it->wr0;
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
