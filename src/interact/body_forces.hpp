#pragma once
// The body forces: uniform fields acting on every particle, one entry each in one compile-time
// list (BodyForces), applied in the one accumulation pass that starts an evaluation's force sums
// (Interactions::start_accumulators): no pass of their own, no virtual call per particle.
//
// An entry is a small struct built from the scene's [fields] (FieldParams) with
//   kEnergy          how its work enters the energy balance: a potential that the state scan sums
//                    (integrate/health_scan: gravity and electric), no work (the Lorentz force is
//                    normal to v), or dissipated: its power -F.v summed over the particles at every
//                    evaluation, booked by the trapezoid over committed steps into
//                    InteractionStats::field_dissipated (interact/interaction_stats.hpp)
//   on()             whether the scene turns it on (an entry that is off reads nothing)
//   force(p, i)      N, its force on owned particle i at the evaluated state (p: Particles, or
//                    Bodies for the clumps' bodies, which have the same arrays: mass, charge, v, fixed)
// Adding a body force: its formula in physics/field_forces.hpp, its key in FieldParams and the
// scene reader, one struct here and its name in BodyForces (docs/architecture.md).
#include <array>
#include <cstddef>
#include <tuple>
#include <utility>

#include "model/params.hpp"
#include "physics/field_forces.hpp"
#include "state/particles.hpp"

namespace mpdem {

enum class BodyEnergy { potential, no_work, dissipated };

struct GravityBodyForce {
  static constexpr BodyEnergy kEnergy = BodyEnergy::potential;  // -m g.x
  Vec3 g;                                                       // m/s^2
  explicit GravityBodyForce(const FieldParams& f) : g(f.gravity) {}
  static bool on() { return true; }  // the first entry: it starts every force sum
  template <class P>
  Vec3 force(const P& p, std::size_t i) const {
    return gravity_force(p.mass[i], g);
  }
};

struct ElectricBodyForce {
  static constexpr BodyEnergy kEnergy = BodyEnergy::potential;  // -q E.x
  Vec3 E;                                                       // V/m
  explicit ElectricBodyForce(const FieldParams& f) : E(f.electric) {}
  bool on() const { return norm2(E) > 0.0; }
  template <class P>
  Vec3 force(const P& p, std::size_t i) const {
    return electric_force(p.charge[i], E);
  }
};

struct MagneticBodyForce {
  static constexpr BodyEnergy kEnergy = BodyEnergy::no_work;
  Vec3 B;  // T
  explicit MagneticBodyForce(const FieldParams& f) : B(f.magnetic) {}
  bool on() const { return norm2(B) > 0.0; }
  template <class P>
  Vec3 force(const P& p, std::size_t i) const {
    return magnetic_force(p.charge[i], p.v[i], B);
  }
};

// Fixed particles keep their prescribed motion: the drag leaves them alone.
struct DragBodyForce {
  static constexpr BodyEnergy kEnergy = BodyEnergy::dissipated;
  double c;  // N s/m
  explicit DragBodyForce(const FieldParams& f) : c(f.drag) {}
  bool on() const { return c > 0.0; }
  template <class P>
  Vec3 force(const P& p, std::size_t i) const {
    return p.fixed[i] ? Vec3{} : drag_force(c, p.v[i]);
  }
};

template <class... E>
class BodyForceList {
 public:
  static constexpr std::size_t kCount = sizeof...(E);
  explicit BodyForceList(const FieldParams& f) : entries_(E(f)...) {
    std::size_t k = 0;
    ((on_[k++] = std::get<E>(entries_).on()), ...);
  }
  // Only the first entry (gravity) acts: the pass needs nothing but the masses.
  bool only_first() const {
    for (std::size_t k = 1; k < kCount; ++k)
      if (on_[k]) return false;
    return true;
  }
  // Some entry that dissipates acts: the pass sums its power.
  bool any_dissipated() const { return any_dissipated(std::index_sequence_for<E...>{}); }
  template <class P>
  Vec3 first_force(const P& p, std::size_t i) const {
    return std::get<0>(entries_).force(p, i);
  }
  // N, the sum of the acting entries' forces on particle i, as a right fold over the list
  // (f0 + (f1 + (f2 + ...))); adds their dissipated power -F.v (W) to `lost`.
  template <class P>
  Vec3 force(const P& p, std::size_t i, double& lost) const {
    Vec3 sum{};
    bool any = false;
    fold_right(p, i, lost, sum, any, std::index_sequence_for<E...>{});
    return sum;
  }

 private:
  template <std::size_t... I>
  bool any_dissipated(std::index_sequence<I...>) const {
    return ((on_[I] && std::tuple_element_t<I, std::tuple<E...>>::kEnergy == BodyEnergy::dissipated) || ...);
  }
  template <std::size_t I, class P>
  void add(const P& p, std::size_t i, double& lost, Vec3& sum, bool& any) const {
    if (!on_[I]) return;
    const Vec3 f = std::get<I>(entries_).force(p, i);
    if constexpr (std::tuple_element_t<I, std::tuple<E...>>::kEnergy == BodyEnergy::dissipated) lost -= dot(f, p.v[i]);
    sum = any ? f + sum : f;
    any = true;
  }
  template <class P, std::size_t... I>
  void fold_right(const P& p, std::size_t i, double& lost, Vec3& sum, bool& any, std::index_sequence<I...>) const {
    (add<kCount - 1 - I>(p, i, lost, sum, any), ...);  // last entry first
  }

  std::tuple<E...> entries_;
  std::array<bool, kCount> on_{};
};

// The list. Gravity stays first: it starts every force sum.
using BodyForces = BodyForceList<GravityBodyForce, ElectricBodyForce, MagneticBodyForce, DragBodyForce>;

// Whether the scene has a body force that dissipates (its work has a log column and a
// checkpoint section).
inline bool dissipative_fields(const FieldParams& f) { return BodyForces(f).any_dissipated(); }

}  // namespace mpdem
