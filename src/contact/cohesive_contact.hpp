#pragma once
// The normal half of a contact with cohesion, for the pair and barrier kernels: a contact law
// with hysteresis (contact/laws/law_interface.hpp kHysteresis: JKR's neck) and a liquid bridge
// (contact/bridges/), each with a formed flag per contact that the kernels commit.
// - The law acts while the surfaces touch (overlap > 0), or, formed, until the overlap falls to
//   its break_overlap (laws without hysteresis: 0, so only in contact).
// - A bridge forms at touching and acts across the gap until its rupture distance.
// - What breaks at this evaluation is reported with the energy it held then, the energy the
//   force's jump to zero takes out of the stored elastic energy (booked as dissipated).
#include <cstdint>

#include "contact/bridges/bridge_law.hpp"
#include "contact/contact_law.hpp"

namespace mpdem {

// The bits of a contact's cohesion state.
inline constexpr std::uint8_t kLawFormed = 1, kBridgeFormed = 2;

struct CohesiveNormal {
  NormalContact n;         // the law's part (zero when it does not act) plus the bridge's force
  std::uint8_t live = 0;   // what acts now: kLawFormed (the law) | kBridgeFormed (a bridge); 0: apart
  std::uint8_t next = 0;   // the state to commit: live, less kLawFormed for a law without hysteresis
  std::uint8_t broke = 0;  // what broke now: a neck (kLawFormed) | a bridge (kBridgeFormed)
  double loss = 0.0;       // J, the energy held by what broke now
};

// J, the energy a formed neck (kLawFormed in `which`) and a formed bridge (kBridgeFormed) hold
// when they break: the law's at its break overlap, the bridge's at its rupture distance.
template <class Law>
inline double broken_energy(const PairLaw& c, const BridgeLaw* bridge, std::uint8_t which, double r_star,
                            double inv_reach) {
  double loss = 0.0;
  if ((which & kLawFormed) != 0) loss += Law::stiffness(c, r_star, break_overlap<Law>(c, r_star), inv_reach).energy;
  if ((which & kBridgeFormed) != 0 && bridge && bridge->model != BridgeModel::none)
    loss += bridge_force(*bridge, r_star, inv_reach, -bridge_rupture_distance(*bridge, r_star, inv_reach), 0.0).energy;
  return loss;
}

// before: the committed state; overlap (m) keeps its sign (negative: a gap); bridge: the pair's
// bridge law or null; inv_reach: 1 / (R_i + R_j) (0 at a barrier).
template <class Law>
inline CohesiveNormal cohesive_normal(const PairLaw& c, const BridgeLaw* bridge, std::uint8_t before, double r_star,
                                      double m_star, double overlap, double normal_rate, double inv_reach) {
  CohesiveNormal out;
  const double brk = break_overlap<Law>(c, r_star);  // m, <= 0
  const bool law_on = overlap > 0.0 || ((before & kLawFormed) != 0 && overlap > brk);
  if (law_on) out.n = normal_contact<Law>(c, r_star, m_star, overlap, normal_rate, inv_reach);
  bool bridge_on = false;
  if (bridge && bridge->model != BridgeModel::none) {
    bridge_on = overlap > 0.0 ||
                ((before & kBridgeFormed) != 0 && -overlap < bridge_rupture_distance(*bridge, r_star, inv_reach));
    if (bridge_on) {
      const BridgeForce f = bridge_force(*bridge, r_star, inv_reach, overlap, normal_rate);
      out.n.fn += f.fn;
      out.n.energy += f.energy;
      out.n.damping += f.damping;
    }
  }
  out.live = static_cast<std::uint8_t>((law_on ? kLawFormed : 0) | (bridge_on ? kBridgeFormed : 0));
  out.next = static_cast<std::uint8_t>((law_on && brk < 0.0 ? kLawFormed : 0) | (bridge_on ? kBridgeFormed : 0));
  out.broke = static_cast<std::uint8_t>(before & ~out.live & (kLawFormed | kBridgeFormed));
  if (out.broke != 0) out.loss = broken_energy<Law>(c, bridge, out.broke, r_star, inv_reach);
  return out;
}

// The tangential half where the law does not act (a bridge alone): no spring, no friction.
inline void without_contact(ContactResult& r, const NormalContact& n) {
  r.ft = Vec3{}, r.spring = Vec3{}, r.slipped = false;
  r.energy = n.energy, r.spring_energy = r.spring_energy_before = r.tangential_loss = 0.0;
}

}  // namespace mpdem
