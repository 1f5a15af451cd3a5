// Simulation over several ranks (docs/parallel.md): the decomposition of the scene, the global
// scans and statistics, the particles gathered (or written in pieces) for output, the collective
// step controls.
#include <fmt/core.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "output/output_manager.hpp"
#include "io/pvtu_writer.hpp"
#include "parallel/body_ownership.hpp"
#include "parallel/brick_grid.hpp"
#include "parallel/gather.hpp"
#include "parallel/particle_buffer.hpp"
#include "sim/simulation.hpp"

#include "core/run_error.hpp"
#include "neighbor/neighbor_search.hpp"
#include "sim/inlets.hpp"
#include "sim/step_collective.hpp"
#include "sim/stop_signal.hpp"

namespace mpdem {

void Simulation::decompose(const Communicator& comm) {
  Particles& p = scene_.particles;
  const DomainParams& d = scene_.model.params.domain;
  // The bricks tile the domain; without one, the particles' bounding box (the outer bricks reach
  // to infinity, so this only places the cuts). Every rank loaded the whole scene: the same box.
  Vec3 lo = d.min, hi = d.max;
  if (!d.bounded) {
    lo = Vec3{1, 1, 1} * std::numeric_limits<double>::infinity();
    hi = -lo;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], p.x[i][c]);
        hi[c] = std::max(hi[c], p.x[i][c]);
      }
    if (p.size() == 0) lo = hi = Vec3{};
  }
  const BrickGrid grid(comm.size(), lo, hi, d.periodic);
  // A clump's members belong to the rank of its centre, wherever they reach: the halo grows by
  // twice the largest distance of a member from its body's centre (docs/parallel.md "Clumps").
  double member_reach = 0.0;  // m
  for (std::size_t b = 0; b < p.bodies.size(); ++b)
    for (const ClumpMember& m : scene_.model.clumps[static_cast<std::size_t>(p.bodies.clump[b])].members())
      member_reach = std::max(member_reach, norm(m.x));
  keep_owned(grid, p, comm.rank());
  interactions_->keep_owned_bonds(p);
  comm_ = &comm;
  interactions_->decompose(comm, grid, 2.0 * member_reach);
  trapezoidal_.set_communicator(&comm);
  // The trapezoidal predictor's previous rates follow their particles (and bodies) to their new rank.
  RateHistory& rates = trapezoidal_.rate_history();
  interactions_->set_travelling({[&rates] {
                                   AttachedRecords a = AttachedRecords::of<RateRecord>();
                                   for (const RateRecord& r : rates.records()) a.push(r.id, r);
                                   return a;
                                 },
                                 [&rates](const AttachedRecords& a) {
                                   std::vector<RateRecord> r(a.size());
                                   for (std::size_t k = 0; k < a.size(); ++k) r[k] = a.get<RateRecord>(k);
                                   rates.set_records(std::move(r), rates.dt());
                                 }},
                                {[this] {
                                   AttachedRecords a = AttachedRecords::of<RateRecord>();
                                   for (const RateRecord& r : trapezoidal_.bodies().records(scene_.particles.bodies))
                                     a.push(r.id, r);
                                   return a;
                                 },
                                 [this, &rates](const AttachedRecords& a) {
                                   std::vector<RateRecord> r(a.size());
                                   for (std::size_t k = 0; k < a.size(); ++k) r[k] = a.get<RateRecord>(k);
                                   // The particles' step length: a rank that held no body kept none.
                                   trapezoidal_.bodies().set_records(r, scene_.particles.bodies, rates.dt());
                                 }});
}

const StepCollective& Simulation::reduce_step(const HealthScan& s, double h) {
  StepCollective& t = step_collective_;
  t = StepCollective{};
  t.stats = interactions_->stats();
  t.particles = scene_.particles.size();
  t.scan = s;
  t.deepest = interactions_->max_overlap(scene_.particles, scene_.barriers);
  snapshots_h_ = -1.0;
  if (!comm_) return t;
  t.stop = stop_signal();
  if (output_ && h >= 0.0) {
    // What snapshots(h, false) will ask after this step: the output series change only there.
    const ParticleSnapshotsDue due = output_->particles_due(time_, h, false);
    t.vtu = due.vtu;
    t.csv = due.csv;
    t.vtu_index = due.vtu_index;
    t.body_csv = due.body_csv;
    t.bonds = due.bonds;
  }
  if (const Bonds* b = interactions_->bonds()) t.bond_breaks = b->breaks().size();
  const bool loads = interactions_->barrier_loads_pending();
  if (loads) t.loads = interactions_->barrier_loads(scene_.barriers);
  t = combine_over_ranks(*comm_, t);
  interactions_->end_step_loads(scene_.barriers, t.loads);
  if (h >= 0.0) {
    snapshots_time_ = time_;
    snapshots_h_ = h;
  }
  return t;
}

const InteractionStats& Simulation::stats() const { return comm_ ? step_collective_.stats : interactions_->stats(); }

namespace {
// The particles of the ranks' messages (pack_particles, each followed by its bodies with
// `bodies`: pack_bodies), in id order: what is written or decided from them does not depend on
// the rank count.
Particles in_id_order(const std::vector<std::vector<std::byte>>& messages, bool bodies = false) {
  Particles all;
  for (const auto& bytes : messages) {
    std::size_t pos = 0;
    unpack_particles(all, bytes, pos);
    if (bodies) unpack_bodies(all.bodies, bytes, pos);
  }
  all.sort_by_id();
  all.bodies.sort_by_id();
  return all;
}

std::vector<std::uint32_t> all_of(std::size_t n) {
  std::vector<std::uint32_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::uint32_t{0});
  return idx;
}
}  // namespace

Particles Simulation::gathered() {
  Particles& p = scene_.particles;
  std::vector<std::byte> mine;
  pack_particles(p, all_of(p.size()), {}, mine);
  pack_bodies(p.bodies, all_of(p.bodies.size()), mine);
  return in_id_order(comm_->gather(mine, 0), true);
}

Particles Simulation::near_inlets() {
  Particles& p = scene_.particles;
  double rmax = 0.0;  // m
  for (std::size_t i = 0; i < p.size(); ++i) rmax = std::max(rmax, p.radius[i]);
  Vec3 lo, hi;
  inlets_->reach(comm_->max(rmax), lo, hi);
  std::vector<std::uint32_t> idx;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i].x >= lo.x && p.x[i].x <= hi.x && p.x[i].y >= lo.y && p.x[i].y <= hi.y && p.x[i].z >= lo.z &&
        p.x[i].z <= hi.z)
      idx.push_back(static_cast<std::uint32_t>(i));
  std::vector<std::byte> mine;
  pack_particles(p, idx, {}, mine);
  return in_id_order(comm_->all_gather(mine));
}

void Simulation::keep_own(Particles& fresh) const {
  keep_owned(interactions_->search().halo()->grid(), fresh, comm_->rank());
}

ParticleSnapshotsDue Simulation::particles_due(double h, bool force) {
  // Decided with the step's checks (reduce_step) when they were for this very step.
  const bool decided = !force && snapshots_h_ >= 0.0 && snapshots_h_ == h && snapshots_time_ == time_;
  snapshots_h_ = -1.0;
  if (decided)
    return {step_collective_.vtu, step_collective_.csv, step_collective_.vtu_index, step_collective_.body_csv,
            step_collective_.bonds};
  ParticleSnapshotsDue due;
  if (output_) due = output_->particles_due(time_, h, force);
  const std::uint64_t fields[] = {due.vtu ? 1u : 0u, due.csv ? 1u : 0u, due.vtu_index, due.body_csv ? 1u : 0u,
                                  due.bonds ? 1u : 0u};
  std::vector<std::byte> bytes(sizeof fields);
  std::memcpy(bytes.data(), fields, sizeof fields);
  comm_->broadcast(bytes, 0);
  std::uint64_t got[5] = {};
  if (bytes.size() != sizeof got) throw std::runtime_error("truncated snapshot decision");
  std::memcpy(got, bytes.data(), sizeof got);
  return {got[0] != 0, got[1] != 0, got[2], got[3] != 0, got[4] != 0};
}

void Simulation::write_piece(std::uint64_t index) {
  // Rank 0 created the particles/ folder (OutputManager) before it broadcast this snapshot's
  // decision (particles_due), which every rank has received.
  const std::filesystem::path dir = output_dir_for(scene_, options_);
  write_particles_piece(dir / particle_piece_name(index, comm_->rank()), scene_.particles, time_,
                        vtu_options(scene_.model));
  comm_->barrier();  // every piece complete before rank 0 lists them in the .pvtu
}

std::pair<std::int64_t, int> Simulation::first_nonfinite() const {
  const Particles& p = scene_.particles;
  std::int64_t id = -1;  // the lowest id, so the particle named does not depend on the rank count
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!finite_state(p, i) && (id < 0 || p.id[i] < id)) id = p.id[i];
  if (!comm_) return {id, -1};
  return lowest_id_across(*comm_, id);
}

}  // namespace mpdem
