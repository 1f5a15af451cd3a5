#pragma once
// Inlets: the particles a scene's [[inlet]] entries insert during the run (docs/scene.md
// "[[inlet]]"), decided between steps from the state then.
//
// An inlet inserts at its insertion times t_k = start + k interval (t_k < end), each at the first
// step end at or after it, what is due up to the next one: mass_rate (or count_rate) x
// (min(t_k + interval, end) - start) in all, less what it inserted before. The particles come
// one by one: the next radius is drawn ahead and inserted while the inlet's total stays within
// half that particle of what is due, at a random position of its volume where it overlaps no
// particle and no active barrier element (InsertionSpace). A particle that finds no room in
// max_attempts positions ends the insertion time: what is still due is the inlet's shortfall,
// logged and carried to the next insertion time, never dropped.
//
// Deterministic: insertion time k of inlet j draws from its own Rng seeded by (seed, j, k), and
// the state that decides the next insertion (the next k, the totals, the radius drawn ahead, the
// next id) is checkpointed (section "inlets"), so a resumed run inserts bitwise the same
// particles. Ids continue after the largest id the run has had (never one a removed particle had).
//
// An inlet with `clump` inserts whole rigid bodies the same way (inlet_bodies.hpp): the next
// body's template is drawn from a stream of its own, seeded by (seed, j, n) for the inlet's n-th
// body, so that it is known ahead without being checkpointed; a mass rate counts the bodies' mass,
// a count rate the bodies.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "generate/region.hpp"
#include "core/binary_stream.hpp"
#include "model/scene.hpp"

namespace mpdem {

// m, the world box [lo, hi] holding the centres of the particles of radius `inset` (m) an inlet can
// place in `vol` (inset 0: the volume itself); tight for boxes, cylinders and discs. False when
// no such particle fits.
bool inlet_centre_box(const InsertionVolume& vol, double inset, Vec3& lo, Vec3& hi);
// m, the world box of the centres of an inlet's smallest particles (they come nearest its faces);
// the volume itself when they do not fit. For the checks before the run.
void smallest_centre_box(const InletSpec& in, Vec3& lo, Vec3& hi);

class Inlets {
 public:
  // The scene's inlets (model.params.inlets); `p`: the particles at the start (the first id).
  Inlets(const Model& model, const Particles& p);

  // The particles every inlet inserts at the step end at time t (s), given the particles and
  // barriers then: appended by the caller (Interactions::add_particles). Empty when none is due.
  Particles insert(double t, const Particles& p, const Barriers& b);
  // Whether some inlet has an insertion time due at the step end at t (s): insert() places
  // particles or reports a shortfall.
  bool due(double t) const;
  // m, the box [lo, hi] holding every centre of a particle of radius up to `radius` (m) that
  // reaches into an inlet's volume: insert() looks at no other particle (InsertionSpace), so a
  // decomposed run gathers only those (docs/parallel.md).
  void reach(double radius, Vec3& lo, Vec3& hi) const;

  // J, kinetic + rotational + potential energy the inserted particles brought in (the energy
  // balance takes it off, as it adds what removed particles take along).
  double inserted_energy() const { return inserted_energy_; }
  // Ids: the next inserted particle's (members included), and numbering after `id` (particles
  // added by other means). An inlet with `clump` numbers its bodies after the largest body id the
  // run has had.
  std::int64_t next_id() const { return next_id_; }
  void ids_after(std::int64_t id) { next_id_ = std::max(next_id_, id + 1); }
  // Global log: per inlet "<name>.inserted" (-), "<name>.inserted_mass" (kg), "<name>.shortfall"
  // (kg with mass_rate, particles with count_rate).
  static std::vector<std::string> log_columns(const Params& prm);
  void log_values(std::vector<double>& out) const;  // appends one value per column
  std::string summary() const;                      // one line for stderr, "" when nothing inserted
  void save(BinaryWriter& w) const;                 // checkpoint section "inlets" (+ the next body id with clumps)
  void restore(BinaryReader& r);

  struct State {                 // of one inlet (checkpointed byte for byte)
    std::uint64_t next_k = 0;    // index of its next insertion time
    std::uint64_t inserted = 0;  // particles (bodies with clump) inserted
    double inserted_mass = 0.0;  // kg
    double shortfall = 0.0;      // kg or particles (bodies): due but not placed at the last insertion time
    double next_radius = 0.0;    // m, radius of the next particle (0: not drawn yet; 0 with clump)
  };
  const std::vector<State>& states() const { return state_; }

 private:
  struct Inlet {
    const InletSpec* spec;
    Region region;    // the volume in its frame coordinates
    int material;     // index into Model::materials
    double density;   // kg/m^3
    double end;       // s, end of the insertions
    double interval;  // s (a default one: the checkpoint's after a resume)
    Vec3 lo, hi;      // m, world bounding box of the volume
  };
  bool due(std::size_t j, double t) const;
  // Inserts inlet j's particles (bodies with `clump`) due at its insertion time k into `fresh`.
  void insert_due(std::size_t j, std::uint64_t k, const Particles& p, const Barriers& b, Particles& fresh);
  void insert_due_bodies(std::size_t j, std::uint64_t k, const Particles& p, const Barriers& b, Particles& fresh);
  bool any_clump() const;  // some inlet inserts bodies

  const Model& model_;
  std::vector<Inlet> inlets_;
  std::vector<State> state_;       // [inlets]
  std::int64_t next_id_ = 0;       // id of the next inserted particle
  std::int64_t next_body_id_ = 0;  // id of the next inserted body
  double inserted_energy_ = 0.0;   // J
};

}  // namespace mpdem
