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

namespace cohesion_reach_detail {
// m, >= 0: the largest |break_overlap| at r* over the pairs pair(a, b) of the table's laws.
template <class PairOf>
double neck_gap(const ContactTable& t, LawSet laws, PairOf pair, double r_star) {
  double gap = 0.0;
  if (!any_hysteresis(laws)) return gap;
  for (std::size_t a = 0; a < t.materials(); ++a)
    for (std::size_t b = 0; b < t.materials(); ++b) {
      const PairLaw& c = pair(a, b);
      with_law(c.law, [&]<class Law>(std::type_identity<Law>) { gap = std::max(gap, -break_overlap<Law>(c, r_star)); });
    }
  return gap;
}
}  // namespace cohesion_reach_detail

// m, >= 0. Both grow with the radii (JKR's |delta_c| ~ r*^(1/3), a bridge's volume and rupture
// distance with the particles' volumes), so the largest pair of radius r_max bounds them.
inline double particle_cohesion_gap(const ContactTable& t, double r_max) {
  const double neck = cohesion_reach_detail::neck_gap(
      t, t.particle_laws(), [&](std::size_t a, std::size_t b) -> const PairLaw& { return t.particle_pair(a, b); },
      0.5 * r_max);
  return std::max(neck, t.any_particle_bridges() ? t.bridge_reach(r_max) : 0.0);
}

// m, >= 0: the same for particle-barrier contacts (r* = R).
inline double barrier_cohesion_gap(const ContactTable& t, double r_max) {
  const double neck = cohesion_reach_detail::neck_gap(
      t, t.barrier_laws(), [&](std::size_t a, std::size_t b) -> const PairLaw& { return t.barrier_pair(a, b); }, r_max);
  return std::max(neck, t.any_barrier_bridges() ? t.barrier_bridge_reach(r_max) : 0.0);
}

// m, the largest particle radius of a scene: its particles', its inlets' and its clump members'.
inline double largest_radius(const Model& model, const Particles& p) {
  double r = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) r = std::max(r, p.radius[i]);
  for (const InletSpec& in : model.params.inlets) r = std::max(r, in.radius.largest());
  for (const ClumpTemplate& t : model.clumps)
    for (const ClumpMember& m : t.members()) r = std::max(r, m.r);
  return r;
}

// True when the table's contacts keep a cohesion state: a law with hysteresis or a liquid bridge.
inline bool has_cohesion(const ContactTable& t) {
  return any_hysteresis(t.particle_laws() | t.barrier_laws()) || t.any_particle_bridges() || t.any_barrier_bridges();
}

// How far a scene's contacts reach beyond touching, for its largest particles.
struct CohesionGaps {
  double particles = 0.0;  // m, particle pairs (particle_cohesion_gap)
  double barriers = 0.0;   // m, particle-barrier contacts (barrier_cohesion_gap)
  bool cohesive = false;   // has_cohesion: the contacts keep a formed state
};
inline CohesionGaps cohesion_gaps(const ContactTable& t, const Model& model, const Particles& p) {
  const double r_max = largest_radius(model, p);
  return {particle_cohesion_gap(t, r_max), barrier_cohesion_gap(t, r_max), has_cohesion(t)};
}

inline bool has_cohesion(const Model& model) {
  ContactTable t;
  t.build(model);
  return has_cohesion(t);
}

}  // namespace mpdem
