#pragma once
// HaloExchange: the particles of the neighbouring bricks (BrickGrid) that a rank's owned
// particles can touch, as ghost particles after the owned ones (state/particles.hpp), and the
// migration of owned particles to the rank whose brick they entered (docs/parallel.md).
//
// Ghosts are chosen in stages, one per decomposed or periodic axis (x, then y, then z), two swaps
// per stage: the particles within `width` of the brick's lower face go to the lower neighbour,
// those within `width` of its upper face to the upper one, each stage choosing from the owned
// particles and the ghosts of the earlier stages, so that edge and corner neighbours' particles
// arrive in two or three hops. Crossing a periodic face shifts a ghost by the period; along a
// periodic axis with one brick the neighbour is the rank itself (its own periodic images).
//
// Each evaluation refreshes the ghosts from their sources (the stages in order) and afterwards
// sends what the ghosts received back to their sources (the stages in reverse, and within a
// stage the upper swap's first), where it is added in the order the ghosts were sent: the sums
// depend on the rank count, never on timing. The two swaps of a stage travel at once (both
// choose from what the rank held before the stage, so neither waits for the other's ghosts).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "parallel/attached_records.hpp"
#include "parallel/brick_grid.hpp"
#include "parallel/communicator.hpp"
#include "parallel/load_balance.hpp"
#include "state/particles.hpp"

namespace mpdem {

class HaloExchange {
 public:
  HaloExchange(const Communicator& comm, BrickGrid grid);

  const BrickGrid& grid() const { return grid_; }
  const Communicator& comm() const { return *comm_; }
  // True when the rank exchanges particles with another rank or with itself (periodic images).
  bool active() const { return !stages_.empty(); }

  // Between steps, on owned particles only: sends every particle that left this rank's brick to
  // the neighbour whose brick it entered (per axis, so a diagonal move takes two or three hops)
  // and appends those that entered this one after the particles that stayed (whose order is
  // kept); contact history follows by id. A clump's members go where its body's centre goes,
  // with the body's row of p.bodies, in the same message (parallel/body_ownership.hpp); the
  // records of `attached` are anchored by particle ids, those of `body_attached` by body ids.
  // Throws std::runtime_error naming the particle (or body) when one moved past a neighbouring
  // brick since the last migration.
  void migrate(Particles& p, std::span<AttachedRecords* const> attached = {},
               std::span<AttachedRecords* const> body_attached = {});
  // Chooses and appends the ghosts of the owned centres within `width` (m) of the brick faces.
  // Throws std::invalid_argument when a brick is narrower than `width` along a decomposed axis
  // (ghosts would be needed from beyond the neighbours) or a periodic period shorter than 2 width.
  void build(Particles& p, double width);
  // Copies the sources' motion state (x, v, w, and T with temperatures(true): what a step
  // changes that an interaction reads) onto the ghosts and clears the ghosts' accumulators; the
  // other arrays were copied at the build.
  void refresh(Particles& p) const;
  // Adds the ghosts' force and torque, and heat with temperatures(true), to their sources (on
  // whichever rank they live).
  void fold(Particles& p) const;
  // Whether refresh and fold carry temperatures and heat flows (heat transfer on; default true).
  void temperatures(bool on) { temperatures_ = on; }

  // Between steps (before a migration): moves the cut planes to balance the ranks' cost
  // (parallel/load_balance.hpp: shift_cuts, `x` the owned centres, `min_width` the halo's reach).
  // True when a cut moved. Collective.
  bool shift_cuts(std::span<const Vec3> x, double cost, double min_width) {
    return mpdem::shift_cuts(grid_, *comm_, x, cost, min_width);
  }

  std::size_t size() const { return ghosts_; }
  std::uint64_t migrated() const { return migrated_; }                // particles this rank sent to another
  std::uint64_t migrated_bodies() const { return migrated_bodies_; }  // bodies this rank sent to another

 private:
  struct Swap {
    int axis = 0;
    int send_to = -1;                 // rank receiving this rank's particles (-1: none)
    int recv_from = -1;               // rank whose particles arrive (-1: none)
    Vec3 shift{};                     // m, added to the sent centres (a periodic face crossed)
    std::vector<std::uint32_t> send;  // local indices sent (owned or ghosts of earlier stages)
    std::size_t recv_first = 0;       // first ghost index received
    std::size_t recv_count = 0;
    int tag = 0;
  };
  const Communicator* comm_;
  BrickGrid grid_;
  std::vector<int> stages_;  // axes exchanged, in order
  std::vector<Swap> swaps_;  // two per stage
  std::size_t ghosts_ = 0;
  std::uint64_t migrated_ = 0;
  std::uint64_t migrated_bodies_ = 0;
  bool temperatures_ = true;
};

}  // namespace mpdem
