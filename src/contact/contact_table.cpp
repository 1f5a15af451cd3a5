#include "contact/contact_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "physics/barrier_moduli.hpp"
#include "physics/hertz.hpp"
#include "physics/restitution.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

namespace {

// Whether a [[contact.pair]] entry names materials a and b (or the materials they are variants
// of) and applies to the contact kind.
bool applies(const Model& model, const ContactPairParams& e, std::size_t a, std::size_t b, bool particle_particle) {
  if (particle_particle ? !e.particle_particle : !e.particle_barrier) return false;
  const auto named = [&](std::size_t m, const std::string& name) {
    const Material& mat = model.materials[m];
    return mat.name == name || (mat.variant_of >= 0 && model.materials[mat.variant_of].name == name);
  };
  return (named(a, e.material_a) && named(b, e.material_b)) || (named(a, e.material_b) && named(b, e.material_a));
}

// The defaults of one contact kind with the overrides of every [[contact.pair]] entry that
// applies to materials a and b and that kind.
ContactLawParams pair_params(const Model& model, const ContactLawParams& defaults, std::size_t a, std::size_t b,
                             bool particle_particle) {
  ContactLawParams p = defaults;
  for (const ContactPairParams& e : model.params.contact.pairs) {
    if (!applies(model, e, a, b, particle_particle)) continue;
    if (e.law) p.law = *e.law;
    if (e.cohesion) p.cohesion = *e.cohesion;
    for (const auto& [key, value] : e.law_keys) p.law_keys.insert_or_assign(key, value);
    if (e.tangential_spring) p.tangential_spring = *e.tangential_spring;
    if (e.restitution || e.damping_ratio) {
      p.restitution = e.restitution;
      p.damping_ratio = e.damping_ratio;
    }
    if (e.mu_static) p.mu_static = *e.mu_static;
    if (e.mu_dynamic) p.mu_dynamic = *e.mu_dynamic;
    if (e.mu_rolling) p.mu_rolling = *e.mu_rolling;
    if (e.tangential_damping) p.tangential_damping = e.tangential_damping;
  }
  return p;
}

// The bridge of materials a and b for one contact kind: [liquid_bridge] (at barriers only with
// barriers = true), then every applying entry's liquid_bridge table, which turns bridges on.
BridgeLaw pair_bridge(const Model& model, std::size_t a, std::size_t b, bool particle_particle) {
  const LiquidBridgeParams& d = model.params.contact.liquid_bridge;
  LiquidBridgeKeys k = d.defaults.value_or(LiquidBridgeKeys{});
  bool on = d.defaults.has_value() && (particle_particle || d.barriers);
  for (const ContactPairParams& e : model.params.contact.pairs) {
    if (!e.liquid_bridge || !applies(model, e, a, b, particle_particle)) continue;
    k = overridden(k, *e.liquid_bridge);
    on = true;
  }
  return resolve_bridge_law(k, on);
}

double reach_of(const std::vector<BridgeLaw>& laws, double r_max, bool barrier) {
  double reach = 0.0;
  for (const BridgeLaw& l : laws) reach = std::max(reach, bridge_reach(l, r_max, barrier));
  return reach;
}

LawSet laws_of(const std::vector<PairLaw>& laws) {
  LawSet set = 0;
  for (const PairLaw& l : laws) set |= LawSet{1} << l.law;
  return set;
}

}  // namespace

PairLaw resolve_pair_law(const ContactLawParams& p, double E_star, double G_star) {
  PairLaw l;
  l.law = find_law(p.law, p.cohesion);
  if (l.law < 0)
    throw std::invalid_argument("no contact law has law = \"" + p.law + "\" and cohesion = \"" + p.cohesion + "\"");
  l.spring = p.tangential_spring;
  // The law's own slots, and its calibration of the damping ratio from the restitution.
  double xi_n = 0.0;
  with_law(l.law, [&]<class Law>(std::type_identity<Law>) {
    const auto own = Law::coefficients(LawInputs{E_star, G_star, &p});
    std::copy(own.begin(), own.end(), l.c.begin() + kLawSlots);
    if (p.damping_ratio) xi_n = *p.damping_ratio;
    else if (p.restitution) xi_n = Law::damping_ratio(*p.restitution);
  });
  const double k_n = l.c[kLawSlots], k_t = l.c[kLawSlots + 1];  // the law's normal and tangential constants
  // Without its own ratio the tangential dashpot takes the normal one: undamped, a contact that
  // starts with e < 1 sticks at first touch (the normal dashpot dominates the still tiny
  // spring force there) and the tangential impulse falls short of Coulomb's mu J_n.
  const std::array<double, kLawSlots> common{
      k_n > 0.0 ? std::sqrt(k_t / k_n) : 0.0,  // kShearRoot
      xi_n,                                    // kXiN
      p.tangential_damping.value_or(xi_n),     // kXiT
      p.mu_static,                             // kMuS
      p.mu_dynamic,                            // kMuD
      p.mu_rolling,                            // kMuR
  };
  std::copy(common.begin(), common.end(), l.c.begin());
  return l;
}

BridgeLaw resolve_bridge_law(const LiquidBridgeKeys& k, bool on) {
  const std::string model = k.model.value_or(LiquidBridgeKeys::kModel);
  BridgeLaw b;
  if (!on || model == "none") return b;
  if (model == "willett") b.model = BridgeModel::willett;
  else if (model == "rabinovich") b.model = BridgeModel::rabinovich;
  else throw std::invalid_argument("no liquid bridge model is called \"" + model + "\"");
  b.surface_tension = k.surface_tension.value_or(0.0);
  b.contact_angle = k.contact_angle.value_or(0.0);
  b.volume = k.volume.value_or(0.0);
  b.liquid_fraction = k.liquid_fraction.value_or(0.0);
  b.viscosity = k.viscosity.value_or(0.0);
  b.min_gap = k.min_gap.value_or(LiquidBridgeKeys::kMinGap);
  return b;
}

double ContactTable::bridge_reach(double r_max) const { return reach_of(particle_bridges_, r_max, false); }
double ContactTable::barrier_bridge_reach(double r_max) const { return reach_of(barrier_bridges_, r_max, true); }

void ContactTable::build(const Model& model) {
  const std::vector<Material>& mats = model.materials;
  n_ = mats.size();
  particle_pairs_.resize(n_ * n_);
  barrier_pairs_.resize(n_ * n_);
  particle_bridges_.resize(n_ * n_);
  barrier_bridges_.resize(n_ * n_);
  rolling_ = false;
  for (std::size_t a = 0; a < n_; ++a) {
    const Material& ma = mats[a];
    // Rigid materials (E = +inf) are barrier elements' only: a pair with a rigid particle side is
    // never looked up and gets zero moduli rather than the NaN of inf/inf.
    const bool rigid_a = is_rigid(ma);
    const double ca = (1.0 - ma.poisson * ma.poisson) / ma.young;                // (51)
    const double sa = (2.0 - ma.poisson) / shear_modulus(ma.young, ma.poisson);  // Mindlin G*
    for (std::size_t b = 0; b < n_; ++b) {
      const Material& mb = mats[b];
      const double cb = (1.0 - mb.poisson * mb.poisson) / mb.young;
      const double sb = (2.0 - mb.poisson) / shear_modulus(mb.young, mb.poisson);
      const bool pp_used = !rigid_a && !is_rigid(mb);
      // Particle pairs: E* = 1 / (sum of the members' compliances) (51), G* likewise.
      particle_pairs_[a * n_ + b] = resolve_pair_law(
          pair_params(model, model.params.contact.particle_particle, a, b, true), pp_used ? 1.0 / (ca + cb) : 0.0,
          pp_used ? 1.0 / (sa + sb) : 0.0);
      // A particle against the half-space of the barrier's material, or a rigid barrier (section 7).
      barrier_pairs_[a * n_ + b] = resolve_pair_law(
          pair_params(model, model.params.contact.particle_barrier, a, b, false),
          rigid_a ? 0.0 : barrier_effective_modulus(ma.young, ma.poisson, mb.young, mb.poisson),
          rigid_a ? 0.0 : barrier_effective_shear_modulus(ma.young, ma.poisson, mb.young, mb.poisson));
      rolling_ = rolling_ || particle_pairs_[a * n_ + b].mu_r() > 0.0 || barrier_pairs_[a * n_ + b].mu_r() > 0.0;
      particle_bridges_[a * n_ + b] = pair_bridge(model, a, b, true);
      barrier_bridges_[a * n_ + b] = pair_bridge(model, a, b, false);
    }
  }
  const auto any = [](const std::vector<BridgeLaw>& v) {
    return std::any_of(v.begin(), v.end(), [](const BridgeLaw& l) { return l.model != BridgeModel::none; });
  };
  any_particle_bridges_ = any(particle_bridges_);
  any_barrier_bridges_ = any(barrier_bridges_);
  particle_laws_ = laws_of(particle_pairs_);
  barrier_laws_ = laws_of(barrier_pairs_);
}

}  // namespace mpdem
