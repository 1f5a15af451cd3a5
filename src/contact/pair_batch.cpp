#include "contact/pair_batch.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "contact/cohesive_contact.hpp"
#include "contact/contact_law.hpp"
#include "contact/pair_candidates.hpp"
#include "physics/rolling.hpp"

// GCC vectorises the indexed loads of the gather stages into element-by-element gathers,
// slower than plain loads; other compilers get no attribute.
#if defined(__GNUC__) && !defined(__clang__)
#define MPDEM_SCALAR_LOOPS __attribute__((optimize("no-tree-vectorize")))
#else
#define MPDEM_SCALAR_LOOPS
#endif

namespace mpdem {

const bool kVectorSelect = MPDEM_VECTOR_SELECT != 0;

namespace {
using namespace pair_kernel;
constexpr std::size_t kAhead = 32;  // slots ahead to prefetch

// Stage 1a: the members' values for the batch (indexed loads). Kept scalar: vectorised, the
// compiler emulates the gathers element by element, which is slower than plain loads.
// Several materials (!kUniform): each pair's law from the table, by the members' materials.
template <bool kUniform, bool kCohesive = false>
MPDEM_SCALAR_LOOPS void gather_members(const PairPass& pass, Batch& b) {
  // Lanes past count repeat the last candidate (run() is called with count >= 1).
  for (std::size_t t = b.count; t < b.lanes(); ++t) {
    const std::size_t l = b.count - 1;
    b.i[t] = b.i[l], b.j[t] = b.j[l], b.slot[t] = b.slot[l];
    b.dx[t] = b.dx[l], b.dy[t] = b.dy[l], b.dz[t] = b.dz[l], b.reach[t] = b.reach[l];
  }
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const std::size_t i = b.i[t], j = b.j[t];
    const ContactTerms& ti = pass.terms[i];
    const ContactTerms& tj = pass.terms[j];
    const double ri = ti.radius, rj = tj.radius;
    const Vec3 dv = pass.v[i] - pass.v[j], ws = ri * pass.w[i] + rj * pass.w[j];  // (x_i - x_j, R_i + R_j: pass 0)
    b.dvx[t] = dv.x, b.dvy[t] = dv.y, b.dvz[t] = dv.z;
    b.wsx[t] = ws.x, b.wsy[t] = ws.y, b.wsz[t] = ws.z;
    if constexpr (!kUniform) {
      const PairLaw& c = pass.laws[static_cast<std::size_t>(pass.material[i]) * pass.materials + pass.material[j]];
      b.law[t] = c.law, b.spring_form[t] = c.spring;
      for (std::size_t s = 0; s < kCoefficients; ++s) b.coefficients[s][t] = c.c[s];
    }
    b.radius_product[t] = ri * rj;
    b.inverse_mass_sum[t] = ti.inv_mass + tj.inv_mass;
    if constexpr (kCohesive) {
      b.state0[t] = pass.state[b.slot[t]];
      b.bridge[t] = pass.bridges ? pass.bridges + static_cast<std::size_t>(pass.material[i]) * pass.materials +
                                       static_cast<std::size_t>(pass.material[j])
                                 : nullptr;
    }
  }
}

// Stage 2a: each slot's stored spring and (kStepStart: the trapezoidal rule) its step-start
// tangential velocity and imposed stick/slip decision (indexed loads, scalar like gather_members).
template <bool kStepStart>
MPDEM_SCALAR_LOOPS void gather_history(const PairPass& pass, Batch& b) {
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const std::size_t k = b.slot[t];
    const Vec3 s0 = pass.spring[k];
    b.s0x[t] = s0.x, b.s0y[t] = s0.y, b.s0z[t] = s0.z;
    if constexpr (kStepStart) {
      const Vec3 v0 = pass.vt0[k];
      b.v0x[t] = v0.x, b.v0y[t] = v0.y, b.v0z[t] = v0.z;
      b.decide[t] = pass.iteration < 2 ? SlipDecision::Free
                    : pass.slipped[k]  ? SlipDecision::Slip
                                       : SlipDecision::Stick;
    }
  }
}

// Stage 1: geometry and kinematics (60)-(62) and the normal half of the law (normal_contact,
// contact_law.hpp), over contiguous arrays (vectorised; an apart candidate, overlap 0, gets finite
// values that apply() skips). One loop: the intermediate values stay in registers.
// kCohesive (PairPass::state): the overlap keeps its sign (negative: a gap), and the law and a
// liquid bridge act by the contact's formed state (contact/cohesive_contact.hpp), which records
// what acts now and what broke with the energy it held; scalar, the bridges read through the table.
template <bool kUniform, class Law, bool kCohesive = false, bool kEnergy = true>
void geometry_normal(const PairPass& pass, Batch& b) {
  gather_members<kUniform, kCohesive>(pass, b);
  const PairLaw u = pass.uniform_law;
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const Vec3 d{b.dx[t], b.dy[t], b.dz[t]};
    const double dist = std::sqrt(norm2(d));
    const double ov = b.reach[t] - dist;
    // Coincident centres get +z, so nothing becomes NaN.
    const double inv = 1.0 / (dist > 0.0 ? dist : 1.0);
    const Vec3 nrm = dist > 0.0 ? d * inv : Vec3{0.0, 0.0, 1.0};
    // r* = R_i R_j / (R_i + R_j) (52) and m* = 1 / sm (53) from one division.
    const double inv_rm = 1.0 / (b.reach[t] * b.inverse_mass_sum[t]);
    const double r = b.radius_product[t] * b.inverse_mass_sum[t] * inv_rm, m = b.reach[t] * inv_rm;
    // (61) with the arms r_Pi = -R_i n, r_Pj = R_j n (62).
    const Vec3 vrel = Vec3{b.dvx[t], b.dvy[t], b.dvz[t]} - cross(Vec3{b.wsx[t], b.wsy[t], b.wsz[t]}, nrm);
    const double vn = dot(vrel, nrm);
    const Vec3 vt = vrel - vn * nrm;                                                     // (60)
    const double inv_reach = kCohesive || Law::kExactGeometry ? 1.0 / b.reach[t] : 0.0;  // 1/m (SJKR's lens)
    NormalContact n;
    if constexpr (kCohesive) {
      const CohesiveNormal cn = cohesive_normal<Law>(b.pair_law(t), b.bridge[t], b.state0[t], r, m, ov, vn, inv_reach);
      n = cn.n;
      b.live[t] = cn.live, b.next[t] = cn.next, b.broke[t] = cn.broke;
      b.loss[t] = cn.loss;
      b.overlap[t] = ov;
    } else {
      const double overlap = ov > 0.0 ? ov : 0.0;
      n = normal_contact<Law>(kUniform ? u : b.pair_law(t), r, m, overlap, vn, inv_reach);
      b.overlap[t] = overlap;
    }
    b.nx[t] = nrm.x, b.ny[t] = nrm.y, b.nz[t] = nrm.z;
    b.vtx[t] = vt.x, b.vty[t] = vt.y, b.vtz[t] = vt.z;
    b.r_star[t] = r;
    b.fn_net[t] = n.fn, b.fn_load[t] = n.fn_limit;
    b.tangential_stiffness[t] = n.k_t, b.tangential_damping[t] = n.d_t;
    if constexpr (kEnergy) b.normal_energy[t] = n.energy, b.normal_damping[t] = n.damping;
  }
}

// Stage 2: the tangential half of the law (tangential_contact) with the spring increment (64)
// (Verlet: phi = 1), and the contact's force, torque arm and energy terms (vectorised).
template <bool kUniform, bool kStepStart, bool kCohesive = false, bool kEnergy = true>
void tangential_stage(const PairPass& pass, Batch& b) {
  gather_history<kStepStart>(pass, b);
  const double dt = pass.dt, phi = pass.phi, dt_phi = pass.dt * pass.phi;
  const double mu_s_u = pass.uniform_law.mu_s(), mu_d_u = pass.uniform_law.mu_d();
  const TangentialSpring form_u = pass.uniform_law.spring;
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const Vec3 nrm = b.normal(t), vt = b.vt(t);
    Vec3 increment;
    SlipDecision decide = SlipDecision::Free;
    if constexpr (kStepStart) {
      increment = dt * ((1.0 - phi) * Vec3{b.v0x[t], b.v0y[t], b.v0z[t]} + phi * vt);
      decide = b.decide[t];
    } else {
      increment = dt_phi * vt;
    }
    NormalContact n;
    n.fn = b.fn_net[t], n.fn_limit = b.fn_load[t];
    n.k_t = b.tangential_stiffness[t], n.d_t = b.tangential_damping[t];
    if constexpr (kEnergy) n.energy = b.normal_energy[t], n.damping = b.normal_damping[t];
    ContactResult r = tangential_contact(
        kUniform ? mu_s_u : b.coefficients[kMuS][t], kUniform ? mu_d_u : b.coefficients[kMuD][t],
        kUniform ? form_u : b.spring_form[t], n, {b.s0x[t], b.s0y[t], b.s0z[t]}, nrm, increment, vt, decide);
    if constexpr (kCohesive) {
      // A bridge alone (the law apart) pulls along the normal only: no spring, no friction.
      if ((b.live[t] & kLawFormed) == 0) without_contact(r, n);
    }
    b.sx[t] = r.spring.x, b.sy[t] = r.spring.y, b.sz[t] = r.spring.z;
    b.slip[t] = r.slipped ? 1 : 0;
    const Vec3 f = r.fn * nrm + r.ft;
    const Vec3 arm = cross(nrm, r.ft);  // torque r_P x f_t = -R n x f_t on both members (62)
    b.fx[t] = f.x, b.fy[t] = f.y, b.fz[t] = f.z;
    b.ax[t] = arm.x, b.ay[t] = arm.y, b.az[t] = arm.z;
    if constexpr (kEnergy) {
      b.energy[t] = r.energy;
      b.damping[t] = r.damping;
      b.spring_energy_before[t] = r.spring_energy_before;
      b.spring_energy_after[t] = r.spring_energy;
      b.tangential_loss[t] = r.tangential_loss;
    }
  }
}

// Stage 3: history, rolling resistance (71), the forces and the sums, in slot order.
// The sums and the arrays' addresses are local: kept in out and pass, every store to a particle
// would make the compiler reload them, and each contact's sums would wait for the previous
// contact's store (a store-to-load chain through memory).
template <bool kUniform, bool kCohesive = false, bool kEnergy = true>
void apply(const PairPass& pass, const Batch& b, PairBlockSums& out) {
  const bool rolling = pass.rolling, commit = pass.commit, first_iteration = pass.iteration == 1;
  const double uniform_mu_r = pass.uniform_law.mu_r();
  const Vec3* const w = pass.w;
  const ContactTerms* const terms = pass.terms;
  Vec3* const force = pass.force;
  Vec3* const torque = pass.torque;
  Vec3* const cross_force = pass.cross_force;
  Vec3* const cross_torque = pass.cross_torque;
  Vec3* const spring = pass.spring;
  Vec3* const vt0 = pass.vt0;
  Vec3* const wr0 = pass.wr0;
  PairBlockSums s = out;
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t i = b.i[t], j = b.j[t], k = b.slot[t];
    if constexpr (kCohesive) {
      if (commit) {
        // What held and broke now: its energy is dissipated (the force drops to zero).
        s.breaks += (b.broke[t] & kLawFormed) != 0 ? 1.0 : 0.0;
        s.ruptures += (b.broke[t] & kBridgeFormed) != 0 ? 1.0 : 0.0;
        s.cohesion_loss += b.loss[t];
        pass.state[k] = b.next[t];
      }
      s.bridges += (b.live[t] & kBridgeFormed) != 0 ? 1.0 : 0.0;
      if (b.live[t] == 0) {
        if (commit) forget_history(pass, k);
        continue;
      }
    } else if (!(b.overlap[t] > 0.0)) {  // a candidate within the margin but apart: forget its history
      if (commit) forget_history(pass, k);
      continue;
    }
    if (first_iteration) pass.slipped[k] = static_cast<std::uint8_t>(b.slip[t]);
    // Rolling resistance against the relative rotation of the step start (the state itself
    // outside the iteration): constant during the iteration (docs/integrators.md).
    Vec3 roll{}, wrel{};
    if (rolling || wr0) wrel = w[i] - w[j];
    if (rolling)
      roll = rolling_resistance_torque(pass.iteration > 0 ? wr0[k] : wrel,
                                       kUniform ? uniform_mu_r : b.coefficients[kMuR][t], b.r_star[t], b.fn_load[t],
                                       rolling_inertia_pair(pass.inertia[i], pass.inertia[j]), pass.dt);
    if (commit) {
      spring[k] = {b.sx[t], b.sy[t], b.sz[t]};
      if (vt0) vt0[k] = b.vt(t);
      if (wr0) wr0[k] = wrel;
    }
    const Vec3 f{b.fx[t], b.fy[t], b.fz[t]};
    const Vec3 arm{b.ax[t], b.ay[t], b.az[t]};
    const double ri = terms[i].radius, rj = terms[j].radius;
    force[i] += f;
    torque[i] += roll - ri * arm;
    // j's share: to j itself, or (cross pair, j in a later block) to the zeroed cross buffer.
    const bool internal = b.cross[t] == kInternal;
    Vec3* fj = (internal ? force : cross_force) + (internal ? j : b.cross[t]);
    Vec3* tj = (internal ? torque : cross_torque) + (internal ? j : b.cross[t]);
    *fj -= f;
    *tj -= roll + rj * arm;
    s.contacts += kCohesive ? ((b.live[t] & kLawFormed) != 0 ? 1.0 : 0.0) : 1.0;
    if constexpr (kEnergy) {
      s.elastic_energy += b.energy[t];
      if constexpr (kCohesive) s.elastic_magnitude += std::abs(b.energy[t]);
      s.damping_power += b.damping[t];
      s.rolling_power -= dot(roll, wrel);
      // Selected values, not a selected address: that would keep the sums in memory.
      const bool slid = b.slip[t] != 0;
      s.sliding_loss += slid ? b.tangential_loss[t] : 0.0;
      s.sticking_loss += slid ? 0.0 : b.tangential_loss[t];
      s.spring_before += b.spring_energy_before[t];
      s.spring_after += b.spring_energy_after[t];
    }
    // Divide only for a contact deeper than the deepest so far.
    const double rmin = std::min(ri, rj);
    if (b.overlap[t] > s.deepest.ratio * rmin) s.deepest = {b.overlap[t] / rmin, pass.id[i], pass.id[j]};
  }
  out = s;
}

// Recording (PairPass::record): each touching slot's contact, from the batch's results, in a loop
// of its own so that apply's loop is the same with recording off.
template <bool kCohesive>
void record_batch(const PairPass& pass, const Batch& b) {
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::uint32_t live = kCohesive ? b.live[t] : (b.overlap[t] > 0.0 ? kLawFormed : 0u);
    if (live != 0)
      pass.record[b.slot[t]] = {Vec3{b.fx[t], b.fy[t], b.fz[t]},       b.normal(t), b.overlap[t], b.fn_net[t],
                                static_cast<std::uint32_t>(b.slip[t]), live};
  }
}

template <bool kUniform, class Law, bool kStepStart, bool kCohesive, bool kEnergy>
void run(const PairPass& pass, Batch& b, PairBlockSums& out) {
  geometry_normal<kUniform, Law, kCohesive, kEnergy>(pass, b);
  tangential_stage<kUniform, kStepStart, kCohesive, kEnergy>(pass, b);
  apply<kUniform, kCohesive, kEnergy>(pass, b, out);
  if (pass.record) record_batch<kCohesive>(pass, b);
  b.count = 0;
}

template <bool kUniform, class Law, bool kStepStart, bool kCohesive = false, bool kEnergy = true>
PairBlockSums evaluate_block(const PairPass& pass, std::size_t lo, std::size_t hi, std::size_t cross_first,
                             std::size_t cross_last) {
  PairBlockSums out;
  Batch b;
  const auto end = static_cast<std::uint32_t>(hi);  // [lo, hi) is one whole block: j >= hi is a cross pair
  // Cross shares default to zero (contacts add to them).
  std::fill(pass.cross_force + cross_first, pass.cross_force + cross_last, Vec3{});
  std::fill(pass.cross_torque + cross_first, pass.cross_torque + cross_last, Vec3{});
  std::uint32_t c = static_cast<std::uint32_t>(cross_first);  // next cross index
  // The block's slots in groups, in slot order; a batch runs when the next group might not fit.
  const std::size_t k1 = pass.off[hi];
  for (std::size_t k = pass.off[lo]; k < k1; k += kGroup) {
    // The neighbours' data are indirect loads the hardware cannot foresee: fetch them ahead.
    for (std::size_t a = k + kAhead; a < std::min(k + kAhead + kGroup, pass.pairs); ++a) {
      const std::uint32_t ja = pass.idx[a];
      __builtin_prefetch(&pass.x[ja]);
      __builtin_prefetch(&pass.v[ja]);
      __builtin_prefetch(&pass.w[ja]);
      __builtin_prefetch(&pass.terms[ja]);
    }
    // The slots' springs (read for every slot at a commit) are a sequential stream the hardware
    // prefetcher does not keep ahead of.
    // So are the slots' first members (the prefetch loop above reads the second ones).
    if (k + kAhead + kGroup <= pass.pairs) {
      const char* sp = reinterpret_cast<const char*>(pass.spring + k + kAhead);
      __builtin_prefetch(sp);
      __builtin_prefetch(sp + 64);
      __builtin_prefetch(sp + 128);
      __builtin_prefetch(pass.first + k + kAhead);
      if constexpr (kStepStart) {  // and so is the trapezoidal rule's step-start tangential velocity
        const char* vp = reinterpret_cast<const char*>(pass.vt0 + k + kAhead);
        __builtin_prefetch(vp);
        __builtin_prefetch(vp + 64);
        __builtin_prefetch(vp + 128);
      }
    }
    // The first members' data and sums too (their index rises slowly: one group covers them).
    if (k + kAhead / 2 < k1) {
      const std::uint32_t ia = pass.first[k + kAhead / 2];
      __builtin_prefetch(&pass.x[ia]);
      __builtin_prefetch(&pass.v[ia]);
      __builtin_prefetch(&pass.w[ia]);
      __builtin_prefetch(&pass.terms[ia]);
      __builtin_prefetch(&pass.force[ia], 1);
      __builtin_prefetch(&pass.torque[ia], 1);
    }
    if (k + 4 * kAhead < pass.pairs) __builtin_prefetch(pass.idx + k + 4 * kAhead);
    const std::size_t cnt = std::min(kGroup, k1 - k);
    if constexpr (kCohesive) {
      select_scalar<true>(pass, b, k, cnt, end, c);
    } else {
#if MPDEM_VECTOR_SELECT
      if (pass.vector_select) select_vector(pass, b, k, cnt, end, c);
      else select_scalar(pass, b, k, cnt, end, c);
#else
      select_scalar(pass, b, k, cnt, end, c);
#endif
    }
    if (b.count + kGroup > kBatch) run<kUniform, Law, kStepStart, kCohesive, kEnergy>(pass, b, out);
  }
  if (b.count > 0) run<kUniform, Law, kStepStart, kCohesive, kEnergy>(pass, b, out);
  return out;
}

// One instantiation per law mix, material count (one or several) and integrator history. One
// material has one law: no mix then. Cohesion: the table's path (several materials) for any count.
template <class Law>
PairBlockSums block_for_law(const PairPass& pass, std::size_t lo, std::size_t hi, std::size_t c0, std::size_t c1) {
  const bool step_start = pass.vt0 != nullptr;
  if (pass.state)
    return step_start ? evaluate_block<false, Law, true, true>(pass, lo, hi, c0, c1)
                      : evaluate_block<false, Law, false, true>(pass, lo, hi, c0, c1);
  // Without energies (PairPass::energies): the evaluations whose energies nobody reads.
  const auto block = [&]<bool kUniform, bool kStepStart>() {
    return pass.energies ? evaluate_block<kUniform, Law, kStepStart>(pass, lo, hi, c0, c1)
                         : evaluate_block<kUniform, Law, kStepStart, false, false>(pass, lo, hi, c0, c1);
  };
  if constexpr (!std::is_same_v<Law, MixedLaw>) {
    if (pass.uniform)
      return step_start ? block.template operator()<true, true>() : block.template operator()<true, false>();
  }
  return step_start ? block.template operator()<false, true>() : block.template operator()<false, false>();
}

}  // namespace

PairBlockSums contact_block(const PairPass& pass, std::size_t lo, std::size_t hi, std::size_t cross_first,
                            std::size_t cross_last) {
  return with_laws(
      pass.uniform ? LawSet{1} << pass.uniform_law.law : pass.laws_used,
      [&]<class Law>(std::type_identity<Law>) { return block_for_law<Law>(pass, lo, hi, cross_first, cross_last); });
}

}  // namespace mpdem
