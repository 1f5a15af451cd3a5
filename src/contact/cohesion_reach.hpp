#pragma once
// How far beyond touching the contacts of a table act: the largest break overlap of its laws with
// hysteresis (contact/laws/law_interface.hpp) and the largest rupture distance of its liquid
// bridges (contact/bridges/), for particles of radius <= r_max. The neighbour list and the pair
// kernel's candidates reach that far (ParticleContacts::set_gap), the barrier detection too.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "contact/contact_table.hpp"

namespace mpdem {

// m, >= 0. Both grow with the radii (JKR's |delta_c| ~ r*^(1/3), a bridge's volume and rupture
// distance with the particles' volumes), so the largest pair of radius r_max bounds them.
inline double particle_cohesion_gap(const ContactTable& t, double r_max) {
  double gap = 0.0;
  const std::size_t n = t.materials();
  if (any_hysteresis(t.particle_laws()))
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) {
        const PairLaw& c = t.particle_pair(a, b);
        with_law(c.law,
                 [&]<class Law>(std::type_identity<Law>) { gap = std::max(gap, -break_overlap<Law>(c, 0.5 * r_max)); });
      }
  if (t.any_particle_bridges()) gap = std::max(gap, t.bridge_reach(r_max));
  return gap;
}

// m, >= 0: the same for particle-barrier contacts (r* = R).
inline double barrier_cohesion_gap(const ContactTable& t, double r_max) {
  double gap = 0.0;
  const std::size_t n = t.materials();
  if (any_hysteresis(t.barrier_laws()))
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) {
        const PairLaw& c = t.barrier_pair(a, b);
        with_law(c.law,
                 [&]<class Law>(std::type_identity<Law>) { gap = std::max(gap, -break_overlap<Law>(c, r_max)); });
      }
  if (t.any_barrier_bridges()) gap = std::max(gap, t.barrier_bridge_reach(r_max));
  return gap;
}

// True when the table's contacts keep a cohesion state: a law with hysteresis or a liquid bridge.
inline bool has_cohesion(const ContactTable& t) {
  return any_hysteresis(t.particle_laws() | t.barrier_laws()) || t.any_particle_bridges() || t.any_barrier_bridges();
}
inline bool has_cohesion(const Model& model) {
  ContactTable t;
  t.build(model);
  return has_cohesion(t);
}

}  // namespace mpdem
