#pragma once
// One particle-particle contact as the evaluation that recorded it computed it: recorded only on
// request (Interactions::record_contacts: the Python contact list), per pair slot.
#include <cstdint>

#include "core/vec3.hpp"

namespace mpdem {

struct PairRecord {
  Vec3 force;                 // N, on the slot's first member (normal + tangential)
  Vec3 normal;                // -, unit, from the second member to the first
  double overlap = 0.0;       // m, < 0 across a liquid bridge's gap or a JKR neck past touching
  double normal_force = 0.0;  // N, net normal force along `normal` (on the first member)
  std::uint32_t sliding = 0;  // 1: at the Coulomb limit
  std::uint32_t live = 0;  // 0: not in contact; else kLawFormed (a contact) | kBridgeFormed (a bridge), pair_batch.hpp
};

}  // namespace mpdem
