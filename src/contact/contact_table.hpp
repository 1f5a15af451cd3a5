#pragma once
// ContactTable: the constants of every contact law for every pair of materials, resolved from
// the scene's [contact] defaults and [[contact.pair]] overrides (docs/scene.md "Contact") and
// the materials' elastic constants. The kernels index it by the two material indices; nothing
// per contact depends on names. Cheap to build (the restitution calibration is cached), so it
// is rebuilt from the model at every evaluation: a material edited between steps takes effect
// at the next one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/params.hpp"
#include "model/scene.hpp"

namespace mpdem {

// One material pair's law. 8-byte fields, so that the kernels' selects vectorise.
struct PairLaw {
  ContactLawKind law = ContactLawKind::Hertz;
  double cn = 0.0;          // Hertz: 2 E* (Pa), k_n = cn sqrt(r* delta); linear: k_n (N/m)
  double ct = 0.0;          // Hertz: 8 G* (Pa), k_t = ct sqrt(r* delta); linear: k_t (N/m)
  double shear_root = 0.0;  // -, sqrt(ct / cn) = sqrt(k_t / k_n)
  double xi_n = 0.0;        // -, normal damping ratio (50)
  double xi_t = 0.0;        // -, tangential damping ratio (67)
  double mu_s = 0.0;        // -, static friction (68)
  double mu_d = 0.0;        // -, dynamic friction (69)
  double mu_r = 0.0;        // -, rolling resistance (71)
  // The spring form; Incremental stores k_t s (N) instead of s (m), so that the next step's
  // stiffness scales only the increment (contact_law.hpp's tangential_contact).
  TangentialSpring spring = TangentialSpring::Total;
};

// Which laws a table holds: the kernels are instantiated for one law, or for a mix.
enum class LawMix { Hertz, Linear, Mixed };

class ContactTable {
 public:
  // Resolves the table for all materials of the model (particle and barrier materials alike).
  void build(const Model& model);

  std::size_t materials() const { return n_; }
  // Particle of material a against particle of material b (symmetric).
  const PairLaw& particle_pair(std::size_t a, std::size_t b) const { return pp_[a * n_ + b]; }
  // Particle of material a against a barrier element of material b.
  const PairLaw& barrier_pair(std::size_t a, std::size_t b) const { return pb_[a * n_ + b]; }
  const PairLaw* particle_pairs() const { return pp_.data(); }  // [n x n], row = first member
  LawMix particle_mix() const { return pp_mix_; }
  LawMix barrier_mix() const { return pb_mix_; }
  bool any_rolling() const { return rolling_; }  // some pair has mu_r > 0

 private:
  std::size_t n_ = 0;
  std::vector<PairLaw> pp_, pb_;  // [n x n]
  LawMix pp_mix_ = LawMix::Hertz, pb_mix_ = LawMix::Hertz;
  bool rolling_ = false;
};

// The law of one pair from its effective moduli (Pa; Hertz) and resolved parameters: exposed for
// the tests, which evaluate the very constants the kernels use.
PairLaw resolve_pair_law(const ContactLawParams& p, double E_star, double G_star);

}  // namespace mpdem
