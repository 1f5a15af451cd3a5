// Interactions' checkpoint sections (interact/interactions.hpp): statistics, neighbour lists and
// contact history; on several ranks gathered by ids into one file that any rank count resumes.
#include <algorithm>
#include <array>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>
#include <type_traits>

#include "contact/barrier_contacts.hpp"
#include "contact/bonds.hpp"
#include "contact/cohesion_reach.hpp"
#include "contact/particle_contacts.hpp"
#include "neighbor/neighbor_search.hpp"
#include "parallel/gather.hpp"
#include "interact/body_forces.hpp"
#include "interact/interactions.hpp"
#include "parallel/body_ownership.hpp"

namespace mpdem {

namespace {
// The statistics of one checkpoint section, in table order (interact/interaction_stats.hpp).
template <class S, class F>
void for_each_saved_stat(S& s, StatSaved section, F&& f) {
  for_each_stat(s, [&](const StatInfo& info, auto& v) {
    if (info.saved == section) f(v);
  });
}
// The "interactions" section's layout: 19 values of 8 bytes in table order. Another row there
// changes the format (bump kCheckpointFormat); new rows go in an optional section instead.
static_assert([] {
  std::size_t n = 0;
  for (const StatInfo& s : kStats) n += s.saved == StatSaved::interactions ? 1 : 0;
  return n;
}() == 19);
// Reads one section with `read(BinaryReader&)`, which must consume it whole.
template <class F>
void read_section(CheckpointReader& r, const std::string& name, F&& read) {
  BinaryReader in = r.open(name);
  read(in);
  r.done(name, in);
}
}  // namespace

namespace {
// The interactions' four sections; the lists and history sections from the callers' writers
// (one layout for one rank and for several ranks' gathered state).
// The "fields" section only when the scene has a dissipative body force (`fields`), the
// "cohesion" one only with cohesion (contact/cohesion_reach.hpp has_cohesion).
template <class N, class P, class B>
void write_sections(CheckpointWriter& w, const InteractionStats& s, const std::array<double, 3>& out, bool fields,
                    bool cohesion, N&& neighbor, P&& pairs, B&& barriers) {
  w.section("interactions", [&](BinaryWriter& o) {
    for_each_saved_stat(s, StatSaved::interactions, [&](const auto& v) { o.value(v); });
    for (double v : out) o.value(v);
  });
  if (fields)
    w.section("fields",
              [&](BinaryWriter& o) { for_each_saved_stat(s, StatSaved::fields, [&](const auto& v) { o.value(v); }); });
  if (cohesion)
    w.section("cohesion", [&](BinaryWriter& o) {
      for_each_saved_stat(s, StatSaved::cohesion, [&](const auto& v) { o.value(v); });
    });
  w.section("neighbor", neighbor);
  w.section("particle_contacts", pairs);
  w.section("barrier_contacts", barriers);
}
}  // namespace

void Interactions::save(CheckpointWriter& w, const Particles& p) const {
  write_sections(
      w, stats_, {out_barriers_, out_convected_, out_radiated_}, dissipative_fields(model_.params.fields),
      has_cohesion(table_), [&](BinaryWriter& o) { search_->save(o); },
      [&](BinaryWriter& o) { particle_contacts_->save(o, p, *search_); },
      [&](BinaryWriter& o) { barrier_contacts_->save(o); });
  if (bonds_)
    w.section("bonds", [&](BinaryWriter& o) {
      for_each_saved_stat(stats_, StatSaved::bonds, [&](const auto& v) { o.value(v); });
      bonds_->save(o);
    });
}

void Interactions::save_gathered(CheckpointWriter& w, const Particles& p, const Particles& all) const {
  constexpr int kRoot = 0;
  const InteractionStats s = global_stats();
  std::array<double, 3> out{out_barriers_, out_convected_, out_radiated_};  // W, summed like the stats
  comm_->sum(out);
  AttachedRecords build = AttachedRecords::of<Vec3>();  // m, build position of each owned particle
  const auto& xb = search_->pairs().build_positions();
  for (std::size_t i = 0; i < p.size(); ++i) build.push(p.id[i], xb[i]);
  build = gather_records(*comm_, build, kRoot);
  std::vector<PairHistory> pairs = gather_values<PairHistory>(*comm_, particle_contacts_->export_history(p, *search_),
                                                              kRoot);
  const AttachedRecords barrier = gather_records(*comm_, barrier_contacts_->export_records(p), kRoot);
  const std::uint64_t overflows = comm_->sum(barrier_contacts_->overflows());
  std::vector<BondRecord> bonds;  // each bond is held by one rank
  if (bonds_) bonds = gather_values<BondRecord>(*comm_, bonds_->export_records(), kRoot);
  if (comm_->rank() != kRoot) return;
  // `all` is in id order: each record goes to its particle's index there.
  const std::span<const std::int64_t> ids(all.id.data(), all.size());
  std::vector<Vec3> xb_all(all.size());
  for (std::size_t r = 0; r < build.size(); ++r)
    xb_all[static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), build.anchor[r]) - ids.begin())] =
        build.get<Vec3>(r);
  // Each pair is listed by one rank; the file does not depend on which.
  std::sort(pairs.begin(), pairs.end(), [](const PairHistory& a, const PairHistory& b) {
    return std::minmax(a.id_first, a.id_second) < std::minmax(b.id_first, b.id_second);
  });
  write_sections(
      w, s, out, dissipative_fields(model_.params.fields), has_cohesion(table_),
      [&](BinaryWriter& o) { search_->save(o, xb_all); }, [&](BinaryWriter& o) { o.vector(pairs); },
      [&](BinaryWriter& o) { BarrierContacts::save_records(o, barrier, ids, overflows); });
  if (bonds_)
    w.section("bonds", [&](BinaryWriter& o) {
      for_each_saved_stat(s, StatSaved::bonds, [&](const auto& v) { o.value(v); });
      Bonds::save_records(o, std::move(bonds));
    });
}

void Interactions::restore(CheckpointReader& r, Particles& p, const Barriers& b) {
  next_drift_.valid = false;
  read_section(r, "interactions", [&](BinaryReader& in) {
    for_each_saved_stat(stats_, StatSaved::interactions, [&](auto& v) { v = in.value<std::decay_t<decltype(v)>>(); });
    out_barriers_ = in.value<double>();
    out_convected_ = in.value<double>();
    out_radiated_ = in.value<double>();
  });
  // Written only with a dissipative body force: absent, its statistics start at 0.
  if (r.has("fields"))
    read_section(r, "fields", [&](BinaryReader& in) {
      for_each_saved_stat(stats_, StatSaved::fields, [&](auto& v) { v = in.value<std::decay_t<decltype(v)>>(); });
    });
  if (r.has("cohesion"))
    read_section(r, "cohesion", [&](BinaryReader& in) {
      for_each_saved_stat(stats_, StatSaved::cohesion, [&](auto& v) { v = in.value<std::decay_t<decltype(v)>>(); });
    });
  // Written only with [bonds] (the scene fingerprint makes a resume agree on that).
  if (r.has("bonds") && bonds_)
    read_section(r, "bonds", [&](BinaryReader& in) {
      for_each_saved_stat(stats_, StatSaved::bonds, [&](auto& v) { v = in.value<std::decay_t<decltype(v)>>(); });
      bonds_->restore(in);
    });
  if (!comm_) {
    read_section(r, "neighbor", [&](BinaryReader& in) { search_->restore(in, p, b); });
    read_section(r, "particle_contacts", [&](BinaryReader& in) { particle_contacts_->restore(in, p, *search_); });
    read_section(r, "barrier_contacts", [&](BinaryReader& in) { barrier_contacts_->restore(in, p.size()); });
    return;
  }
  // Several ranks: the sums over the particles are held once, by rank 0.
  const bool counts_sums = comm_->rank() == 0;
  if (!counts_sums) {
    for_each_stat(stats_, [](const StatInfo& info, auto& v) {
      if (info.ranks == StatRanks::sum) v = 0;
    });
    out_barriers_ = out_convected_ = out_radiated_ = 0.0;
  }
  // p holds every particle of the checkpoint (written on any rank count): the history is keyed
  // by ids first, then this rank keeps its brick's particles and the history anchored on them.
  read_section(r, "barrier_contacts", [&](BinaryReader& in) { barrier_contacts_->restore(in, p.size()); });
  const AttachedRecords barrier = barrier_contacts_->export_records(p);
  if (!counts_sums) barrier_contacts_->clear_overflows();
  // A clump's members are kept with their body, by its centre (parallel/body_ownership.hpp).
  const BrickGrid& grid = search_->halo()->grid();
  const std::vector<char> keep = owned_particles(grid, p, comm_->rank());
  if (p.has_bodies()) p.bodies.compact(grid.owned(p.bodies.x, comm_->rank()));
  std::unordered_set<std::int64_t> mine;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (keep[i]) mine.insert(p.id[i]);
  read_section(r, "neighbor", [&](BinaryReader& in) { search_->restore(in, p, b, &keep); });
  std::vector<PairHistory> pairs;
  read_section(r, "particle_contacts", [&](BinaryReader& in) { pairs = in.vector<PairHistory>(); });
  // A pair's history lives with its lower-id particle (the rank that computes the pair).
  std::erase_if(pairs, [&](const PairHistory& h) { return !mine.contains(std::min(h.id_first, h.id_second)); });
  particle_contacts_->import_history(p, *search_, std::move(pairs));
  barrier_contacts_->import_records(p, barrier);
  if (bonds_) {
    // A bond lives with its lower-id particle.
    std::vector<BondRecord> bonds = bonds_->export_records();
    std::erase_if(bonds, [&](const BondRecord& r2) { return !mine.contains(r2.id_i); });
    bonds_->import_records(std::move(bonds));
  }
  stats_.rebuilds = search_->rebuilds();
}

}  // namespace mpdem
