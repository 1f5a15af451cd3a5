#pragma once
// The pair kernel's batch (contact/pair_batch.cpp): its structure of arrays, and pass 0, which
// selects the candidate pairs of a group of list slots into it (scalar, or AVX-512 when the build
// targets it, bit for bit the same). Internal to the kernel: included by pair_batch.cpp only,
// so that everything here inlines into its loops.
#include <bit>
#include <cstddef>
#include <cstdint>

#include "contact/laws/law_list.hpp"
#include "contact/pair_batch.hpp"
#include "physics/tangential.hpp"

// Candidate selection with AVX-512 (8 slots per instruction) when the build targets it.
#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512DQ__) && defined(__BMI2__)
#define MPDEM_VECTOR_SELECT 1
#include <immintrin.h>
#else
#define MPDEM_VECTOR_SELECT 0
#endif

namespace mpdem::pair_kernel {

constexpr std::size_t kBatch = 128;               // candidate pairs per batch
constexpr std::size_t kGroup = 8;                 // slots selected at a time
constexpr std::size_t kLanes = 8;                 // doubles per vector (AVX-512); kBatch is a multiple
constexpr std::uint32_t kInternal = 0xffffffffu;  // "no cross index"
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
  double radius_product[kBatch];                 // m^2, R_i R_j
  double inverse_mass_sum[kBatch];               // 1/kg, 1/m_i + 1/m_j
  // The pair's law (several materials only; one material: PairPass::uniform_law).
  LawId law[kBatch];
  TangentialSpring spring_form[kBatch];
  double coefficients[kCoefficients][kBatch];  // PairLaw::c by slot (contact/laws/), units by slot
  // Stage 1: geometry and kinematics.
  double overlap[kBatch];                        // m, 0 when apart
  double nx[kBatch], ny[kBatch], nz[kBatch];     // -, n_ij, from j to i
  double vtx[kBatch], vty[kBatch], vtz[kBatch];  // m/s, tangential relative velocity (60)
  double r_star[kBatch];                         // m, r* (52)
  // Stage 1: the normal half of the law.
  double fn_load[kBatch];               // N, max(fn_net + adhesion, 0): Coulomb's limit and rolling scale with it
  double fn_net[kBatch];                // N, net normal force
  double tangential_stiffness[kBatch];  // N/m, k_t
  double tangential_damping[kBatch];    // N s/m, d_t
  double normal_energy[kBatch];         // J, normal spring energy
  double normal_damping[kBatch];        // W, normal dashpot power
  // Stage 2a: history.
  double s0x[kBatch], s0y[kBatch], s0z[kBatch];  // m, stored spring
  double v0x[kBatch], v0y[kBatch], v0z[kBatch];  // m/s, step-start tangential velocity (kStepStart)
  SlipDecision decide[kBatch];
  // Stage 2: the tangential half.
  double sx[kBatch], sy[kBatch], sz[kBatch];  // m, spring for the next step
  std::int64_t slip[kBatch];                  // 1 when sliding (8 bytes, like SlipDecision)
  // Stage 4a: results.
  double fx[kBatch], fy[kBatch], fz[kBatch];  // N, force on i
  double ax[kBatch], ay[kBatch], az[kBatch];  // N, n x f_t
  double energy[kBatch];                      // J, elastic energy of the contact
  double damping[kBatch];                     // W, normal dashpot power
  double spring_energy_before[kBatch];        // J, stored spring at this step's stiffness
  double spring_energy_after[kBatch];         // J, the new spring's energy
  double tangential_loss[kBatch];             // J, tangential loss of the step (ContactResult)
  // The vector stages run over whole vectors: the lanes past count repeat the last candidate
  // (gather_members, gather_history), so they compute finite values nobody reads.
  // Cohesion (PairPass::state): the committed state, the bridge law, what acts (0: apart), the
  // state to commit, what broke and the energy it held (J) (contact/cohesive_contact.hpp).
  std::uint8_t state0[kBatch];
  const BridgeLaw* bridge[kBatch];
  std::uint8_t live[kBatch];
  std::uint8_t next[kBatch];
  std::uint8_t broke[kBatch];
  double loss[kBatch];
  std::size_t lanes() const { return (count + kLanes - 1) / kLanes * kLanes; }
  // Lane t's law, slot by slot (several materials).
  PairLaw pair_law(std::size_t t) const {
    PairLaw l;
    l.law = law[t];
    l.spring = spring_form[t];
    for (std::size_t s = 0; s < kCoefficients; ++s) l.c[s] = coefficients[s][t];
    return l;
  }
  Vec3 normal(std::size_t t) const { return {nx[t], ny[t], nz[t]}; }
  Vec3 vt(std::size_t t) const { return {vtx[t], vty[t], vtz[t]}; }
};

// A commit forgets the history of slot k, whose pair is apart.
inline void forget_history(const PairPass& pass, std::size_t k) {
  pass.spring[k] = Vec3{};
  if (pass.state) pass.state[k] = 0;
  if (pass.vt0) pass.vt0[k] = Vec3{};
  if (pass.wr0) pass.wr0[k] = Vec3{};
}

// Pass 0: selects the candidates among slots [k, k + cnt) of one block (cnt <= kGroup) into
// the batch, in slot order, and numbers the cross slots from c on. A candidate is a pair within
// reach up to a relative margin that leaves the exact decision (overlap > 0) to stage 1; a
// commit forgets the history of the other slots. Every slot is written, the count advances only
// for a candidate (no data-dependent branch). kCohesive: the reach grows by pass.gap, and a slot
// with a formed state is a candidate wherever it is (its break is booked by the kernel).
template <bool kCohesive = false>
inline void select_scalar(const PairPass& pass, Batch& b, std::size_t k, std::size_t cnt, std::uint32_t end,
                          std::uint32_t& c) {
  for (const std::size_t stop = k + cnt; k < stop; ++k) {
    const std::uint32_t i = pass.first[k], j = pass.idx[k];
    const bool internal = j < end;
    const std::uint32_t cross = internal ? kInternal : c;
    c += internal ? 0u : 1u;
    const double reach = pass.terms[i].radius + pass.terms[j].radius;
    const Vec3 d = pass.x[i] - pass.x[j];
    bool cand;
    if constexpr (kCohesive) {
      const double r = reach + pass.gap;
      cand = (norm2(d) <= r * r * kCandidateReach) | (pass.state[k] != 0);
    } else {
      cand = norm2(d) <= reach * reach * kCandidateReach;
    }
    const std::size_t t = b.count;
    b.i[t] = i;
    b.j[t] = j;
    b.slot[t] = static_cast<std::uint32_t>(k);
    b.cross[t] = cross;
    b.dx[t] = d.x, b.dy[t] = d.y, b.dz[t] = d.z;  // kept for stage 1
    b.reach[t] = reach;
    b.count += cand;
    if (pass.commit) {
      // Only a contact that just opened has history to forget (rare): store only then.
      const Vec3& s0 = pass.spring[k];
      const bool held = (s0.x != 0.0) | (s0.y != 0.0) | (s0.z != 0.0) | (pass.vt0 != nullptr) | (pass.wr0 != nullptr);
      if (!cand & held) forget_history(pass, k);
    }
  }
}

#if MPDEM_VECTOR_SELECT
// The same selection, bit for bit, 8 slots at once: gathers of the members' centres and radii,
// the candidates compressed into the batch, the cross numbers by expansion.
inline void select_vector(const PairPass& pass, Batch& b, std::size_t k, std::size_t cnt, std::uint32_t end,
                          std::uint32_t& c) {
  const __mmask8 lanes = static_cast<__mmask8>((1u << cnt) - 1u);
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i iv = _mm256_maskz_loadu_epi32(lanes, pass.first + k);
  const __m256i jv = _mm256_maskz_loadu_epi32(lanes, pass.idx + k);
  const __m256i i3 = _mm256_add_epi32(iv, _mm256_add_epi32(iv, iv));  // Vec3 = 3 doubles
  const __m256i j3 = _mm256_add_epi32(jv, _mm256_add_epi32(jv, jv));
  const double* xb = &pass.x[0].x;
  const __m512d zero = _mm512_setzero_pd();
  const __m512d dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, lanes, i3, xb, 8),
                                   _mm512_mask_i32gather_pd(zero, lanes, j3, xb, 8));
  const __m512d dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, lanes, i3, xb + 1, 8),
                                   _mm512_mask_i32gather_pd(zero, lanes, j3, xb + 1, 8));
  const __m512d dz = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, lanes, i3, xb + 2, 8),
                                   _mm512_mask_i32gather_pd(zero, lanes, j3, xb + 2, 8));
  const double* rb = &pass.terms[0].radius;  // ContactTerms = 2 doubles
  const __m512d reach = _mm512_add_pd(_mm512_mask_i32gather_pd(zero, lanes, _mm256_slli_epi32(iv, 1), rb, 8),
                                      _mm512_mask_i32gather_pd(zero, lanes, _mm256_slli_epi32(jv, 1), rb, 8));
  // norm2(d) <= reach^2 kCandidateReach in the scalar order of operations.
  const __m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
  const __m512d lim = _mm512_mul_pd(_mm512_mul_pd(reach, reach), _mm512_set1_pd(kCandidateReach));
  const __mmask8 cand = _mm512_mask_cmp_pd_mask(lanes, d2, lim, _CMP_LE_OQ);
  const __mmask8 crossing = static_cast<__mmask8>(
      lanes & ~_mm256_cmplt_epu32_mask(jv, _mm256_set1_epi32(static_cast<int>(end))));
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
  if (!pass.commit) return;
  // Slots apart that hold history: any non-zero spring component (vt0 / wr0: every slot apart).
  unsigned held = lanes;
  if (!pass.vt0 && !pass.wr0) {
    const double* sp = &pass.spring[k].x;
    const unsigned m24 = (1u << (3 * cnt)) - 1u;  // 3 doubles per slot
    const auto nonzero = [&](int part) {
      const __m512d s = _mm512_maskz_loadu_pd(static_cast<__mmask8>(m24 >> (8 * part)), sp + 8 * part);
      return static_cast<unsigned>(_mm512_cmp_pd_mask(s, zero, _CMP_NEQ_UQ));
    };
    const unsigned bits = nonzero(0) | (nonzero(1) << 8) | (nonzero(2) << 16);
    held = _pext_u32(bits | (bits >> 1) | (bits >> 2), 0x249249u);  // bit 3s of each slot s
  }
  for (unsigned stale = held & lanes & ~static_cast<unsigned>(cand); stale != 0; stale &= stale - 1)
    forget_history(pass, k + static_cast<std::size_t>(std::countr_zero(stale)));
}
#endif

}  // namespace mpdem::pair_kernel
