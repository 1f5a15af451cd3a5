#include "sim/pair_batch.hpp"

#include <algorithm>
#include <cmath>

#include "neighbor/pair_blocks.hpp"
#include "physics/contact_coefficients.hpp"
#include "physics/hertz.hpp"
#include "physics/rolling.hpp"
#include "physics/tangential.hpp"

// GCC vectorises the indexed loads of the gather stages into element-by-element gathers,
// slower than plain loads; other compilers get no attribute.
#if defined(__GNUC__) && !defined(__clang__)
#define MPDEM_SCALAR_LOOPS __attribute__((optimize("no-tree-vectorize")))
#else
#define MPDEM_SCALAR_LOOPS
#endif

namespace mpdem {

namespace {

constexpr std::size_t kBatch = 64;                  // candidate pairs per batch
constexpr std::uint32_t kInternal = 0xffffffffu;    // "no cross index"

// One batch: the candidates, then each stage's results, structure-of-arrays so that the stage
// loops vectorise.
struct Batch {
  std::size_t count = 0;
  std::uint32_t i[kBatch], j[kBatch];  // members
  std::size_t slot[kBatch];            // pair slot
  std::uint32_t cross[kBatch];         // cross index, or kInternal
  // Stage 1a: the members' values, combined where the laws only need the combination.
  double dx[kBatch], dy[kBatch], dz[kBatch];     // m, x_i - x_j
  double dvx[kBatch], dvy[kBatch], dvz[kBatch];  // m/s, v_i - v_j
  double wsx[kBatch], wsy[kBatch], wsz[kBatch];  // m/s, R_i w_i + R_j w_j
  double reach[kBatch];                          // m, R_i + R_j
  double sc[kBatch], ss[kBatch], sr[kBatch], sm[kBatch];  // 1/Pa, 1/Pa, 1/m, 1/kg: sums of ContactTerms
  // Stage 1: geometry and kinematics.
  double overlap[kBatch];              // m, 0 when apart
  double nx[kBatch], ny[kBatch], nz[kBatch];     // -, n_ij, from j to i
  double vtx[kBatch], vty[kBatch], vtz[kBatch];  // m/s, tangential relative velocity (61)
  double vn[kBatch];                   // m/s, normal rate
  double E[kBatch], G[kBatch], r[kBatch], m[kBatch];  // Pa, Pa, m, kg (51)-(53), Mindlin G*
  // Stage 2: normal law.
  double f_el[kBatch];                 // N, elastic Hertz force
  double fn[kBatch];                   // N, net normal force (clamped at 0)
  double pn[kBatch];                   // W, normal damping power
  double kt[kBatch], dtc[kBatch];      // N/m, N s/m
  // Stage 3a: history.
  double s0x[kBatch], s0y[kBatch], s0z[kBatch];  // m, stored spring
  double dsx[kBatch], dsy[kBatch], dsz[kBatch];  // m, increment (64)
  SlipDecision decide[kBatch];
  // Stage 3: tangential law.
  double ftx[kBatch], fty[kBatch], ftz[kBatch];  // N, tangential force on i
  double sx[kBatch], sy[kBatch], sz[kBatch];     // m, spring for the next step
  double pt[kBatch];                   // W, tangential dissipation
  std::uint8_t slip[kBatch];           // 1 when sliding
  // Stage 4a: results.
  double fx[kBatch], fy[kBatch], fz[kBatch];     // N, force on i
  double ax[kBatch], ay[kBatch], az[kBatch];     // N, n x f_t
  double energy[kBatch];               // J, elastic energy of the contact
  double damping[kBatch];              // W, dashpot power
  double friction[kBatch];             // W, sliding power
  Vec3 normal(std::size_t t) const { return {nx[t], ny[t], nz[t]}; }
  Vec3 vt(std::size_t t) const { return {vtx[t], vty[t], vtz[t]}; }
};

// Stage 1a: the members' values for the batch (indexed loads). Kept scalar: vectorised, the
// compiler emulates the gathers element by element, which is slower than plain loads.
MPDEM_SCALAR_LOOPS void gather_members(const PairPass& q, Batch& b) {
  const std::size_t count = b.count;
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t i = b.i[t], j = b.j[t];
    const double ri = q.radius[i], rj = q.radius[j];
    const Vec3 dv = q.v[i] - q.v[j], ws = ri * q.w[i] + rj * q.w[j];  // (x_i - x_j, R_i + R_j: pass 0)
    b.dvx[t] = dv.x, b.dvy[t] = dv.y, b.dvz[t] = dv.z;
    b.wsx[t] = ws.x, b.wsy[t] = ws.y, b.wsz[t] = ws.z;
    const ContactTerms& ti = q.terms[i];
    const ContactTerms& tj = q.terms[j];
    b.sc[t] = ti.compliance + tj.compliance;
    b.ss[t] = ti.shear_compliance + tj.shear_compliance;
    b.sr[t] = ti.inv_radius + tj.inv_radius;
    b.sm[t] = ti.inv_mass + tj.inv_mass;
  }
}

// Stage 1 (60)-(62): overlap, normal, relative velocity at the contact point.
void geometry(const PairPass& q, Batch& b) {
  const std::size_t count = b.count;
  gather_members(q, b);
  // 1b. The arithmetic, over contiguous arrays (vectorised).
  for (std::size_t t = 0; t < count; ++t) {
    const Vec3 d{b.dx[t], b.dy[t], b.dz[t]};
    const double dist = std::sqrt(norm2(d));
    const double ov = b.reach[t] - dist;
    b.overlap[t] = ov > 0.0 ? ov : 0.0;
    // Coincident centres get +z, so nothing becomes NaN.
    const double inv = 1.0 / (dist > 0.0 ? dist : 1.0);
    const Vec3 nrm = dist > 0.0 ? d * inv : Vec3{0.0, 0.0, 1.0};
    b.nx[t] = nrm.x;
    b.ny[t] = nrm.y;
    b.nz[t] = nrm.z;
    b.E[t] = 1.0 / b.sc[t];  // (51)
    b.G[t] = 1.0 / b.ss[t];  // Mindlin G*
    b.r[t] = 1.0 / b.sr[t];  // (52)
    b.m[t] = 1.0 / b.sm[t];  // (53)
    // (60) with the arms r_Pi = -R_i n, r_Pj = R_j n (62).
    const Vec3 vrel = Vec3{b.dvx[t], b.dvy[t], b.dvz[t]} - cross(Vec3{b.wsx[t], b.wsy[t], b.wsz[t]}, nrm);
    const double vn = dot(vrel, nrm);
    const Vec3 vt = vrel - vn * nrm;  // (61)
    b.vn[t] = vn;
    b.vtx[t] = vt.x;
    b.vty[t] = vt.y;
    b.vtz[t] = vt.z;
  }
}

// Stage 2 (49)-(50), (65), (67); an apart candidate (overlap 0) gets zero coefficients.
void normal_law(const PairPass& q, Batch& b) {
  const double xi_n = q.law.xi_n, xi_t = q.law.xi_t;
  for (std::size_t t = 0; t < b.count; ++t) {
    const ContactCoefficients cc = contact_coefficients(b.E[t], b.G[t], b.r[t], b.m[t], xi_n, xi_t, b.overlap[t]);
    const NormalForce fn = damped_normal_force(cc.f_el, cc.d_n, b.vn[t]);
    b.f_el[t] = cc.f_el;
    b.fn[t] = fn.magnitude;
    b.pn[t] = fn.dissipated_power;
    b.kt[t] = cc.k_t;
    b.dtc[t] = cc.d_t;
  }
}

// Stage 3 (57)-(70): the stored spring on the current tangent plane plus the trapezoidal
// increment (64) (Verlet: phi = 1), Coulomb stick or slip.
// Stage 3a: each slot's stored spring, the increment (64) and the imposed stick/slip decision
// (indexed loads, scalar like gather_members), so that the law's loop has no branch.
MPDEM_SCALAR_LOOPS void gather_history(const PairPass& q, Batch& b) {
  const double dt = q.dt, phi = q.phi;
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t k = b.slot[t];
    const Vec3 ds = q.vt0 ? dt * ((1.0 - phi) * q.vt0[k] + phi * b.vt(t)) : (dt * phi) * b.vt(t);
    b.dsx[t] = ds.x, b.dsy[t] = ds.y, b.dsz[t] = ds.z;
    const Vec3 s0 = q.spring[k];
    b.s0x[t] = s0.x, b.s0y[t] = s0.y, b.s0z[t] = s0.z;
    b.decide[t] = q.iteration < 2 ? SlipDecision::Free : q.slipped[k] ? SlipDecision::Slip : SlipDecision::Stick;
  }
}

void tangential_law(const PairPass& q, Batch& b) {
  const double mu_s = q.law.mu_s, mu_d = q.law.mu_d;
  gather_history(q, b);
  for (std::size_t t = 0; t < b.count; ++t) {
    const TangentialResult ft = tangential_force(project_spring({b.s0x[t], b.s0y[t], b.s0z[t]}, b.normal(t)),
                                                 {b.dsx[t], b.dsy[t], b.dsz[t]}, b.vt(t), b.kt[t], b.dtc[t], mu_s,
                                                 mu_d, b.fn[t], b.decide[t]);
    b.ftx[t] = ft.force.x;
    b.fty[t] = ft.force.y;
    b.ftz[t] = ft.force.z;
    b.sx[t] = ft.spring.x;
    b.sy[t] = ft.spring.y;
    b.sz[t] = ft.spring.z;
    b.pt[t] = ft.dissipated_power;
    b.slip[t] = ft.slipped;
  }
}

// Stage 4: history, rolling resistance (71), and the sums, in slot order.
// Stage 4a: each contact's force, torque arm and energy terms (vectorised).
void results(Batch& b) {
  for (std::size_t t = 0; t < b.count; ++t) {
    const Vec3 nrm = b.normal(t);
    const Vec3 ft{b.ftx[t], b.fty[t], b.ftz[t]};
    const Vec3 f = b.fn[t] * nrm + ft;
    const Vec3 arm = cross(nrm, ft);  // torque r_P x f_t = -R n x f_t on both members (62)
    b.fx[t] = f.x, b.fy[t] = f.y, b.fz[t] = f.z;
    b.ax[t] = arm.x, b.ay[t] = arm.y, b.az[t] = arm.z;
    const bool slipped = b.slip[t] != 0;
    b.energy[t] = hertz_energy_from_force(b.f_el[t], b.overlap[t]) + 0.5 * b.kt[t] * (b.sx[t] * b.sx[t] +
                  b.sy[t] * b.sy[t] + b.sz[t] * b.sz[t]);
    b.damping[t] = b.pn[t] + (slipped ? 0.0 : b.pt[t]);
    b.friction[t] = slipped ? b.pt[t] : 0.0;
  }
}

// Stage 4b: history, rolling resistance (71), the forces and the sums, in slot order.
void apply(const PairPass& q, const Batch& b, PairBlockSums& out) {
  const bool rolling = q.law.mu_r > 0.0;
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t i = b.i[t], j = b.j[t], k = b.slot[t];
    if (!(b.overlap[t] > 0.0)) {  // a candidate within the margin but apart: forget its history
      if (q.commit) {
        q.spring[k] = Vec3{};
        if (q.vt0) q.vt0[k] = Vec3{};
        if (q.wr0) q.wr0[k] = Vec3{};
      }
      continue;
    }
    if (q.iteration == 1) q.slipped[k] = b.slip[t];
    // Rolling resistance against the relative rotation of the step start (the state itself
    // outside the iteration): constant during the iteration (docs/contact_model.md).
    Vec3 roll{}, wrel{};
    if (rolling || q.wr0) wrel = q.w[i] - q.w[j];
    if (rolling)
      roll = rolling_resistance_torque(q.iteration > 0 ? q.wr0[k] : wrel, q.law.mu_r, b.r[t], b.fn[t],
                                       rolling_inertia_pair(q.inertia[i], q.inertia[j]), q.dt);
    if (q.commit) {
      q.spring[k] = {b.sx[t], b.sy[t], b.sz[t]};
      if (q.vt0) q.vt0[k] = b.vt(t);
      if (q.wr0) q.wr0[k] = wrel;
    }
    const Vec3 f{b.fx[t], b.fy[t], b.fz[t]};
    const Vec3 arm{b.ax[t], b.ay[t], b.az[t]};
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
    out.elastic_energy += b.energy[t];
    out.damping_power += b.damping[t];
    out.friction_power += b.friction[t] - dot(roll, wrel);
    // Divide only for a contact deeper than the deepest so far.
    const double rmin = std::min(q.radius[i], q.radius[j]);
    if (b.overlap[t] > out.deepest.ratio * rmin) out.deepest = {b.overlap[t] / rmin, q.id[i], q.id[j]};
  }
}

void run(const PairPass& q, Batch& b, PairBlockSums& out) {
  geometry(q, b);
  normal_law(q, b);
  tangential_law(q, b);
  results(b);
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
      const Vec3 d = xi - q.x[j];
      const bool cand = norm2(d) <= reach * reach * (1.0 + 1e-9);
      const std::size_t t = b.count;
      b.i[t] = static_cast<std::uint32_t>(i);
      b.j[t] = j;
      b.slot[t] = k;
      b.cross[t] = cross;
      b.dx[t] = d.x, b.dy[t] = d.y, b.dz[t] = d.z;  // kept for stage 1
      b.reach[t] = reach;
      b.count += cand;
      if (q.commit) {
        // Only a contact that just opened has history to forget: test without a data-dependent
        // branch (about a third of the slots are apart) and store only then (rare).
        const Vec3& s0 = q.spring[k];
        const bool held = (s0.x != 0.0) | (s0.y != 0.0) | (s0.z != 0.0) | (q.vt0 != nullptr) | (q.wr0 != nullptr);
        if (!cand & held) {
          q.spring[k] = Vec3{};
          if (q.vt0) q.vt0[k] = Vec3{};
          if (q.wr0) q.wr0[k] = Vec3{};
        }
      }
      if (b.count == kBatch) run(q, b, out);
    }
  }
  if (b.count > 0) run(q, b, out);
  return out;
}

}  // namespace mpdem
