#pragma once
// InteractionStats: the energy and contact bookkeeping of the evaluations (physics.md section
// 12), from one table. Each row of MPDEM_INTERACTION_STATS is one member and says how it is
// summed over the ranks, whether it accumulates over committed steps, which checkpoint section
// holds it, its role in the energy balance (integrate: energy_balance) and its log.csv column.
// Adding a statistic is adding a row; every user below iterates the table.
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace mpdem {

// How a member combines over the ranks of a decomposed run.
enum class StatRanks {
  count,  // a count over the particles: summed (as a double, exact below 2^53)
  sum,    // a sum over the particles: summed
  global  // computed from values already the same on every rank (the summed barrier loads)
};
// The checkpoint section that holds a member ("interactions": always, in table order; "fields":
// an optional section written only when a dissipative body force is on, so that the checkpoints
// of scenes without one keep their bytes; "cohesion": likewise, only with a contact law with
// hysteresis or liquid bridges; "bonds": only with [bonds]).
enum class StatSaved { interactions, fields, cohesion, bonds };
// The member's part in the energy balance (integrate/energy_balance.hpp).
enum class StatBalance {
  none,        // not an energy of the balance (powers, counts, the springs' share of elastic)
  stored,      // + energy held now (elastic)
  dissipated,  // + energy lost so far (damping, friction, dissipative body forces)
  supplied,    // - work done on the particles so far by prescribed motion and added loads
  // + a potential cut off at a range (the near field): in the log's total_energy, left out of the
  // balance the run checks (a pair crossing the cutoff steps the total by U(cutoff))
  cut_potential,
  heat  // the thermal balance (heat that left the particles), not the mechanical one
};
// When the member has a log.csv column (the optional ones only for the physics the scene uses).
// ledger: only with the contacts' energy ledger ([checks] energy_ledger).
enum class StatLogged {
  never,
  always,
  ledger,
  near_field,
  driven_barriers,
  thermal,
  dissipative_field,
  cohesion,
  bonds
};
// Where its column goes among the log's own (docs/output.md "log.csv"): after `removed`; after
// `potential`; before `total_energy` (the work taken off it); after `total_energy`.
enum class StatSlot { counts, energies, supplied, heat };

struct StatInfo {
  const char* name;  // the member's name
  const char* unit;
  StatRanks ranks;
  bool cumulative;  // accumulated over committed steps (else: the last evaluation's value)
  StatSaved saved;
  StatBalance balance;
  const char* column;  // log.csv column (nullptr: none)
  StatLogged logged;
  StatSlot slot;
};

// clang-format off
// X(type, member, unit, ranks, cumulative, checkpoint section, balance role, log column, logged when, log slot)
// Checkpoint order is the row order: new rows go at the end, in an optional section.
#define MPDEM_INTERACTION_STATS(X)                                                                                     \
  /* particle-particle and particle-barrier contacts at the last evaluation */                                         \
  X(std::size_t, contacts_pp, "-", count, false, interactions, none, "contacts_pp", always, counts)                    \
  X(std::size_t, contacts_pb, "-", count, false, interactions, none, "contacts_pb", always, counts)                    \
  /* Hertz + tangential springs at the last evaluation */                                                              \
  X(double, elastic_energy, "J", sum, false, interactions, stored, "elastic", always, energies)                        \
  /* normal dashpots and sticking tangential dashpots; sliding, rolling and the springs' restiffening */               \
  X(double, damping_dissipated, "J", sum, true, interactions, dissipated, "damping_dissipated", ledger, energies)      \
  X(double, friction_dissipated, "J", sum, true, interactions, dissipated, "friction_dissipated", ledger, energies)    \
  /* normal dashpots' and rolling resistance's powers at the last commit (the trapezoid's start values) */             \
  X(double, damping_power, "W", sum, false, interactions, none, nullptr, never, energies)                              \
  X(double, rolling_power, "W", sum, false, interactions, none, nullptr, never, energies)                              \
  /* the tangential springs' energy at the last commit */                                                              \
  X(double, spring_energy, "J", sum, false, interactions, none, nullptr, never, energies)                              \
  /* work of the barriers' prescribed motion on the particles (trapezoid of drive_power), and that power */            \
  X(double, barrier_work, "J", global, true, interactions, supplied, "barrier_work", driven_barriers, supplied)        \
  X(double, drive_power, "W", global, false, interactions, none, nullptr, never, supplied)                             \
  /* work of what holds the fixed particles to their motion, and its power -sum (F.v + T.w) over them */               \
  X(double, fixed_work, "J", sum, true, interactions, supplied, nullptr, never, supplied)                              \
  X(double, fixed_power, "W", sum, false, interactions, none, nullptr, never, supplied)                                \
  /* work of the loads a caller added (ExternalLoads), and its power sum (F.v + T.w) */                                \
  X(double, external_work, "J", sum, true, interactions, supplied, nullptr, never, supplied)                           \
  X(double, external_power, "W", sum, false, interactions, none, nullptr, never, supplied)                             \
  /* neighbour list rebuilds */                                                                                        \
  X(std::uint64_t, rebuilds, "-", global, true, interactions, none, nullptr, never, counts)                            \
  /* potential of the near-field pairs within the cutoff */                                                            \
  X(double, near_field_energy, "J", sum, false, interactions, cut_potential, "near_field", near_field, energies)       \
  /* heat from the particles into fixed-temperature barriers, to the air, radiated (multiphysics.md) */                \
  X(double, heat_to_barriers, "J", sum, true, interactions, heat, "heat_to_barriers", thermal, heat)                   \
  X(double, heat_convected, "J", sum, true, interactions, heat, "heat_convected", thermal, heat)                       \
  X(double, heat_radiated, "J", sum, true, interactions, heat, "heat_radiated", thermal, heat)                         \
  /* work of the dissipative body forces (interact/body_forces.hpp; trapezoid of field_power), and their */                 \
  /* power sum -F.v over the particles at the last commit */                                                           \
  X(double, field_dissipated, "J", sum, true, fields, dissipated, "field_dissipated", dissipative_field, energies)     \
  X(double, field_power, "W", sum, false, fields, none, nullptr, never, energies)                              \
  /* cohesion: liquid bridges held at the last evaluation; contacts with hysteresis (JKR) and bridges */               \
  /* broken so far, and the energy they held when they broke (contact/pair_batch.hpp) */                               \
  X(std::uint64_t, bridges, "-", count, false, cohesion, none, "bridges", cohesion, counts)                            \
  X(std::uint64_t, cohesion_breaks, "-", sum, true, cohesion, none, "breaks", cohesion, counts)                        \
  X(std::uint64_t, ruptures, "-", sum, true, cohesion, none, "ruptures", cohesion, counts)                             \
  X(double, cohesion_dissipated, "J", sum, true, cohesion, dissipated, "cohesion_dissipated", cohesion, energies)    \
  /* the sum of the contacts' stored energies' magnitudes at the last evaluation (cohesion only: the scale */         \
  /* of the energy checks, integrate/energy_balance.hpp active_energy) */                                             \
  X(double, elastic_magnitude, "J", sum, false, cohesion, none, nullptr, never, energies)                          \
  /* parallel bonds (contact/bonds.hpp): intact at the last evaluation, broken so far, the energy their springs */   \
  /* hold, what their dashpots dissipated (trapezoid of bond_damping_power), the energy the broken ones held */       \
  X(std::uint64_t, bonds_intact, "-", count, false, bonds, none, "bonds", bonds, counts)                               \
  X(std::uint64_t, bonds_broken, "-", sum, true, bonds, none, "bonds_broken", bonds, counts)                           \
  X(double, bond_energy, "J", sum, false, bonds, stored, "bond_energy", bonds, energies)                               \
  X(double, bond_damping_dissipated, "J", sum, true, bonds, dissipated, "bond_damping", bonds, energies)                \
  X(double, bond_break_dissipated, "J", sum, true, bonds, dissipated, "bond_break_energy", bonds, energies)            \
  X(double, bond_damping_power, "W", sum, false, bonds, none, nullptr, never, energies)
// clang-format on

struct InteractionStats {
#define MPDEM_STAT_MEMBER(type, member, ...) type member = 0;
  MPDEM_INTERACTION_STATS(MPDEM_STAT_MEMBER)
#undef MPDEM_STAT_MEMBER
};

// The table's rows as data, in member order.
inline constexpr StatInfo kStats[] = {
#define MPDEM_STAT_ROW(type, member, unit, ranks, cumulative, saved, balance, column, logged, slot) \
  StatInfo{#member,          unit,                                                                  \
           StatRanks::ranks, cumulative,                                                            \
           StatSaved::saved, StatBalance::balance,                                                  \
           column,           StatLogged::logged,                                                    \
           StatSlot::slot},
    MPDEM_INTERACTION_STATS(MPDEM_STAT_ROW)
#undef MPDEM_STAT_ROW
};
inline constexpr std::size_t kStatCount = std::size(kStats);

// f(info, member) for every member in table order (member: a reference to its value in s).
template <class S, class F>
constexpr void for_each_stat(S& s, F&& f) {
  std::size_t k = 0;
#define MPDEM_STAT_VISIT(type, member, ...) f(kStats[k++], s.member);
  MPDEM_INTERACTION_STATS(MPDEM_STAT_VISIT)
#undef MPDEM_STAT_VISIT
}

// The members summed over the ranks (count and sum rows), in table order, as doubles: one
// reduction for all of them.
inline constexpr std::size_t kRankSummedStatCount = [] {
  std::size_t n = 0;
  for (const StatInfo& s : kStats) n += s.ranks != StatRanks::global ? 1 : 0;
  return n;
}();
inline std::array<double, kRankSummedStatCount> rank_summed_values(const InteractionStats& s) {
  std::array<double, kRankSummedStatCount> out{};
  std::size_t k = 0;
  for_each_stat(s, [&](const StatInfo& info, const auto& v) {
    if (info.ranks != StatRanks::global) out[k++] = static_cast<double>(v);
  });
  return out;
}
template <class V>  // V: kRankSummedStatCount doubles, in rank_summed_values' order
void set_rank_summed_values(InteractionStats& s, const V& sums) {
  std::size_t k = 0;
  for_each_stat(s, [&](const StatInfo& info, auto& v) {
    if (info.ranks != StatRanks::global) v = static_cast<std::decay_t<decltype(v)>>(sums[k++]);
  });
}

}  // namespace mpdem
