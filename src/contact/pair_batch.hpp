#pragma once
// The particle-particle contact kernel (physics.md sections 5-6) for one block of particles
// (neighbor/pair_blocks.hpp), evaluated in batches.
//
// Why batches: one Hertz-Mindlin contact is a long chain of dependent square roots and divisions
// (distance -> overlap -> sqrt(r* delta) -> damping root -> force -> Coulomb test), so a loop that
// finishes one contact before starting the next waits on latency. The kernel first collects up
// to kBatch candidate pairs, then runs each stage (geometry, normal law, tangential law) over the
// whole batch - independent iterations the processor overlaps - and finally adds the results to
// the particles in slot order, so every particle's sum has a fixed order for any thread count.
#include <cstddef>
#include <cstdint>

#include "core/vec3.hpp"
#include "contact/bridges/bridge_law.hpp"
#include "contact/contact_record.hpp"
#include "contact/contact_table.hpp"

namespace mpdem {

// Per-particle values the kernel reads of a neighbour, one 16-byte record (a quarter of a cache
// line to fetch): r* (52) = R_i R_j / (R_i + R_j), m* (53) = 1 / (1/m_i + 1/m_j).
struct ContactTerms {
  double radius = 0.0;    // m
  double inv_mass = 0.0;  // 1/kg
};

// The deepest contact, relative to the smaller radius.
struct DeepestPair {
  double ratio = 0.0;       // -, overlap / min(R_i, R_j)
  std::int64_t first = -1;  // particle ids
  std::int64_t second = -1;
};

// Sums over one block, added in block order by the caller.
struct PairBlockSums {
  double contacts = 0.0;
  double elastic_energy = 0.0;  // J
  double damping_power = 0.0;   // W, normal dashpots
  double rolling_power = 0.0;   // W, rolling friction
  double sticking_loss = 0.0;   // J, tangential loss (ContactResult) of the sticking contacts
  double sliding_loss = 0.0;    // J, tangential loss of the sliding contacts
  double spring_before = 0.0;   // J, the stored springs' energy at this step's stiffness
  double spring_after = 0.0;    // J, the new springs' energy
  // Cohesion (PairPass::state): bridges held, contacts and bridges that broke at this commit,
  // and the energy they held then (J, dissipated).
  double bridges = 0.0;
  double breaks = 0.0;
  double ruptures = 0.0;
  double cohesion_loss = 0.0;
  double elastic_magnitude = 0.0;  // J, sum of |stored energy| of the contacts (cohesion only)
  DeepestPair deepest;
};


// Everything the kernel reads and writes, as plain pointers into distinct arrays.
struct PairPass {
  const Vec3* __restrict x;               // [N] m
  const Vec3* __restrict v;               // [N] m/s
  const Vec3* __restrict w;               // [N] rad/s
  const std::int64_t* __restrict id;      // [N]
  const ContactTerms* __restrict terms;   // [N]
  const double* __restrict inertia;       // [N] kg m^2 (rolling resistance)
  const int* __restrict material;         // [N] material index
  const PairLaw* __restrict laws;         // [materials x materials] contact table (contact_table.hpp)
  const std::uint32_t* __restrict off;    // [N+1] half-list CSR offsets
  const std::uint32_t* __restrict idx;    // [pairs] second members
  const std::uint32_t* __restrict first;  // [pairs] first members
  Vec3* __restrict force;                 // [N] N, accumulated
  Vec3* __restrict torque;                // [N] N m, accumulated
  Vec3* __restrict spring;                // [pairs] m, committed spring (updated at commits)
  Vec3* __restrict vt0;                   // [pairs] m/s step-start tangential velocity, or null
  Vec3* __restrict wr0;                   // [pairs] rad/s step-start w_i - w_j, or null
  std::uint8_t* __restrict slipped;       // [pairs] first iteration's slip, or null
  Vec3* __restrict cross_force;           // [cross] N, force on the second member
  Vec3* __restrict cross_torque;          // [cross] N m, torque on the second member
  std::size_t materials = 0;              // rows of laws
  bool uniform = false;                   // every particle has one material: uniform_law for all pairs
  PairLaw uniform_law;
  LawSet laws_used = 0;  // the laws the table holds (ContactTable::particle_laws)
  bool rolling = false;  // some pair has rolling resistance
  double dt = 0.0;       // s
  double phi = 1.0;      // -
  int iteration = 0;
  bool commit = false;
  std::size_t n = 0;                        // particles
  std::size_t pairs = 0;                    // list slots
  bool vector_select = true;                // AVX-512 candidate selection, when built in (kVectorSelect)
  PairRecord* __restrict record = nullptr;  // [pairs] each touching slot's contact, or null (not recording)
  // Cohesion: a law with hysteresis or liquid bridges in the table. Null / 0 without: the plain kernel.
  std::uint8_t* __restrict state = nullptr;  // [pairs] kLawFormed | kBridgeFormed (cohesive_contact.hpp), committed
  const BridgeLaw* __restrict bridges = nullptr;  // [materials x materials] (ContactTable), or null: none
  double gap = 0.0;                               // m, >= 0, the candidates' reach beyond touching
  // False: the contacts' energy terms (PairBlockSums' energies and powers) are neither computed nor
  // summed: an evaluation whose energies nobody reads (the trapezoidal rule's iterations; with
  // [checks] energy_ledger = false, the steps between log rows). The cohesive kernel computes them
  // always: with `state`, ParticleContacts sets it true.
  bool energies = true;
};

// True when the build has the AVX-512 candidate selection (bitwise the same as the scalar one).
extern const bool kVectorSelect;

// A pair is a candidate of the kernel when |x_i - x_j|^2 <= (R_i + R_j)^2 kCandidateReach: a
// relative margin that leaves the exact decision (overlap > 0) to the contact law, so every
// touching pair is a candidate. With cohesion, (R_i + R_j + gap)^2 kCandidateReach, and every
// slot with a formed state.
inline constexpr double kCandidateReach = 1.0 + 1e-9;

// Evaluates the pairs whose first member is in [lo, hi), one PairBlocks block; its cross pairs
// are numbered [cross_first, cross_last).
PairBlockSums contact_block(const PairPass& q, std::size_t lo, std::size_t hi, std::size_t cross_first,
                            std::size_t cross_last);

}  // namespace mpdem
