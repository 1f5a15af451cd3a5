#include "contact/pair_batch.hpp"

#include <algorithm>
#include <bit>
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

// Candidate selection with AVX-512 (8 slots per instruction) when the build targets it.
#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512DQ__) && defined(__BMI2__)
#define MPDEM_VECTOR_SELECT 1
#include <immintrin.h>
#else
#define MPDEM_VECTOR_SELECT 0
#endif

namespace mpdem {

const bool kVectorSelect = MPDEM_VECTOR_SELECT != 0;

namespace {
constexpr std::size_t kBatch = 128;                 // candidate pairs per batch
constexpr std::size_t kGroup = 8;                   // slots selected at a time
constexpr std::size_t kLanes = 8;                   // doubles per vector (AVX-512); kBatch is a multiple
constexpr std::size_t kAhead = 32;                  // slots ahead to prefetch
constexpr std::uint32_t kInternal = 0xffffffffu;    // "no cross index"
static_assert(kBatch % kLanes == 0 && kBatch >= kGroup, "batches hold whole vectors and groups");

// One batch: the candidates, then each stage's results, structure-of-arrays so that the stage
// loops vectorise.
struct Batch {
  std::size_t count = 0;
  std::uint32_t i[kBatch], j[kBatch];  // members
  std::uint32_t slot[kBatch];          // pair slot
  std::uint32_t cross[kBatch];         // cross index, or kInternal
  // Stage 1a: the members' values, combined where the laws only need the combination.
  double dx[kBatch], dy[kBatch], dz[kBatch];     // m, x_i - x_j
  double dvx[kBatch], dvy[kBatch], dvz[kBatch];  // m/s, v_i - v_j
  double wsx[kBatch], wsy[kBatch], wsz[kBatch];  // m/s, R_i w_i + R_j w_j
  double reach[kBatch];                          // m, R_i + R_j
  double sc[kBatch], ss[kBatch];                 // 1/Pa: sums of the members' ContactCompliance
  double rr[kBatch], sm[kBatch];                 // m^2, 1/kg: R_i R_j, 1/m_i + 1/m_j
  // Stage 1: geometry and kinematics.
  double overlap[kBatch];              // m, 0 when apart
  double nx[kBatch], ny[kBatch], nz[kBatch];     // -, n_ij, from j to i
  double vtx[kBatch], vty[kBatch], vtz[kBatch];  // m/s, tangential relative velocity (61)
  double r[kBatch];                    // m, r* (52)
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
  double sx[kBatch], sy[kBatch], sz[kBatch];     // m, spring for the next step
  std::int64_t slip[kBatch];           // 1 when sliding (8 bytes, like SlipDecision)
  // Stage 4a: results.
  double fx[kBatch], fy[kBatch], fz[kBatch];     // N, force on i
  double ax[kBatch], ay[kBatch], az[kBatch];     // N, n x f_t
  double energy[kBatch];               // J, elastic energy of the contact
  double damping[kBatch];              // W, dashpot power
  double friction[kBatch];             // W, sliding power
  // The vector stages run over whole vectors: the lanes past count repeat the last candidate
  // (gather_members, gather_history), so they compute finite values nobody reads.
  std::size_t lanes() const { return (count + kLanes - 1) / kLanes * kLanes; }
  Vec3 normal(std::size_t t) const { return {nx[t], ny[t], nz[t]}; }
  Vec3 vt(std::size_t t) const { return {vtx[t], vty[t], vtz[t]}; }
};

// A commit forgets the history of slot k, whose pair is apart.
void forget_history(const PairPass& q, std::size_t k) {
  q.spring[k] = Vec3{};
  if (q.vt0) q.vt0[k] = Vec3{};
  if (q.wr0) q.wr0[k] = Vec3{};
}

// Stage 1a: the members' values for the batch (indexed loads). Kept scalar: vectorised, the
// compiler emulates the gathers element by element, which is slower than plain loads.
// kUniform (every particle has the same elastic constants): E* and G* are constants, not sums.
template <bool kUniform>
MPDEM_SCALAR_LOOPS void gather_members(const PairPass& q, Batch& b) {
  // Lanes past count repeat the last candidate (run() is called with count >= 1).
  for (std::size_t t = b.count; t < b.lanes(); ++t) {
    const std::size_t l = b.count - 1;
    b.i[t] = b.i[l], b.j[t] = b.j[l], b.slot[t] = b.slot[l];
    b.dx[t] = b.dx[l], b.dy[t] = b.dy[l], b.dz[t] = b.dz[l], b.reach[t] = b.reach[l];
  }
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const std::size_t i = b.i[t], j = b.j[t];
    const ContactTerms& ti = q.terms[i];
    const ContactTerms& tj = q.terms[j];
    const double ri = ti.radius, rj = tj.radius;
    const Vec3 dv = q.v[i] - q.v[j], ws = ri * q.w[i] + rj * q.w[j];  // (x_i - x_j, R_i + R_j: pass 0)
    b.dvx[t] = dv.x, b.dvy[t] = dv.y, b.dvz[t] = dv.z;
    b.wsx[t] = ws.x, b.wsy[t] = ws.y, b.wsz[t] = ws.z;
    if constexpr (!kUniform) {
      b.sc[t] = q.compliance[i].normal + q.compliance[j].normal;
      b.ss[t] = q.compliance[i].shear + q.compliance[j].shear;
    }
    b.rr[t] = ri * rj;
    b.sm[t] = ti.inv_mass + tj.inv_mass;
  }
}

// Stage 1 (60)-(62): overlap, normal, relative velocity at the contact point; and the normal
// law (49)-(50), (65), (67) (an apart candidate, overlap 0, gets zero coefficients). One loop:
// the intermediate values stay in registers.
template <bool kUniform>
void geometry_normal(const PairPass& q, Batch& b) {
  const double xi_n = q.law.xi_n, xi_t = q.law.xi_t;
  const UniformModuli u = q.uniform;
  gather_members<kUniform>(q, b);
  // 1b. The arithmetic, over contiguous arrays (vectorised).
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const Vec3 d{b.dx[t], b.dy[t], b.dz[t]};
    const double dist = std::sqrt(norm2(d));
    const double reach = b.reach[t];
    const double ov = reach - dist;
    b.overlap[t] = ov > 0.0 ? ov : 0.0;
    // Coincident centres get +z, so nothing becomes NaN.
    const double inv = 1.0 / (dist > 0.0 ? dist : 1.0);
    const Vec3 nrm = dist > 0.0 ? d * inv : Vec3{0.0, 0.0, 1.0};
    b.nx[t] = nrm.x;
    b.ny[t] = nrm.y;
    b.nz[t] = nrm.z;
    // r* = R_i R_j / (R_i + R_j) (52) and m* = 1 / sm (53) from one division.
    const double inv_rm = 1.0 / (reach * b.sm[t]);
    const double r = b.rr[t] * b.sm[t] * inv_rm, m = reach * inv_rm;
    b.r[t] = r;
    // (60) with the arms r_Pi = -R_i n, r_Pj = R_j n (62).
    const Vec3 vrel = Vec3{b.dvx[t], b.dvy[t], b.dvz[t]} - cross(Vec3{b.wsx[t], b.wsy[t], b.wsz[t]}, nrm);
    const double vn = dot(vrel, nrm);
    const Vec3 vt = vrel - vn * nrm;  // (61)
    b.vtx[t] = vt.x;
    b.vty[t] = vt.y;
    b.vtz[t] = vt.z;
    const ContactCoefficients cc =
        kUniform ? contact_coefficients_fixed_moduli(u.E_star, u.G_star, u.shear_root, r, m, xi_n, xi_t, b.overlap[t])
                 : contact_coefficients(1.0 / b.sc[t], 1.0 / b.ss[t], r, m, xi_n, xi_t, b.overlap[t]);  // (51), G*
    const NormalForce fn = damped_normal_force(cc.f_el, cc.d_n, vn);
    b.f_el[t] = cc.f_el;
    b.fn[t] = fn.magnitude;
    b.pn[t] = fn.dissipated_power;
    b.kt[t] = cc.k_t;
    b.dtc[t] = cc.d_t;
  }
}

// Stage 3 (57)-(70): the stored spring on the current tangent plane plus the trapezoidal
// increment (64) (Verlet: phi = 1), Coulomb stick or slip.
// Stage 3a: each slot's stored spring, and (kFull) the increment (64) and the imposed stick/slip
// decision (indexed loads, scalar like gather_members), so that the law's loop has no branch.
// Without step-start velocities and before the second iteration (velocity Verlet, and the
// trapezoidal rule's first evaluations) the increment is dt phi v_t and the decision free: the
// law's loop forms them itself (!kFull), with the same arithmetic.
template <bool kFull>
MPDEM_SCALAR_LOOPS void gather_history(const PairPass& q, Batch& b) {
  const double dt = q.dt, phi = q.phi;
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const std::size_t k = b.slot[t];
    const Vec3 s0 = q.spring[k];
    b.s0x[t] = s0.x, b.s0y[t] = s0.y, b.s0z[t] = s0.z;
    if constexpr (kFull) {
      const Vec3 ds = q.vt0 ? dt * ((1.0 - phi) * q.vt0[k] + phi * b.vt(t)) : (dt * phi) * b.vt(t);
      b.dsx[t] = ds.x, b.dsy[t] = ds.y, b.dsz[t] = ds.z;
      b.decide[t] = q.iteration < 2 ? SlipDecision::Free : q.slipped[k] ? SlipDecision::Slip : SlipDecision::Stick;
    }
  }
}

template <bool kFull>
void tangential_stage(const PairPass& q, Batch& b) {
  const double mu_s = q.law.mu_s, mu_d = q.law.mu_d, dt_phi = q.dt * q.phi;
  gather_history<kFull>(q, b);
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const Vec3 ds = kFull ? Vec3{b.dsx[t], b.dsy[t], b.dsz[t]} : dt_phi * b.vt(t);
    const SlipDecision decide = kFull ? b.decide[t] : SlipDecision::Free;
    const TangentialResult ft = tangential_force(project_spring({b.s0x[t], b.s0y[t], b.s0z[t]}, b.normal(t)), ds,
                                                 b.vt(t), b.kt[t], b.dtc[t], mu_s, mu_d, b.fn[t], decide);
    b.sx[t] = ft.spring.x;
    b.sy[t] = ft.spring.y;
    b.sz[t] = ft.spring.z;
    b.slip[t] = ft.slipped ? 1 : 0;
    // Stage 4a: the contact's force, torque arm and energy terms.
    const Vec3 nrm = b.normal(t);
    const Vec3 f = b.fn[t] * nrm + ft.force;
    const Vec3 arm = cross(nrm, ft.force);  // torque r_P x f_t = -R n x f_t on both members (62)
    b.fx[t] = f.x, b.fy[t] = f.y, b.fz[t] = f.z;
    b.ax[t] = arm.x, b.ay[t] = arm.y, b.az[t] = arm.z;
    b.energy[t] = hertz_energy_from_force(b.f_el[t], b.overlap[t]) + 0.5 * b.kt[t] * (ft.spring.x * ft.spring.x +
                  ft.spring.y * ft.spring.y + ft.spring.z * ft.spring.z);
    b.damping[t] = b.pn[t] + (ft.slipped ? 0.0 : ft.dissipated_power);
    b.friction[t] = ft.slipped ? ft.dissipated_power : 0.0;
  }
}

void tangential_law(const PairPass& q, Batch& b) {
  if (!q.vt0 && q.iteration < 2)
    tangential_stage<false>(q, b);
  else
    tangential_stage<true>(q, b);
}

// Stage 4b: history, rolling resistance (71), the forces and the sums, in slot order.
// The sums and the arrays' addresses are local: kept in out and q, every store to a particle
// would make the compiler reload them, and each contact's sums would wait for the previous
// contact's store (a store-to-load chain through memory).
void apply(const PairPass& q, const Batch& b, PairBlockSums& out) {
  const bool rolling = q.law.mu_r > 0.0, commit = q.commit, first_iteration = q.iteration == 1;
  const Vec3* const w = q.w;
  const ContactTerms* const terms = q.terms;
  Vec3* const force = q.force;
  Vec3* const torque = q.torque;
  Vec3* const cross_force = q.cross_force;
  Vec3* const cross_torque = q.cross_torque;
  Vec3* const spring = q.spring;
  Vec3* const vt0 = q.vt0;
  Vec3* const wr0 = q.wr0;
  PairBlockSums s = out;
  for (std::size_t t = 0; t < b.count; ++t) {
    const std::size_t i = b.i[t], j = b.j[t], k = b.slot[t];
    if (!(b.overlap[t] > 0.0)) {  // a candidate within the margin but apart: forget its history
      if (commit) forget_history(q, k);
      continue;
    }
    if (first_iteration) q.slipped[k] = static_cast<std::uint8_t>(b.slip[t]);
    // Rolling resistance against the relative rotation of the step start (the state itself
    // outside the iteration): constant during the iteration (docs/contact_model.md).
    Vec3 roll{}, wrel{};
    if (rolling || wr0) wrel = w[i] - w[j];
    if (rolling)
      roll = rolling_resistance_torque(q.iteration > 0 ? wr0[k] : wrel, q.law.mu_r, b.r[t], b.fn[t],
                                       rolling_inertia_pair(q.inertia[i], q.inertia[j]), q.dt);
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
    // j's share: to j itself, or (cross pair, j in a later block) to the zeroed cross buffer
    // (about 9 % of the contacts on the 100k bed, with blocks of 4096 particles).
    const bool internal = b.cross[t] == kInternal;
    Vec3* fj = (internal ? force : cross_force) + (internal ? j : b.cross[t]);
    Vec3* tj = (internal ? torque : cross_torque) + (internal ? j : b.cross[t]);
    *fj -= f;
    *tj -= roll + rj * arm;
    s.contacts += 1.0;
    s.elastic_energy += b.energy[t];
    s.damping_power += b.damping[t];
    s.friction_power += b.friction[t] - dot(roll, wrel);
    // Divide only for a contact deeper than the deepest so far.
    const double rmin = std::min(ri, rj);
    if (b.overlap[t] > s.deepest.ratio * rmin) s.deepest = {b.overlap[t] / rmin, q.id[i], q.id[j]};
  }
  out = s;
}

template <bool kUniform>
void run(const PairPass& q, Batch& b, PairBlockSums& out) {
  geometry_normal<kUniform>(q, b);
  tangential_law(q, b);
  apply(q, b, out);
  b.count = 0;
}

// Pass 0: selects the candidates among slots [k, k + cnt) of one block (cnt <= kGroup) into
// the batch, in slot order, and numbers the cross slots from c on. A candidate is a pair within
// reach up to a relative margin that leaves the exact decision (overlap > 0) to stage 1; a
// commit forgets the history of the other slots. Every slot is written, the count advances only
// for a candidate (no data-dependent branch).
void select_scalar(const PairPass& q, Batch& b, std::size_t k, std::size_t cnt, std::uint32_t end,
                   std::uint32_t& c) {
  for (const std::size_t stop = k + cnt; k < stop; ++k) {
    const std::uint32_t i = q.first[k], j = q.idx[k];
    const bool internal = j < end;
    const std::uint32_t cross = internal ? kInternal : c;
    c += internal ? 0u : 1u;
    const double reach = q.terms[i].radius + q.terms[j].radius;
    const Vec3 d = q.x[i] - q.x[j];
    const bool cand = norm2(d) <= reach * reach * (1.0 + 1e-9);
    const std::size_t t = b.count;
    b.i[t] = i;
    b.j[t] = j;
    b.slot[t] = static_cast<std::uint32_t>(k);
    b.cross[t] = cross;
    b.dx[t] = d.x, b.dy[t] = d.y, b.dz[t] = d.z;  // kept for stage 1
    b.reach[t] = reach;
    b.count += cand;
    if (q.commit) {
      // Only a contact that just opened has history to forget (rare): store only then.
      const Vec3& s0 = q.spring[k];
      const bool held = (s0.x != 0.0) | (s0.y != 0.0) | (s0.z != 0.0) | (q.vt0 != nullptr) | (q.wr0 != nullptr);
      if (!cand & held) forget_history(q, k);
    }
  }
}

#if MPDEM_VECTOR_SELECT
// The same selection, bit for bit, 8 slots at once: gathers of the members' centres and radii,
// the candidates compressed into the batch, the cross numbers by expansion.
void select_vector(const PairPass& q, Batch& b, std::size_t k, std::size_t cnt, std::uint32_t end,
                   std::uint32_t& c) {
  const __mmask8 lanes = static_cast<__mmask8>((1u << cnt) - 1u);
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i iv = _mm256_maskz_loadu_epi32(lanes, q.first + k);
  const __m256i jv = _mm256_maskz_loadu_epi32(lanes, q.idx + k);
  const __m256i i3 = _mm256_add_epi32(iv, _mm256_add_epi32(iv, iv));  // Vec3 = 3 doubles
  const __m256i j3 = _mm256_add_epi32(jv, _mm256_add_epi32(jv, jv));
  const double* xb = &q.x[0].x;
  const __m512d zero = _mm512_setzero_pd();
  const __m512d dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, lanes, i3, xb, 8),
                                   _mm512_mask_i32gather_pd(zero, lanes, j3, xb, 8));
  const __m512d dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, lanes, i3, xb + 1, 8),
                                   _mm512_mask_i32gather_pd(zero, lanes, j3, xb + 1, 8));
  const __m512d dz = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, lanes, i3, xb + 2, 8),
                                   _mm512_mask_i32gather_pd(zero, lanes, j3, xb + 2, 8));
  const double* rb = &q.terms[0].radius;  // ContactTerms = 2 doubles
  const __m512d reach = _mm512_add_pd(_mm512_mask_i32gather_pd(zero, lanes, _mm256_slli_epi32(iv, 1), rb, 8),
                                      _mm512_mask_i32gather_pd(zero, lanes, _mm256_slli_epi32(jv, 1), rb, 8));
  // norm2(d) <= reach^2 (1 + 1e-9) in the scalar order of operations.
  const __m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
  const __m512d lim = _mm512_mul_pd(_mm512_mul_pd(reach, reach), _mm512_set1_pd(1.0 + 1e-9));
  const __mmask8 cand = _mm512_mask_cmp_pd_mask(lanes, d2, lim, _CMP_LE_OQ);
  const __mmask8 crossing = static_cast<__mmask8>(lanes & ~_mm256_cmplt_epu32_mask(jv, _mm256_set1_epi32(static_cast<int>(end))));
  const __m256i cross = _mm256_mask_expand_epi32(_mm256_set1_epi32(static_cast<int>(kInternal)), crossing,
                                                 _mm256_add_epi32(iota, _mm256_set1_epi32(static_cast<int>(c))));
  c += static_cast<std::uint32_t>(std::popcount(static_cast<unsigned>(crossing)));
  // Compress in registers, then plain stores (a compressing store to memory is slow on some
  // processors); the batch has room for a whole group past its count.
  const std::size_t t = b.count;
  const __m256i slot = _mm256_add_epi32(iota, _mm256_set1_epi32(static_cast<int>(k)));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.i + t), _mm256_maskz_compress_epi32(cand, iv));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.j + t), _mm256_maskz_compress_epi32(cand, jv));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.slot + t), _mm256_maskz_compress_epi32(cand, slot));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(b.cross + t), _mm256_maskz_compress_epi32(cand, cross));
  _mm512_storeu_pd(b.dx + t, _mm512_maskz_compress_pd(cand, dx));
  _mm512_storeu_pd(b.dy + t, _mm512_maskz_compress_pd(cand, dy));
  _mm512_storeu_pd(b.dz + t, _mm512_maskz_compress_pd(cand, dz));
  _mm512_storeu_pd(b.reach + t, _mm512_maskz_compress_pd(cand, reach));
  b.count += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(cand)));
  if (!q.commit) return;
  // Slots apart that hold history: any non-zero spring component (vt0 / wr0: every slot apart).
  unsigned held = lanes;
  if (!q.vt0 && !q.wr0) {
    const double* sp = &q.spring[k].x;
    const unsigned m24 = (1u << (3 * cnt)) - 1u;  // 3 doubles per slot
    const auto nonzero = [&](int part) {
      const __m512d s = _mm512_maskz_loadu_pd(static_cast<__mmask8>(m24 >> (8 * part)), sp + 8 * part);
      return static_cast<unsigned>(_mm512_cmp_pd_mask(s, zero, _CMP_NEQ_UQ));
    };
    const unsigned bits = nonzero(0) | (nonzero(1) << 8) | (nonzero(2) << 16);
    held = _pext_u32(bits | (bits >> 1) | (bits >> 2), 0x249249u);  // bit 3s of each slot s
  }
  for (unsigned stale = held & lanes & ~static_cast<unsigned>(cand); stale != 0; stale &= stale - 1)
    forget_history(q, k + static_cast<std::size_t>(std::countr_zero(stale)));
}
#endif

template <bool kUniform>
PairBlockSums evaluate_block(const PairPass& q, std::size_t lo, std::size_t hi, std::size_t cross_first,
                             std::size_t cross_last) {
  PairBlockSums out;
  Batch b;
  const auto end = static_cast<std::uint32_t>(PairBlocks::block_end(lo, q.n));
  // Cross shares default to zero (contacts add to them).
  std::fill(q.cross_force + cross_first, q.cross_force + cross_last, Vec3{});
  std::fill(q.cross_torque + cross_first, q.cross_torque + cross_last, Vec3{});
  std::uint32_t c = static_cast<std::uint32_t>(cross_first);  // next cross index
  // The block's slots in groups, in slot order; a batch runs when the next group might not fit.
  const std::size_t k1 = q.off[hi];
  for (std::size_t k = q.off[lo]; k < k1; k += kGroup) {
    // The neighbours' data are indirect loads the hardware cannot foresee: fetch them ahead
    // (about 13% of the pair time on the 100k bed).
    for (std::size_t a = k + kAhead; a < std::min(k + kAhead + kGroup, q.pairs); ++a) {
      const std::uint32_t ja = q.idx[a];
      __builtin_prefetch(&q.x[ja]);
      __builtin_prefetch(&q.v[ja]);
      __builtin_prefetch(&q.w[ja]);
      __builtin_prefetch(&q.terms[ja]);
    }
    // The slots' springs (read for every slot at a commit) are a sequential stream the hardware
    // prefetcher does not keep ahead of (about 10% of the pair time on the 100k bed).
    // So are the slots' first members (the prefetch loop above reads the second ones).
    if (k + kAhead + kGroup <= q.pairs) {
      const char* sp = reinterpret_cast<const char*>(q.spring + k + kAhead);
      __builtin_prefetch(sp);
      __builtin_prefetch(sp + 64);
      __builtin_prefetch(sp + 128);
      __builtin_prefetch(q.first + k + kAhead);
    }
    // The first members' data and sums too (their index rises slowly: one group covers them).
    if (k + kAhead / 2 < k1) {
      const std::uint32_t ia = q.first[k + kAhead / 2];
      __builtin_prefetch(&q.x[ia]);
      __builtin_prefetch(&q.v[ia]);
      __builtin_prefetch(&q.w[ia]);
      __builtin_prefetch(&q.terms[ia]);
      __builtin_prefetch(&q.force[ia], 1);
      __builtin_prefetch(&q.torque[ia], 1);
    }
    if (k + 4 * kAhead < q.pairs) __builtin_prefetch(q.idx + k + 4 * kAhead);
    const std::size_t cnt = std::min(kGroup, k1 - k);
#if MPDEM_VECTOR_SELECT
    if (q.vector_select)
      select_vector(q, b, k, cnt, end, c);
    else
      select_scalar(q, b, k, cnt, end, c);
#else
    select_scalar(q, b, k, cnt, end, c);
#endif
    if (b.count + kGroup > kBatch) run<kUniform>(q, b, out);
  }
  if (b.count > 0) run<kUniform>(q, b, out);
  return out;
}

}  // namespace

PairBlockSums contact_block(const PairPass& q, std::size_t lo, std::size_t hi, std::size_t cross_first,
                            std::size_t cross_last) {
  return q.uniform.on ? evaluate_block<true>(q, lo, hi, cross_first, cross_last)
                      : evaluate_block<false>(q, lo, hi, cross_first, cross_last);
}

}  // namespace mpdem
