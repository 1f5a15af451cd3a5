#pragma once
// ContactTable: the constants (PairLaw, contact/laws/law_list.hpp) of the contact law of every
// pair of materials, resolved from
// the scene's [contact] defaults and [[contact.pair]] overrides (docs/scene.md "Contact") and
// the materials' elastic constants. The kernels index it by the two material indices; nothing
// per contact depends on names. Cheap to build (the restitution calibration is cached), so it
// is rebuilt from the model at every evaluation: a material edited between steps takes effect
// at the next one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact/bridges/bridge_law.hpp"
#include "contact/laws/law_list.hpp"
#include "model/params.hpp"
#include "model/scene.hpp"

namespace mpdem {

class ContactTable {
 public:
  // Resolves the table for all materials of the model (particle and barrier materials alike).
  void build(const Model& model);

  std::size_t materials() const { return n_; }
  // Particle of material a against particle of material b (symmetric).
  const PairLaw& particle_pair(std::size_t a, std::size_t b) const { return particle_pairs_[a * n_ + b]; }
  // Particle of material a against a barrier element of material b.
  const PairLaw& barrier_pair(std::size_t a, std::size_t b) const { return barrier_pairs_[a * n_ + b]; }
  const PairLaw* particle_pairs() const { return particle_pairs_.data(); }  // [n x n], row = first member
  // The laws the particle pairs and the barrier pairs use: the kernels are instantiated for one
  // law, or for a mix (MixedLaw).
  LawSet particle_laws() const { return particle_laws_; }
  LawSet barrier_laws() const { return barrier_laws_; }
  bool any_rolling() const { return rolling_; }  // some pair has mu_r > 0
  // Capillary bridges (contact/bridges/bridge_law.hpp), laid out as the laws: model none where
  // the scene has none.
  const BridgeLaw& particle_bridge(std::size_t a, std::size_t b) const { return particle_bridges_[a * n_ + b]; }
  const BridgeLaw& barrier_bridge(std::size_t a, std::size_t b) const { return barrier_bridges_[a * n_ + b]; }
  const BridgeLaw* particle_bridges() const { return particle_bridges_.data(); }  // [n x n], row = first member
  const BridgeLaw* barrier_bridges() const { return barrier_bridges_.data(); }    // [n x n], row = the particle's
  bool any_particle_bridges() const { return any_particle_bridges_; }
  bool any_barrier_bridges() const { return any_barrier_bridges_; }
  // m, the largest rupture distance of the particle pairs' (barrier pairs') bridges for particles
  // of radius <= r_max (m); 0 without bridges.
  double bridge_reach(double r_max) const;
  double barrier_bridge_reach(double r_max) const;

 private:
  std::size_t n_ = 0;
  std::vector<PairLaw> particle_pairs_, barrier_pairs_;  // [n x n], row = the particle's material
  LawSet particle_laws_ = 0, barrier_laws_ = 0;
  bool rolling_ = false;
  std::vector<BridgeLaw> particle_bridges_, barrier_bridges_;  // [n x n], row = the particle's material
  bool any_particle_bridges_ = false, any_barrier_bridges_ = false;
};

// The law of one pair from its effective moduli (Pa; Hertz-like laws) and resolved parameters
// (whose law and cohesion name a law of the list: the scene reader checked them): exposed for
// the tests, which evaluate the very constants the kernels use.
PairLaw resolve_pair_law(const ContactLawParams& p, double E_star, double G_star);

// The bridge law of resolved keys (LiquidBridgeKeys with the entries' overrides), model none
// when `on` is false or the model is "none"; the scene reader checked the keys.
BridgeLaw resolve_bridge_law(const LiquidBridgeKeys& k, bool on);

}  // namespace mpdem
