#pragma once
// Wet, adhesive test scenes (contact/cohesive_contact.hpp): JKR necks and Willett bridges on
// every contact.
#include "model/scene.hpp"

namespace mpdem::test {

// Gives every contact of `s` JKR adhesion (surface energy w, J/m^2; restitution e) and every pair
// and barrier contact Willett bridges of surface tension gamma (N/m) holding `fraction` of the
// particles' volume (docs/scene.md "[liquid_bridge]").
inline void make_wet(Scene& s, double w, double e, double gamma, double fraction) {
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->cohesion = "jkr";
    c->law_keys["surface_energy"] = w;
    c->restitution = e;
  }
  LiquidBridgeKeys k;
  k.surface_tension = gamma;
  k.liquid_fraction = fraction;
  s.model.params.contact.liquid_bridge.defaults = k;
}

}  // namespace mpdem::test
