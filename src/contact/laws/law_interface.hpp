#pragma once
// What every contact law (contact/laws/<law>.hpp) provides. The one record of a pair's resolved
// constants, PairLaw, is sized from the laws (law_list.hpp), so the laws take it as a template.
//
// A law is a type with (see hertz.hpp for the smallest complete one):
//   kLaw, kCohesion        the values of the scene keys `law` and `cohesion` that select it
//   kKeys                  its own scene keys (LawKey: name, unit, range, default)
//   kEnd                   one past its last coefficient slot (slots kLawSlots.. are its own, named)
//   kElastic               its stiffness comes from the materials' E and nu (Hertz-like): the
//                          Rayleigh time and the material modulus drive the time-step advice
//   kAdhesion              the force may be attractive (stiffness() fills Stiffness::adhesion
//                          and Stiffness::load_offset)
//   kHysteresis            a contact, formed when the surfaces touch (overlap > 0), holds until
//                          the overlap falls to break_overlap(c, r*) <= 0 (JKR's neck): the
//                          kernels keep a formed flag per contact beside the tangential spring,
//                          reach that far beyond touching, and book the energy the contact held
//                          when it breaks (stiffness(..., break_overlap).energy) as dissipated
//   coefficients(in)       its own slots (law_slots) from the materials' moduli and its keys (LawInputs)
//   damping_ratio(e)       the normal damping ratio that gives restitution e
//   kExactGeometry         stiffness() reads k below (the pair kernel computes it only then)
//   stiffness(c, r*, d, k) k_n, the elastic force, k_t and the stored energy at overlap d >= 0
//                          (kHysteresis: d >= break_overlap); k = 1 / (R_i + R_j) (m^-1, 0 at a
//                          barrier) for laws that need the exact geometry of the overlap (SJKR's
//                          lens); k_n is what the dashpot and the time step use (finite, >= 0)
//   contact_time(...)      the duration of an undamped impact, for the time-step advice
//   peak_overlap(...)      the largest overlap of an undamped impact, for checks.max_overlap
// Everything else of a contact (the damping from the ratio, the projected spring, Coulomb's
// stick and slip, rolling resistance) is shared: contact/contact_law.hpp. These are the slots of
// LAMMPS GRANULAR's sub-models: normal (stiffness), damping (damping_ratio, shared dashpot),
// tangential and rolling (shared, by the common coefficients), adhesion (kAdhesion).
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "core/value_range.hpp"
#include "model/params.hpp"

namespace mpdem {

// The coefficient slots every law has, then the law's own from kLawSlots on. A law's first two
// slots are its normal and tangential constants with k_t / k_n = c[kLawSlots + 1] / c[kLawSlots]
// at every overlap (the shared tangential damping takes d_n's root, contact_law.hpp).
enum CoefficientSlot : std::size_t {
  kShearRoot,  // -, sqrt(k_t / k_n)
  kXiN,        // -, normal damping ratio (50)
  kXiT,        // -, tangential damping ratio (67)
  kMuS,        // -, static friction (68)
  kMuD,        // -, dynamic friction (69)
  kMuR,        // -, rolling resistance (71)
  kLawSlots    // the first of the law's own slots
};
using LawId = std::int64_t;  // the law's position in ContactLaws (law_list.hpp); 8 bytes for the selects

// A law's normal spring at one overlap.
struct Stiffness {
  double k_n = 0.0;       // N/m, normal stiffness dF/d(delta)
  double f_el = 0.0;      // N, elastic normal force (attractive part included)
  double k_t = 0.0;       // N/m, tangential stiffness
  double energy = 0.0;    // J, stored energy of the normal force (its potential, 0 at touching)
  bool clamp = true;      // the net normal force is kept >= -adhesion (no more attractive)
  double adhesion = 0.0;  // N, >= 0, the pull-off: the floor of the net normal force (kAdhesion laws only)
  // N, >= 0, what Coulomb's limit and rolling resistance add to the net normal force: they scale
  // with max(fn + load_offset, 0) (kAdhesion laws only; DMT: the adhesion, JKR: 2 F_c as Thornton)
  double load_offset = 0.0;
};

// One scene key of a law, under [contact.*] and [[contact.pair]] (docs/scene.md "Contact laws").
struct LawKey {
  std::string_view name;
  std::string_view unit;
  Range range;                     // accepted values
  std::optional<double> fallback;  // the default; none: the law computes it, or requires the key
  bool required = false;           // the law needs the key (the reader refuses a scene without it)
  std::string_view default_text;   // the default as docs/scene.md states it ("2/7 stiffness_normal", "0")
  std::string_view meaning;
};

// What a law resolves its coefficients from: the pair's effective moduli and its keys.
struct LawInputs {
  double E_star = 0.0;  // Pa, effective modulus (51) (barrier: (76)-(79))
  double G_star = 0.0;  // Pa, effective shear modulus (Mindlin)
  const ContactLawParams* params = nullptr;
  // The key's value as given, else its default (nullopt: neither).
  std::optional<double> key(const LawKey& k) const {
    const auto it = params->law_keys.find(k.name);
    return it != params->law_keys.end() ? std::optional<double>(it->second) : k.fallback;
  }
};

// The law's own slots, all of them: a missing or extra value does not compile.
template <class Law, class... V>
constexpr std::array<double, Law::kEnd - kLawSlots> law_slots(V... v) {
  static_assert(sizeof...(V) == Law::kEnd - kLawSlots, "give every slot of the law");
  return {static_cast<double>(v)...};
}

}  // namespace mpdem
