#pragma once
// BarrierBatch: particle-barrier contacts evaluated together (contact/barrier_contacts.cpp) - the
// batch's structure of arrays and the contact law over it.
#include <cstddef>
#include <cstdint>

#include "core/vec3.hpp"
#include "contact/contact_table.hpp"
#include "physics/tangential.hpp"
#include "contact/barrier_contact_store.hpp"
#include "contact/eval_request.hpp"

namespace mpdem {

// The contacts of consecutive active particles of one group, evaluated stage by stage. Why: one
// Hertz-Mindlin contact is a long chain of dependent square roots and divisions, so finishing
// one contact before starting the next waits on latency; the law's loop over a batch has
// independent iterations the processor overlaps (and vectorises). Structure of arrays for that.
struct BarrierBatch {
  static constexpr std::size_t kLanes = 8;      // doubles per vector (AVX-512)
  static constexpr std::size_t kContacts = 64;  // contacts per batch, a multiple of kLanes
  static constexpr std::size_t kSlots = BarrierContactStore::kSlots;
  static_assert(kContacts % kLanes == 0 && kContacts >= kSlots, "batches hold whole vectors and a particle");

  // --- the particles, in active order
  std::size_t particles = 0;
  std::uint32_t k[kContacts];    // active position
  std::uint32_t end[kContacts];  // one past its last contact (the first is the previous end)
  // --- their contacts, from detection and history (collect)
  std::size_t count = 0;
  std::int32_t element[kContacts];                           // barrier element
  const BarrierSlot* hist[kContacts];                        // history record, or null
  SlipDecision decide[kContacts];                            // imposed stick/slip (later iterations)
  Vec3 point[kContacts];                                     // m, contact point
  double overlap[kContacts];                                 // m
  double nx[kContacts], ny[kContacts], nz[kContacts];        // -, unit normal towards the particle
  double vx[kContacts], vy[kContacts], vz[kContacts];        // m/s, particle velocity
  double wx[kContacts], wy[kContacts], wz[kContacts];        // rad/s, particle rotation
  double ux[kContacts], uy[kContacts], uz[kContacts];        // m/s, barrier velocity
  double s0x[kContacts], s0y[kContacts], s0z[kContacts];     // m, stored spring (zero: none)
  double vt0x[kContacts], vt0y[kContacts], vt0z[kContacts];  // m/s, stored tangential velocity
  // the pair's law (PairLaw, contact/laws/law_list.hpp)
  LawId law[kContacts];
  TangentialSpring spring_form[kContacts];
  double coefficients[kCoefficients][kContacts];  // PairLaw::c by slot, units by slot
  double r_star[kContacts], m_star[kContacts];    // m, kg: r* = R, m* = m
  // --- the law's results (contact_law)
  double fx[kContacts], fy[kContacts], fz[kContacts];     // N, force on the particle
  double tx[kContacts], ty[kContacts], tz[kContacts];     // N m, r_P x f_t
  double sx[kContacts], sy[kContacts], sz[kContacts];     // m, spring for the next step
  double vtx[kContacts], vty[kContacts], vtz[kContacts];  // m/s, tangential velocity
  double fn_load[kContacts];                              // N, max(fn + adhesion, 0) (rolling resistance)
  double energy[kContacts];                               // J, elastic energy
  double damping[kContacts];                              // W, normal dashpot power
  double spring_energy_before[kContacts];                 // J, stored spring at this step's stiffness
  double spring_energy_after[kContacts];                  // J, the new spring's energy
  double tangential_loss[kContacts];                      // J, tangential loss (ContactResult)
  std::int64_t slip[kContacts];                           // 1 when sliding (8 bytes, like SlipDecision)
  // --- cohesion (BarrierContacts::gap() > 0): the committed state, the bridge law (or null), the
  // state after the law and the energy of what broke (J) (contact/cohesive_contact.hpp)
  std::uint8_t state0[kContacts];
  const BridgeLaw* bridge[kContacts];
  std::uint8_t live[kContacts];
  std::uint8_t next[kContacts];
  std::uint8_t broke[kContacts];
  double loss[kContacts];

  // Room for one more particle with all its contacts.
  bool room() const { return count + kSlots <= kContacts && particles < kContacts; }
  // Contacts rounded up to whole vectors.
  std::size_t lanes() const { return (count + kLanes - 1) / kLanes * kLanes; }

  void set_law(std::size_t t, const PairLaw& c) {
    law[t] = c.law, spring_form[t] = c.spring;
    for (std::size_t s = 0; s < kCoefficients; ++s) coefficients[s][t] = c.c[s];
  }
  PairLaw law_of(std::size_t t) const {
    PairLaw c;
    c.law = law[t], c.spring = spring_form[t];
    for (std::size_t s = 0; s < kCoefficients; ++s) c.c[s] = coefficients[s][t];
    return c;
  }
};

// The contact law (contact_law.hpp; physics.md sections 5-7, 13) of every contact of the batch
// (count >= 1), for the laws the table holds (ContactTable::barrier_laws): fills the results from the inputs, lane by
// lane.
// cohesive: with the states and bridges of the batch (contact/cohesive_contact.hpp).
void barrier_contact_law(LawSet laws, const EvalRequest& req, BarrierBatch& b, bool cohesive = false);

}  // namespace mpdem
