// The open system (simulation.hpp): particles that leave the domain or enter a sink are
// removed, with what they take along kept in the energy balance and every removal named by id
// (removed.csv, the progress line) whichever rank held it; inlets add particles.
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <vector>

#include "output/output_manager.hpp"
#include "output/progress.hpp"
#include "parallel/gather.hpp"
#include "sim/inlets.hpp"
#include "core/run_error.hpp"
#include "sim/simulation.hpp"
#include "sim/sinks.hpp"
#include "integrate/health_scan.hpp"

namespace mpdem {

namespace {

// Marks every member of a body with a member marked in keep [N] (1 = stays) and returns which
// bodies stay [B] (empty without bodies).
std::vector<char> whole_bodies(Particles& p, std::vector<char>& keep) {
  Bodies& B = p.bodies;
  if (B.empty()) return {};
  B.index_members(p);
  std::vector<char> stays(B.size(), 1);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!keep[i] && p.body[i] != kNoBody) stays[B.owner[i]] = 0;
  for (std::size_t b = 0; b < B.size(); ++b)
    if (!stays[b])
      for (std::uint32_t k = B.first[b]; k < B.first[b + 1]; ++k) keep[B.index[k]] = 0;
  return stays;
}

}  // namespace

void Simulation::remove_outside() {
  Particles& p = scene_.particles;
  const DomainParams& d = scene_.model.params.domain;
  std::vector<char> keep(p.size(), 1);
  std::size_t gone = 0;
  struct Exit {
    std::int64_t id = -1;
    Vec3 x;
  } first;  // the first particle outside (on the lowest rank that has one)
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (inside_domain(d, p.x[i])) continue;
    if (first.id < 0) first = {p.id[i], p.x[i]};
    keep[i] = 0;
    ++gone;
  }
  int rank = -1;
  if (comm_)
    std::tie(first, rank) = best_across(*comm_, first,
                                        [](const Exit& a, const Exit& b) { return a.id >= 0 && b.id < 0; });
  if (d.on_exit == ExitPolicy::Stop && first.id >= 0)
    throw RunError(fmt::format("particle id {}{} left the domain at step {} (t = {:.9g} s) at ({:.6g}, {:.6g}, "
                               "{:.6g}); domain.on_exit = \"stop\"",
                               first.id, rank_note(comm_, rank), steps_, time_, first.x.x, first.x.y, first.x.z));
  remove_marked(keep, true);
}

void Simulation::remove_in_sinks() {
  std::vector<char> keep(scene_.particles.size(), 1);
  if (sinks_->mark(scene_.particles, keep, comm_) > 0) remove_marked(keep, false);  // stderr: the summary line
}

void Simulation::remove_marked(std::vector<char> keep, bool exits) {
  Particles& p = scene_.particles;
  const FieldParams& fields = scene_.model.params.fields;
  const DomainParams& domain = scene_.model.params.domain;
  // A clump body is removed whole: with any member marked (one that left the domain), all of them.
  std::vector<char> keep_body = whole_bodies(p, keep);
  // Every rank's removals, named on rank 0 (removed.csv, the progress line).
  struct Removed {
    std::int64_t id;
    Vec3 x;
  };
  std::vector<Removed> gone;
  double energy = 0.0;  // J, what the removed particles take along
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (keep[i]) continue;
    // The energy it takes along stays in the balance, which would otherwise drop (or rise) by it
    // (a member's is its body's, below).
    std::array<double, kScanSums> e{};
    scan_range(p, i, i + 1, fields, domain, e);  // potentials unwrapped
    energy += e[0] + e[1] + e[2] + e[3];
    gone.push_back({p.id[i], p.x[i]});
  }
  bool fixed_body = false;  // a removed body was held (its holding power changes)
  for (std::size_t b = 0; b < keep_body.size(); ++b) {
    if (keep_body[b]) continue;
    std::array<double, kScanSums> e{};
    scan_body(p.bodies, b, fields, domain, e);
    energy += e[0] + e[1] + e[2] + e[3];
    fixed_body = fixed_body || p.bodies.fixed[b] != 0;
  }
  std::uint64_t count = gone.size();
  if (comm_) {
    energy = comm_->sum(energy);
    count = comm_->sum(count);
    gone = gather_values<Removed>(*comm_, gone, 0);  // on rank 0; empty elsewhere
  }
  // By id: removed.csv does not depend on the particle order or the rank count.
  std::sort(gone.begin(), gone.end(), [](const Removed& a, const Removed& b) { return a.id < b.id; });
  if (count == 0) return;  // nobody removed anything (on any rank): no rebuild either
  record_.removed_energy += energy;
  for (std::size_t k = 0; k < gone.size(); ++k) {
    if (output_) output_->removed(gone[k].id, time_, gone[k].x);
    if (exits && progress_) progress_->removed(gone[k].id, time_, removed_ + k + 1);
  }
  if (exits) removed_ += count;
  // The removed particles' forces on the others are gone: re-evaluate the rates (no increment),
  // unless the removed particles acted on nobody (a particle that fell out of the domain alone).
  const bool acted = interactions_->removal_acts_on_others(p, keep) || fixed_body;
  interactions_->remove_particles(p, scene_.barriers, keep);
  if (!keep_body.empty()) {
    p.bodies.compact(keep_body);
    trapezoidal_.bodies().compact(keep_body);
  }
  if (!acted) return;
  interactions_->evaluate(p, scene_.barriers, EvalRequest{time_, 0.0, 1.0, true});
  ++evaluations_;
}

void Simulation::insert_from_inlets() {
  if (!inlets_->due(time_)) return;
  // Several ranks: every rank places the same particles among the same neighbours (those near the
  // inlets, gathered), then keeps those of its brick.
  Particles fresh = inlets_->insert(time_, comm_ ? near_inlets() : scene_.particles, scene_.barriers);
  if (fresh.size() == 0) return;
  // New bodies: the bodies' predictor history no longer covers them all (before a rank keeps its own).
  if (fresh.has_bodies()) trapezoidal_.bodies().forget();
  if (comm_) keep_own(fresh);
  interactions_->add_particles(scene_.particles, scene_.barriers, std::move(fresh));
  // The new particles' forces (gravity, fields; no contact yet): re-evaluate the rates.
  interactions_->evaluate(scene_.particles, scene_.barriers, EvalRequest{time_, 0.0, 1.0, true});
  ++evaluations_;
}

std::string Simulation::open_system_summary() const {
  const std::string in = inlets_ ? inlets_->summary() : "", out = sinks_ ? sinks_->summary() : "";
  return in.empty() || out.empty() ? in + out : in + "; " + out;
}

void Simulation::summarise_open_system(RunSummary& sum) const {
  sum.open = inlets_ || sinks_;
  sum.sinks = sinks_ != nullptr;
  sum.inserted_energy = inlets_ ? inlets_->inserted_energy() : 0.0;
  sum.dissipated = dissipated_energy(stats());
  if (sinks_)
    for (const Sinks::State& s : sinks_->states()) sum.sunk += s.removed;
}

}  // namespace mpdem
