#include "sim/pair_batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "neighbor/pair_blocks.hpp"
#include "physics/contact_coefficients.hpp"
#include "physics/hertz.hpp"
#include "physics/rolling.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

namespace {

constexpr std::size_t kBatch = 64;                  // candidate pairs per batch
constexpr std::uint32_t kInternal = 0xffffffffu;    // "no cross index"

// One batch: the candidates, then each stage's results (arrays over the batch).
struct Batch {
  std::size_t count = 0;
  std::uint32_t i[kBatch], j[kBatch];  // members
  std::size_t slot[kBatch];            // pair slot
  std::uint32_t cross[kBatch];         // cross index, or kInternal
  // Stage 1: geometry and kinematics.
  bool touching[kBatch];
  double overlap[kBatch];              // m, 0 when apart
  Vec3 normal[kBatch];                 // -, n_ij, from j to i
  Vec3 vt[kBatch];                     // m/s, tangential relative velocity (61)
  double vn[kBatch];                   // m/s, normal rate
  double E[kBatch], G[kBatch], r[kBatch], m[kBatch];  // Pa, Pa, m, kg (51)-(53), Mindlin G*
  // Stage 2: normal law.
  ContactCoefficients cc[kBatch];
  NormalForce fn[kBatch];
  // Stage 3: tangential law.
  TangentialResult ft[kBatch];
};

// Stage 1 (60)-(62): overlap, normal, relative velocity at the contact point.
void geometry(const PairPass& q, Batch& b) {
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t i = b.i[t], j = b.j[t];
    const Vec3 d = q.x[i] - q.x[j];
    const double ri = q.radius[i], rj = q.radius[j];
    const double dist = std::sqrt(norm2(d));
    const double ov = ri + rj - dist;
    b.touching[t] = ov > 0.0;
    b.overlap[t] = ov > 0.0 ? ov : 0.0;
    // Coincident centres get +z, so nothing becomes NaN.
    const Vec3 nrm = dist > 0.0 ? d * (1.0 / dist) : Vec3{0.0, 0.0, 1.0};
    b.normal[t] = nrm;
    const ContactTerms& ti = q.terms[i];
    const ContactTerms& tj = q.terms[j];
    b.E[t] = 1.0 / (ti.compliance + tj.compliance);              // (51)
    b.G[t] = 1.0 / (ti.shear_compliance + tj.shear_compliance);  // Mindlin G*
    b.r[t] = 1.0 / (ti.inv_radius + tj.inv_radius);              // (52)
    b.m[t] = 1.0 / (ti.inv_mass + tj.inv_mass);                  // (53)
    // (60) with the arms r_Pi = -R_i n, r_Pj = R_j n (62).
    const Vec3 vrel = (q.v[i] - q.v[j]) - cross(ri * q.w[i] + rj * q.w[j], nrm);
    b.vn[t] = dot(vrel, nrm);
    b.vt[t] = vrel - b.vn[t] * nrm;                              // (61)
  }
}

// Stage 2 (49)-(50), (65), (67); an apart candidate (overlap 0) gets zero coefficients.
void normal_law(const PairPass& q, Batch& b) {
  for (std::size_t t = 0; t < b.count; ++t) {
    b.cc[t] = contact_coefficients(b.E[t], b.G[t], b.r[t], b.m[t], q.law.xi_n, q.law.xi_t, b.overlap[t]);
    b.fn[t] = damped_normal_force(b.cc[t].f_el, b.cc[t].d_n, b.vn[t]);
  }
}

// Stage 3 (57)-(70): the stored spring on the current tangent plane plus the trapezoidal
// increment (64) (Verlet: phi = 1), Coulomb stick or slip.
void tangential_law(const PairPass& q, Batch& b) {
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t k = b.slot[t];
    const Vec3 ds = q.vt0 ? q.dt * ((1.0 - q.phi) * q.vt0[k] + q.phi * b.vt[t]) : (q.dt * q.phi) * b.vt[t];
    const SlipDecision decide = q.iteration >= 2 ? (q.slipped[k] ? SlipDecision::Slip : SlipDecision::Stick)
                                                 : SlipDecision::Free;
    b.ft[t] = tangential_force(project_spring(q.spring[k], b.normal[t]), ds, b.vt[t], b.cc[t].k_t, b.cc[t].d_t,
                               q.law.mu_s, q.law.mu_d, b.fn[t].magnitude, decide);
  }
}

// Stage 4: history, rolling resistance (71), and the sums, in slot order.
void apply(const PairPass& q, const Batch& b, PairBlockSums& out) {
  const bool rolling = q.law.mu_r > 0.0;
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t i = b.i[t], j = b.j[t], k = b.slot[t];
    if (!b.touching[t]) {  // a candidate within the margin but apart: forget its history
      if (q.commit) {
        q.spring[k] = Vec3{};
        if (q.vt0) q.vt0[k] = Vec3{};
        if (q.wr0) q.wr0[k] = Vec3{};
      }
      continue;
    }
    const Vec3& nrm = b.normal[t];
    const TangentialResult& ft = b.ft[t];
    const NormalForce& fn = b.fn[t];
    if (q.iteration == 1) q.slipped[k] = ft.slipped;
    // Rolling resistance against the relative rotation of the step start (the state itself
    // outside the iteration): constant during the iteration (docs/contact_model.md).
    const Vec3 wrel = q.w[i] - q.w[j];
    Vec3 roll{};
    if (rolling)
      roll = rolling_resistance_torque(q.iteration > 0 ? q.wr0[k] : wrel, q.law.mu_r, b.r[t], fn.magnitude,
                                       rolling_inertia_pair(q.inertia[i], q.inertia[j]), q.dt);
    if (q.commit) {
      q.spring[k] = ft.spring;
      if (q.vt0) q.vt0[k] = b.vt[t];
      if (q.wr0) q.wr0[k] = wrel;
    }
    const Vec3 f = fn.magnitude * nrm + ft.force;
    const Vec3 arm = cross(nrm, ft.force);  // torque r_P x f_t = -R n x f_t on both members (62)
    if (b.cross[t] == kInternal) {
      q.force[i] += f;
      q.torque[i] += roll - q.radius[i] * arm;
      q.force[j] -= f;
      q.torque[j] -= roll + q.radius[j] * arm;
    } else {
      q.cross_force[b.cross[t]] = f;
      q.cross_arm[b.cross[t]] = arm;
      if (rolling) q.cross_roll[b.cross[t]] = roll;
    }
    out.contacts += 1.0;
    out.elastic_energy += hertz_energy_from_force(b.cc[t].f_el, b.overlap[t]) + 0.5 * b.cc[t].k_t * norm2(ft.spring);
    out.damping_power += fn.dissipated_power + (ft.slipped ? 0.0 : ft.dissipated_power);
    out.friction_power += (ft.slipped ? ft.dissipated_power : 0.0) - dot(roll, wrel);
    // Divide only for a contact deeper than the deepest so far.
    const double rmin = std::min(q.radius[i], q.radius[j]);
    if (b.overlap[t] > out.deepest.ratio * rmin) out.deepest = {b.overlap[t] / rmin, q.id[i], q.id[j]};
  }
}

void run(const PairPass& q, Batch& b, PairBlockSums& out) {
  geometry(q, b);
  normal_law(q, b);
  tangential_law(q, b);
  apply(q, b, out);
  b.count = 0;
}

}  // namespace

PairBlockSums contact_block(const PairPass& q, std::size_t lo, std::size_t hi, std::size_t cross_first) {
  PairBlockSums out;
  Batch b;
  const std::size_t end = PairBlocks::block_end(lo, q.n);
  std::uint32_t c = static_cast<std::uint32_t>(cross_first);  // next cross index
  for (std::size_t i = lo; i < hi; ++i) {
    const Vec3 xi = q.x[i];
    const double ri = q.radius[i];
    for (std::size_t k = q.off[i]; k < q.off[i + 1]; ++k) {
      const std::uint32_t j = q.idx[k];
      const bool internal = j < end;
      const std::uint32_t cross = internal ? kInternal : c;
      if (!internal) {  // results default to zero (the batch overwrites touching ones)
        q.cross_force[c] = q.cross_arm[c] = Vec3{};
        if (q.cross_roll) q.cross_roll[c] = Vec3{};
        ++c;
      }
      // Candidates by squared distance, with a margin that leaves the exact decision
      // (overlap > 0) to stage 1. Branch-free: every slot is written, the count advances only
      // for a candidate. A commit forgets the history of the others (x 0).
      const double reach = ri + q.radius[j];
      const bool cand = norm2(xi - q.x[j]) <= reach * reach * (1.0 + 1e-9);
      b.i[b.count] = static_cast<std::uint32_t>(i);
      b.j[b.count] = j;
      b.slot[b.count] = k;
      b.cross[b.count] = cross;
      b.count += cand;
      if (q.commit) {
        const double keep = cand ? 1.0 : 0.0;
        q.spring[k] *= keep;
        if (q.vt0) q.vt0[k] *= keep;
        if (q.wr0) q.wr0[k] *= keep;
      }
      if (b.count == kBatch) run(q, b, out);
    }
  }
  if (b.count > 0) run(q, b, out);
  return out;
}

}  // namespace mpdem
