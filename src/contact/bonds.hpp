#pragma once
// Bonds: the parallel bonds of a run (physics/parallel_bond.hpp, docs/physics.md "Parallel
// bonds"). A bond is its own object, not a contact: it exists whether or not its particles touch,
// and the contact law acts alongside it when they overlap. Each bond is keyed by its particles'
// ids and finds them by id (owned ones first, else a ghost: a periodic image or, on several
// ranks, the halo), so that reordering, removals and migrations never touch it; on several ranks
// a bond lives on the rank of its lower-id particle and travels with it.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "contact/eval_request.hpp"
#include "core/binary_stream.hpp"
#include "core/vec3.hpp"
#include "model/scene.hpp"
#include "physics/parallel_bond.hpp"
#include "state/particles.hpp"

namespace mpdem {

// One bond's identity and incremental state, as checkpoints, migrations and the Python module
// carry it (trivially copyable). Forces and moments are those on particle j (ids id_i < id_j);
// particle i takes the opposite force and the opposite moment plus the lever arms'.
struct BondRecord {
  std::int64_t id_i = 0, id_j = 0;  // particle ids, id_i < id_j
  double radius = 0.0;              // m, R_b = lambda min(R_i, R_j)
  double length = 0.0;              // m, L: the centre distance when the bond was made
  double fn = 0.0;                  // N, normal force (> 0 compression)
  double mn = 0.0;                  // N m, twisting moment about the normal
  Vec3 fs{};                        // N, shear force (normal to the bond)
  Vec3 ms{};                        // N m, bending moment (normal to the bond)
  Vec3 normal{};                    // -, unit, from i to j at the last commit (0: not yet evaluated)
  Vec3 v_start{};           // m/s, relative velocity at the bond at the last commit (the trapezoidal rule's step start)
  Vec3 w_start{};           // rad/s, relative angular velocity at the last commit
  std::uint8_t intact = 1;  // 0: broken (kept for the outputs, no longer acts)
  std::uint8_t pad[7]{};
};
static_assert(sizeof(BondRecord) == 176);

// The bonds' order: by their particles' ids (id_i, then id_j).
inline bool bond_before(const BondRecord& a, const BondRecord& b) {
  return a.id_i != b.id_i ? a.id_i < b.id_i : a.id_j < b.id_j;
}

// How a bond broke: its tensile or its shear stress reached the strength.
enum class BondBreakMode : std::uint8_t { tension, shear };

// A bond that broke at a committed evaluation.
struct BondBreak {
  double time = 0.0;  // s
  std::int64_t id_i = 0, id_j = 0;
  BondBreakMode mode = BondBreakMode::tension;
  double sigma = 0.0;  // Pa, sigma_max at the break
  double tau = 0.0;    // Pa, tau_max at the break
};

// What an evaluation of the bonds adds to the statistics.
struct BondStats {
  std::uint64_t intact = 0;    // bonds that act after the evaluation
  std::uint64_t broken = 0;    // bonds that broke at this (committed) evaluation
  double energy = 0.0;         // J, held by the intact bonds' springs
  double damping_power = 0.0;  // W, dissipated by their dashpots
  double broken_energy = 0.0;  // J, held by the bonds that broke, when they broke
};

class Bonds {
 public:
  // The laws of the scene's pairs of materials (model.params.bonds); no bond yet.
  explicit Bonds(const Model& model);

  // Adds a bond between the particles of ids a != b (either order) at their present positions
  // (radius and length from them); p holds both (owned). Returns its index.
  std::size_t add(const Particles& p, std::size_t a, std::size_t b);
  // The bonds made at t = 0 by the scene ([bonds] gap rule and file).
  void make(const Particles& p);

  // Adds the bonds' forces and torques to p (before the ghosts are folded onto their sources);
  // a commit evaluation stores the new state, breaks what reaches its strength and records it.
  // Within the trapezoidal rule's iterations (req.iteration > 0) a bond whose trial state passed
  // its strength stays broken for the rest of the step and breaks at its commit.
  BondStats evaluate(Particles& p, const EvalRequest& req);

  std::size_t size() const { return bonds_.size(); }
  std::size_t intact() const;
  bool empty() const { return bonds_.empty(); }
  std::span<const BondRecord> records() const { return bonds_; }
  // The breaks recorded since the last call, in bond order (the outputs drain them).
  std::vector<BondBreak> take_breaks();
  const std::vector<BondBreak>& breaks() const { return breaks_; }

  // Bonds of removed particles go with them (ids: the removed particles').
  void remove_particles(std::span<const std::int64_t> ids);
  // Several ranks: keeps the bonds whose lower-id particle p owns.
  void keep_owned(const Particles& p);
  // m, the largest bond length (the halo must reach the partner of every bond).
  double longest() const;
  // Migration and gathering: the records, and the records put back.
  std::vector<BondRecord> export_records() const { return bonds_; }
  void import_records(std::vector<BondRecord> r);
  // Checkpoint section "bonds": the records in id order.
  void save(BinaryWriter& o) const;
  static void save_records(BinaryWriter& o, std::vector<BondRecord> r);
  void restore(BinaryReader& in);

 private:
  // The particles of every bond by index: bonds' ii_/jj_ checked against the ids, and looked up
  // anew when any moved (a rebuild, a removal, an addition).
  void resolve(const Particles& p);
  // A new bond's record between particles a and b of p, at their present positions.
  BondRecord made(const Particles& p, std::size_t a, std::size_t b) const;
  bool resolved(const Particles& p) const;
  std::size_t law_index(const Particles& p, std::size_t i, std::size_t j) const {
    return static_cast<std::size_t>(p.material[i]) * materials_ + static_cast<std::size_t>(p.material[j]);
  }

  const Model& model_;
  Vec3 period_{};  // m, the domain's period per axis (0: not periodic), for the nearest image
  std::size_t materials_ = 0;
  std::vector<BondLaw> laws_;           // [materials x materials], by the particles' material indices
  std::vector<BondRecord> bonds_;       // [bonds], sorted by (id_i, id_j)
  std::vector<std::uint32_t> ii_, jj_;  // [bonds] the particles' indices at the last resolve (jj_: maybe a ghost)
  // Per evaluation: [bonds] the force on j (N) and the torques on i and j (N m), added in bond order.
  struct Result {
    Vec3 f, ti, tj;
  };
  std::vector<Result> results_;
  struct Stress {
    double sigma, tau;  // Pa, at a break
  };
  std::vector<Stress> stress_;  // [bonds] at a break (or when it passed its strength within the step)
  // [bonds] 1: a trial state of this step's iterations passed the bond's strength; it acts no more
  // in the step and breaks at the commit (reset by the step's first iteration and by the commit).
  std::vector<std::uint8_t> latched_;
  std::vector<std::uint8_t> acting_;  // [bonds] 1: the bond's force acts at this evaluation
  std::vector<BondBreak> breaks_;     // since the last take_breaks
};

}  // namespace mpdem
