// Interactions' checkpoint sections (sim/interactions.hpp): statistics, neighbour lists and
// contact history.
#include <string>
#include <type_traits>

#include "contact/barrier_contacts.hpp"
#include "contact/particle_contacts.hpp"
#include "neighbor/neighbor_search.hpp"
#include "sim/interactions.hpp"

namespace mpdem {

namespace {
// The checkpointed statistics, field by field (one list for writing and reading).
template <class S, class F>
void for_each_stat(S& s, F&& f) {
  f(s.contacts_pp);
  f(s.contacts_pb);
  f(s.elastic_energy);
  f(s.damping_dissipated);
  f(s.friction_dissipated);
  f(s.damping_power);
  f(s.rolling_power);
  f(s.spring_energy);
  f(s.barrier_work);
  f(s.drive_power);
  f(s.fixed_work);
  f(s.fixed_power);
  f(s.rebuilds);
  f(s.near_field_energy);
  f(s.heat_to_barriers);
  f(s.heat_convected);
  f(s.heat_radiated);
}
// A field added to InteractionStats must be added to for_each_stat (and is then a format change).
static_assert(sizeof(InteractionStats) == 17 * 8, "InteractionStats changed: update for_each_stat");
// Reads one section with `read(BinaryReader&)`, which must consume it whole.
template <class F>
void read_section(CheckpointReader& r, const std::string& name, F&& read) {
  BinaryReader in = r.open(name);
  read(in);
  r.done(name, in);
}
}  // namespace

void Interactions::save(CheckpointWriter& w, const Particles& p) const {
  w.section("interactions", [&](BinaryWriter& o) {
    for_each_stat(stats_, [&](const auto& v) { o.value(v); });
    o.value(out_barriers_);
    o.value(out_convected_);
    o.value(out_radiated_);
  });
  w.section("neighbor", [&](BinaryWriter& o) { search_->save(o); });
  w.section("particle_contacts", [&](BinaryWriter& o) { pp_->save(o, p, *search_); });
  w.section("barrier_contacts", [&](BinaryWriter& o) { pb_->save(o); });
}

void Interactions::restore(CheckpointReader& r, Particles& p, const Barriers& b) {
  next_drift_.valid = false;
  read_section(r, "interactions", [&](BinaryReader& in) {
    for_each_stat(stats_, [&](auto& v) { v = in.value<std::decay_t<decltype(v)>>(); });
    out_barriers_ = in.value<double>();
    out_convected_ = in.value<double>();
    out_radiated_ = in.value<double>();
  });
  read_section(r, "neighbor", [&](BinaryReader& in) { search_->restore(in, p, b); });
  read_section(r, "particle_contacts", [&](BinaryReader& in) { pp_->restore(in, p, *search_); });
  read_section(r, "barrier_contacts", [&](BinaryReader& in) { pb_->restore(in, p.size()); });
}

}  // namespace mpdem
