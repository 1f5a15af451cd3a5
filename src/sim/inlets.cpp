#include "sim/inlets.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "core/random.hpp"
#include "model/particle_defaults.hpp"
#include "sim/checkpointed_states.hpp"
#include "model/body_members.hpp"
#include "sim/inlet_bodies.hpp"
#include "sim/insertion_space.hpp"
#include "integrate/health_scan.hpp"

namespace mpdem {

namespace {
// Checkpoints hold the states byte for byte: a layout change is a format change.
static_assert(sizeof(Inlets::State) == 40 && std::is_trivially_copyable_v<Inlets::State>,
              "Inlets::State changed: bump kCheckpointFormat (io/checkpoint_format.hpp) and this size");

constexpr double kTimeSlack = 1e-6;  // -, of the interval: round-off of the summed steps

// SplitMix64's finaliser: nearby inputs (seeds, inlet and insertion indices) give unrelated seeds.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// kg or particles (bodies), what inlet `spec` has due in all at its insertion time k: the rate
// times the time from its start to the next insertion time (or its end).
double due_at(const InletSpec& spec, std::uint64_t k, double interval, double end) {
  const double horizon = std::min(spec.start + static_cast<double>(k + 1) * interval, end);  // s
  return (spec.mass_rate > 0.0 ? spec.mass_rate : spec.count_rate) * (horizon - spec.start);
}

Vec3 to_world(const InsertionVolume& vol, const Vec3& a) {
  return vol.origin + vol.u * a.x + vol.v * a.y + vol.w * a.z;
}
}  // namespace

bool inlet_centre_box(const InsertionVolume& vol, double inset, Vec3& lo, Vec3& hi) {
  // The centres' region, the volume shrunk by `inset`, as a box of the frame [a, b].
  const RegionSpec& spec = vol.region;
  Vec3 a = spec.min + Vec3{inset, inset, inset}, b = spec.max - Vec3{inset, inset, inset};
  if (spec.shape == RegionShape::Cylinder) {  // in world coordinates (identity frame): its tight box
    const double h = norm(spec.axis);
    if (!(spec.radius > inset && h > 2.0 * inset)) return false;
    RegionSpec c = spec;
    c.base += spec.axis * (inset / h);
    c.axis *= 1.0 - 2.0 * inset / h;
    c.radius -= inset;
    const Region region(c, "inlet", 0);
    a = region.lo();
    b = region.hi();
  }
  if (!(a.x <= b.x && a.y <= b.y && a.z <= b.z)) return false;
  for (int c = 0; c < 8; ++c) {  // the frame box's eight corners in the world
    const Vec3 w = to_world(vol, {c & 1 ? b.x : a.x, c & 2 ? b.y : a.y, c & 4 ? b.z : a.z});
    lo = c == 0 ? w : Vec3{std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
    hi = c == 0 ? w : Vec3{std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
  }
  return true;
}

void smallest_centre_box(const InletSpec& in, Vec3& lo, Vec3& hi) {
  if (!inlet_centre_box(in.volume, in.radius.smallest(), lo, hi)) inlet_centre_box(in.volume, 0.0, lo, hi);
}

Inlets::Inlets(const Model& model, const Particles& p) : model_(model) {
  const Params& prm = model.params;
  for (const InletSpec& s : prm.inlets) {
    const int mat = s.material.empty() ? 0 : std::max(0, model.material_index(s.material));
    Inlet in{&s,
             Region(s.volume.region, "inlet", s.line),
             mat,
             model.materials.at(static_cast<std::size_t>(mat)).density,
             s.end.value_or(prm.time.duration),
             s.interval_or_default(prm.time.dt),
             {},
             {}};
    inlet_centre_box(s.volume, 0.0, in.lo, in.hi);
    inlets_.push_back(std::move(in));
  }
  state_.resize(inlets_.size());
  for (std::size_t i = 0; i < p.size(); ++i) next_id_ = std::max(next_id_, p.id[i] + 1);
  for (const std::int64_t id : p.bodies.id) next_body_id_ = std::max(next_body_id_, id + 1);
}

bool Inlets::any_clump() const {
  return std::any_of(inlets_.begin(), inlets_.end(), [](const Inlet& in) { return !in.spec->clump.empty(); });
}

bool Inlets::due(std::size_t j, double t) const {
  const Inlet& in = inlets_[j];
  const double next = in.spec->start + static_cast<double>(state_[j].next_k) * in.interval;  // s
  return !(t + kTimeSlack * in.interval < next) && next < in.end;
}

bool Inlets::due(double t) const {
  for (std::size_t j = 0; j < inlets_.size(); ++j)
    if (due(j, t)) return true;
  return false;
}

void Inlets::reach(double radius, Vec3& lo, Vec3& hi) const {
  const double inf = std::numeric_limits<double>::infinity();
  lo = Vec3{inf, inf, inf};
  hi = -lo;
  for (const Inlet& in : inlets_) {
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], in.lo[c] - radius);
      hi[c] = std::max(hi[c], in.hi[c] + radius);
    }
  }
}

Particles Inlets::insert(double t, const Particles& p, const Barriers& b) {
  Particles fresh;
  for (std::size_t j = 0; j < inlets_.size(); ++j) {
    const Inlet& in = inlets_[j];
    State& s = state_[j];
    const double start = in.spec->start, slack = kTimeSlack * in.interval;
    const auto time_of = [&](std::uint64_t k) { return start + static_cast<double>(k) * in.interval; };
    if (!due(j, t)) continue;
    // The latest insertion time passed (several pass at once when the interval is below the step).
    auto k = static_cast<std::uint64_t>(std::floor((t + slack - start) / in.interval));
    k = std::max(k, s.next_k);
    while (k > s.next_k && !(time_of(k) < in.end)) --k;
    insert_due(j, k, p, b, fresh);
    s.next_k = k + 1;
  }
  if (fresh.size() > 0) {
    const HealthScan e = scan_state(fresh, model_.params.fields, DomainParams{});
    inserted_energy_ += e.energy.kinetic + e.energy.rotational + e.energy.potential + e.electric;
  }
  return fresh;
}

void Inlets::insert_due(std::size_t j, std::uint64_t k, const Particles& p, const Barriers& b, Particles& fresh) {
  const Inlet& in = inlets_[j];
  const InletSpec& spec = *in.spec;
  if (!spec.clump.empty()) return insert_due_bodies(j, k, p, b, fresh);
  State& s = state_[j];
  // Ids after every present one (a restored next id is taken on trust otherwise).
  for (std::size_t i = 0; i < p.size(); ++i) next_id_ = std::max(next_id_, p.id[i] + 1);
  Rng rng(mix(mix(mix(spec.seed) ^ j) ^ k));
  const bool by_mass = spec.mass_rate > 0.0;
  const double due = due_at(spec, k, in.interval, in.end);  // kg or particles
  if (!(s.next_radius > 0.0)) s.next_radius = spec.radius.sample(rng);
  const Material& m = model_.materials[static_cast<std::size_t>(in.material)];
  std::optional<InsertionSpace> space;  // built once something is due
  std::size_t redrawn = 0;
  for (;;) {
    const double r = s.next_radius, mass = sphere_mass(r, in.density);
    const double done = by_mass ? s.inserted_mass : static_cast<double>(s.inserted);
    const double amount = by_mass ? mass : 1.0;
    s.shortfall = 0.0;
    if (done + 0.5 * amount > due) return;  // the rest is due later
    // Only an unbounded log-normal tail can draw a sphere larger than the volume (the reader
    // checks the largest radius of the others): drawn again, so the tail is cut at the volume.
    if (!in.region.has_room(r)) {
      if (++redrawn > spec.max_attempts) {
        s.shortfall = due - done;
        return;
      }
      s.next_radius = spec.radius.sample(rng);
      continue;
    }
    if (!space) {
      space.emplace(p, b, in.lo, in.hi, r);
      for (std::size_t i = 0; i < fresh.size(); ++i) space->add(fresh.x[i], fresh.radius[i]);  // earlier inlets'
    }
    Vec3 x;
    bool placed = false;
    for (std::size_t a = 0; a < spec.max_attempts && !placed; ++a) {
      Vec3 local;
      if (!in.region.sample(rng, r, local)) continue;
      x = to_world(spec.volume, local);
      placed = space->free(x, r);
    }
    if (!placed) {
      s.shortfall = due - done;  // carried: due mass grows, so the next insertion time tries again
      return;
    }
    Vec3 v = spec.velocity;
    if (const double h = spec.velocity_spread; h > 0.0)  // braced: drawn in the order x, y, z
      v += Vec3{rng.uniform(-h, h), rng.uniform(-h, h), rng.uniform(-h, h)};
    fresh.add(next_id_++, in.material, r, in.density, x, v);
    take_material_properties(fresh, fresh.size() - 1, m);
    space->add(x, r);
    ++s.inserted;
    s.inserted_mass += mass;
    s.next_radius = spec.radius.sample(rng);
  }
}

void Inlets::insert_due_bodies(std::size_t j, std::uint64_t k, const Particles& p, const Barriers& b,
                               Particles& fresh) {
  const Inlet& in = inlets_[j];
  const InletSpec& spec = *in.spec;
  State& s = state_[j];
  for (std::size_t i = 0; i < p.size(); ++i) next_id_ = std::max(next_id_, p.id[i] + 1);
  for (const std::int64_t id : p.bodies.id) next_body_id_ = std::max(next_body_id_, id + 1);
  Rng rng(mix(mix(mix(spec.seed) ^ j) ^ k));
  const bool by_mass = spec.mass_rate > 0.0;
  const double due = due_at(spec, k, in.interval, in.end);  // kg or bodies
  const Material& m = model_.materials[static_cast<std::size_t>(in.material)];
  std::optional<InsertionSpace> space;  // built once something is due
  for (;;) {
    // The inlet's n-th body's template, from a stream of its own: the same whenever it is tried.
    constexpr std::uint64_t kTemplateStream = 0x8BB84B93962EACC9ull;
    Rng template_rng(mix(mix(mix(mix(spec.seed) ^ j) ^ s.inserted) ^ kTemplateStream));
    const int c = spec.clump.draw(template_rng);
    const ClumpTemplate& t = model_.clumps[static_cast<std::size_t>(c)];
    const double mass = t.body_mass(in.density);  // kg
    const double done = by_mass ? s.inserted_mass : static_cast<double>(s.inserted);
    s.shortfall = 0.0;
    if (done + 0.5 * (by_mass ? mass : 1.0) > due) return;  // the rest is due later
    if (!space) {
      space.emplace(p, b, in.lo, in.hi, spec.clump.member_radii(model_.clumps).back());
      for (std::size_t i = 0; i < fresh.size(); ++i) space->add(fresh.x[i], fresh.radius[i]);  // earlier inlets'
    }
    BodyPlace at;
    if (!place_body(t, spec.volume, in.region, *space, rng, spec.max_attempts, at)) {
      s.shortfall = due - done;  // carried: due mass grows, so the next insertion time tries again
      return;
    }
    BodyInit init;
    init.id = next_body_id_++;
    init.x = at.x;
    init.q = at.q;
    init.v = spec.velocity;
    if (const double h = spec.velocity_spread; h > 0.0)  // braced: drawn in the order x, y, z
      init.v += Vec3{rng.uniform(-h, h), rng.uniform(-h, h), rng.uniform(-h, h)};
    init.T = m.temperature;
    init.charge = m.charge;
    const std::size_t first = fresh.size();
    add_body(model_, in.material, c, init, fresh);
    for (std::size_t i = first; i < fresh.size(); ++i) {  // the members, in template order
      fresh.id[i] = next_id_++;
      space->add(fresh.x[i], fresh.radius[i]);
    }
    ++s.inserted;
    s.inserted_mass += mass;
  }
}

std::vector<std::string> Inlets::log_columns(const Params& prm) {
  std::vector<std::string> cols;
  for (const InletSpec& s : prm.inlets)
    for (const char* c : {".inserted", ".inserted_mass", ".shortfall"}) cols.push_back(s.name + c);
  return cols;
}

void Inlets::log_values(std::vector<double>& out) const {
  for (const State& s : state_) {
    out.push_back(static_cast<double>(s.inserted));
    out.push_back(s.inserted_mass);
    out.push_back(s.shortfall);
  }
}

std::string Inlets::summary() const {
  std::string line;
  for (std::size_t j = 0; j < inlets_.size(); ++j) {
    const State& s = state_[j];
    if (s.inserted == 0 && s.shortfall == 0.0) continue;
    const char* what = inlets_[j].spec->clump.empty() ? "particles" : "bodies";
    line += fmt::format("{}inlet '{}': {} {} inserted, {:.6g} kg", line.empty() ? "" : "; ", inlets_[j].spec->name,
                        s.inserted, what, s.inserted_mass);
    if (s.shortfall > 0.0)
      line += fmt::format(", shortfall {:.6g} {} (no room in the region)", s.shortfall,
                          inlets_[j].spec->mass_rate > 0.0 ? "kg" : what);
  }
  return line;
}

void Inlets::save(BinaryWriter& w) const {
  w.vector(state_);
  w.value(next_id_);
  w.value(inserted_energy_);
  // The intervals in use: a default one follows time.dt, which a resume may edit, and the
  // insertion times must not move under the resumed run.
  std::vector<double> intervals;
  for (const Inlet& in : inlets_) intervals.push_back(in.interval);
  w.vector(intervals);
  if (any_clump()) w.value(next_body_id_);  // the scene (its fingerprint) says whether it is there
}

void Inlets::restore(BinaryReader& r) {
  state_ = read_states<State>(r, state_.size(), "inlets");
  next_id_ = r.value<std::int64_t>();
  inserted_energy_ = r.value<double>();
  // Intact checksums do not make the values sane (a patched or foreign file): refuse what no run writes.
  for (const State& s : state_)
    if (!(s.inserted_mass >= 0.0 && s.shortfall >= 0.0 && s.next_radius >= 0.0 && std::isfinite(s.inserted_mass) &&
          std::isfinite(s.shortfall) && std::isfinite(s.next_radius)))
      throw std::runtime_error("the section 'inlets' holds a negative or non-finite mass, shortfall or radius");
  if (next_id_ < 0 || !std::isfinite(inserted_energy_))
    throw std::runtime_error("the section 'inlets' holds a negative next id or a non-finite energy");
  const std::vector<double> intervals = read_states<double>(r, inlets_.size(), "inlets");
  for (std::size_t j = 0; j < inlets_.size(); ++j) {
    if (!(intervals[j] > 0.0 && std::isfinite(intervals[j])))
      throw std::runtime_error("the section 'inlets' holds an interval that is not finite and > 0");
    if (!(inlets_[j].spec->interval > 0.0)) inlets_[j].interval = intervals[j];  // a given one is in the fingerprint
  }
  if (any_clump()) {
    next_body_id_ = r.value<std::int64_t>();
    if (next_body_id_ < 0) throw std::runtime_error("the section 'inlets' holds a negative next body id");
  }
}

}  // namespace mpdem
