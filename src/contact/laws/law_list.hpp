#pragma once
// The one list of contact laws. Adding a law = its header (law_interface.hpp says what it
// provides) + one entry in ContactLaws; the contact table, the pair and barrier kernels, the
// mixed-law select, the scene reader, the per-pair override, the time-step advice, the
// impact-overlap check and the docs table (tests/contact/test_law_list.cpp) follow from it.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "contact/laws/dmt.hpp"
#include "contact/laws/hertz.hpp"
#include "contact/laws/jkr.hpp"
#include "contact/laws/law_interface.hpp"
#include "contact/laws/linear.hpp"
#include "contact/laws/sjkr.hpp"

namespace mpdem {

// The first law is the default (law = "hertz", no cohesion).
using ContactLaws = std::tuple<HertzLaw, LinearLaw, DmtLaw, JkrLaw, SjkrLaw>;

inline constexpr std::size_t kLawCount = std::tuple_size_v<ContactLaws>;

// f(std::type_identity<Law>{}, id) for every law, in list order.
template <class F>
constexpr void for_each_law(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::type_identity<std::tuple_element_t<I, ContactLaws>>{}, static_cast<LawId>(I)), ...);
  }
  (std::make_index_sequence<kLawCount>{});
}

template <class Law>
constexpr LawId law_id() {
  LawId id = -1;
  for_each_law([&]<class L>(std::type_identity<L>, LawId i) {
    if (std::is_same_v<L, Law>) id = i;
  });
  return id;
}

namespace law_list_detail {
template <class... Laws>
constexpr std::size_t largest_end(std::type_identity<std::tuple<Laws...>>) {
  std::size_t n = kLawSlots;
  ((n = Laws::kEnd > n ? Laws::kEnd : n), ...);
  return n;
}
}  // namespace law_list_detail

// Coefficient slots: the common ones and the largest law's own.
inline constexpr std::size_t kCoefficients = law_list_detail::largest_end(std::type_identity<ContactLaws>{});

// One material pair's law: which law, the tangential spring form, and every coefficient (slots
// of law_interface.hpp and the law's header). Built by resolve_pair_law (contact_table.hpp) only;
// the kernels copy `c` slot by slot in one loop.
struct PairLaw {
  LawId law = 0;
  // Incremental stores k_t s (N) instead of s (m), so that the next step's stiffness scales
  // only the increment (contact_law.hpp's tangential_contact).
  TangentialSpring spring = TangentialSpring::Total;
  std::array<double, kCoefficients> c{};  // units by slot
  double shear_root() const { return c[kShearRoot]; }
  double xi_n() const { return c[kXiN]; }
  double xi_t() const { return c[kXiT]; }
  double mu_s() const { return c[kMuS]; }
  double mu_d() const { return c[kMuD]; }
  double mu_r() const { return c[kMuR]; }
};

// A set of laws, one bit per LawId: the laws a contact table holds.
using LawSet = std::uint32_t;
static_assert(kLawCount <= 32, "LawSet has a bit per law");

// Every law of the list, one selected per pair by c.law (selects, not branches): serves a table
// that holds several laws.
struct MixedLaw {
  static constexpr bool kAdhesion = [] {
    bool any = false;
    for_each_law([&]<class L>(std::type_identity<L>, LawId) { any = any || L::kAdhesion; });
    return any;
  }();
  static constexpr bool kHysteresis = [] {
    bool any = false;
    for_each_law([&]<class L>(std::type_identity<L>, LawId) { any = any || L::kHysteresis; });
    return any;
  }();
  static constexpr bool kExactGeometry = [] {
    bool any = false;
    for_each_law([&]<class L>(std::type_identity<L>, LawId) { any = any || L::kExactGeometry; });
    return any;
  }();
  static Stiffness stiffness(const PairLaw& c, double r_star, double overlap, double inv_reach = 0.0) {
    Stiffness out = std::tuple_element_t<0, ContactLaws>::stiffness(c, r_star, overlap, inv_reach);
    for_each_law([&]<class L>(std::type_identity<L>, LawId id) {
      if constexpr (!std::is_same_v<L, std::tuple_element_t<0, ContactLaws>>) {
        const Stiffness s = L::stiffness(c, r_star, overlap, inv_reach);
        const bool here = c.law == id;
        out = {here ? s.k_n : out.k_n,
               here ? s.f_el : out.f_el,
               here ? s.k_t : out.k_t,
               here ? s.energy : out.energy,
               here ? s.clamp : out.clamp,
               here ? s.adhesion : out.adhesion,
               here ? s.load_offset : out.load_offset};
      }
    });
    return out;
  }
  // m, <= 0: the overlap at which a formed contact of the pair's law breaks (0: laws without hysteresis).
  static double break_overlap(const PairLaw& c, double r_star) {
    double out = 0.0;
    for_each_law([&]<class L>(std::type_identity<L>, LawId id) {
      if constexpr (L::kHysteresis) out = c.law == id ? L::break_overlap(c, r_star) : out;
    });
    return out;
  }
};

// m, <= 0: where a formed contact of Law breaks (0 for a law without hysteresis: at touching).
template <class Law>
double break_overlap(const PairLaw& c, double r_star) {
  if constexpr (Law::kHysteresis) return Law::break_overlap(c, r_star);
  else return 0.0;
}

// True when a law of the set keeps a formed state per contact (kHysteresis).
inline bool any_hysteresis(LawSet set) {
  bool any = false;
  for_each_law([&]<class L>(std::type_identity<L>, LawId id) { any = any || (L::kHysteresis && ((set >> id) & 1u)); });
  return any;
}

// f(std::type_identity<Law>{}) with the law of id (0 <= id < kLawCount).
template <class F>
decltype(auto) with_law(LawId id, F&& f) {
  using R = decltype(f(std::type_identity<std::tuple_element_t<0, ContactLaws>>{}));
  if constexpr (std::is_void_v<R>) {
    for_each_law([&]<class L>(std::type_identity<L>, LawId i) {
      if (i == id) f(std::type_identity<L>{});
    });
  } else {
    R r{};
    for_each_law([&]<class L>(std::type_identity<L>, LawId i) {
      if (i == id) r = f(std::type_identity<L>{});
    });
    return r;
  }
}

// f(std::type_identity<Law>{}) with the one law of the set, or MixedLaw for several (an empty
// set: the default law).
template <class F>
decltype(auto) with_laws(LawSet set, F&& f) {
  if (set != 0 && (set & (set - 1)) != 0) return f(std::type_identity<MixedLaw>{});
  return with_law(set == 0 ? 0 : static_cast<LawId>(std::countr_zero(set)), std::forward<F>(f));
}

// The law the scene keys `law` and `cohesion` select, or -1 when no law of the list has both.
inline LawId find_law(std::string_view law, std::string_view cohesion) {
  LawId out = -1;
  for_each_law([&]<class L>(std::type_identity<L>, LawId id) {
    if (L::kLaw == law && L::kCohesion == cohesion) out = id;
  });
  return out;
}

}  // namespace mpdem
