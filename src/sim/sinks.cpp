#include "sim/sinks.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "sim/checkpointed_states.hpp"

namespace mpdem {

namespace {
// Checkpoints hold the states byte for byte: a layout change is a format change.
static_assert(sizeof(Sinks::State) == 32 && std::is_trivially_copyable_v<Sinks::State>,
              "Sinks::State changed: bump kCheckpointFormat (io/checkpoint_format.hpp) and this size");
}  // namespace

Sinks::Sinks(const Model& model) : model_(model) {
  for (const SinkSpec& s : model.params.sinks) regions_.emplace_back(s.region, "sink", s.line);
  state_.resize(regions_.size());
}

std::size_t Sinks::mark(Particles& p, std::vector<char>& keep, const Communicator* comm) {
  std::vector<double> taken(2 * regions_.size(), 0.0);  // per sink: particles (-), mass (kg)
  // The first sink holding x, or -1.
  const auto sink_of = [&](const Vec3& x) -> std::ptrdiff_t {
    for (std::size_t s = 0; s < regions_.size(); ++s) {
      const Region& g = regions_[s];
      // The bounding box first: most particles are far from every sink.
      const Vec3 lo = g.lo(), hi = g.hi();
      if (x.x < lo.x || x.x > hi.x || x.y < lo.y || x.y > hi.y || x.z < lo.z || x.z > hi.z) continue;
      if (g.holds(x, 0.0)) return static_cast<std::ptrdiff_t>(s);
    }
    return -1;
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!keep[i] || p.body[i] != kNoBody) continue;  // a clump member goes with its body, below
    const std::ptrdiff_t s = sink_of(p.x[i]);
    if (s < 0) continue;
    keep[i] = 0;
    taken[2 * static_cast<std::size_t>(s)] += 1.0;
    taken[2 * static_cast<std::size_t>(s) + 1] += p.mass[i];
  }
  // A clump body goes whole when its centre of mass is in a sink: all its members (counted as
  // particles), its mass once (each member's mass is the body's).
  Bodies& B = p.bodies;
  if (!B.empty()) B.index_members(p);
  for (std::size_t b = 0; b < B.size(); ++b) {
    const std::ptrdiff_t s = sink_of(B.x[b]);
    if (s < 0) continue;
    for (std::uint32_t k = B.first[b]; k < B.first[b + 1]; ++k) keep[B.index[k]] = 0;
    taken[2 * static_cast<std::size_t>(s)] += static_cast<double>(B.first[b + 1] - B.first[b]);
    taken[2 * static_cast<std::size_t>(s) + 1] += B.mass[b];
  }
  if (comm) comm->sum(taken);  // every rank holds the totals of all
  std::size_t marked = 0;
  for (std::size_t s = 0; s < regions_.size(); ++s) {
    const auto n = static_cast<std::uint64_t>(taken[2 * s]);
    marked += n;
    state_[s].removed += n;
    if (n > 0) state_[s].removed_mass += taken[2 * s + 1];
  }
  return marked;
}

std::vector<std::string> Sinks::log_columns(const Params& prm) {
  std::vector<std::string> cols;
  for (const SinkSpec& s : prm.sinks)
    for (const char* c : {".removed", ".removed_mass", ".mass_rate"}) cols.push_back(s.name + c);
  return cols;
}

void Sinks::log_values(double t, std::vector<double>& out) {
  for (State& s : state_) {
    const double span = t - s.logged_time;  // s
    out.push_back(static_cast<double>(s.removed));
    out.push_back(s.removed_mass);
    out.push_back(span > 0.0 ? (s.removed_mass - s.logged_mass) / span : 0.0);
    s.logged_mass = s.removed_mass;
    s.logged_time = t;
  }
}

std::string Sinks::summary() const {
  std::string line;
  for (std::size_t s = 0; s < state_.size(); ++s) {
    if (state_[s].removed == 0) continue;
    line += fmt::format("{}sink '{}': {} particles removed, {:.6g} kg", line.empty() ? "" : "; ",
                        model_.params.sinks[s].name, state_[s].removed, state_[s].removed_mass);
  }
  return line;
}

void Sinks::save(BinaryWriter& w) const { w.vector(state_); }

void Sinks::restore(BinaryReader& r) {
  state_ = read_states<State>(r, state_.size(), "sinks");
  // Intact checksums do not make the values sane (a patched or foreign file): refuse what no run writes.
  for (const State& s : state_)
    if (!(s.removed_mass >= 0.0 && s.logged_mass >= 0.0 && std::isfinite(s.removed_mass) &&
          std::isfinite(s.logged_mass) && std::isfinite(s.logged_time)))
      throw std::runtime_error("the section 'sinks' holds a negative or non-finite mass or time");
}

}  // namespace mpdem
