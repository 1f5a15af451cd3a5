#include "parallel/halo_exchange.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "parallel/body_ownership.hpp"
#include "parallel/periodic_images.hpp"
#include "parallel/particle_buffer.hpp"

namespace mpdem {

namespace {
constexpr int kHaloTag = 1000;       // + 8 per swap (exchange uses tag and tag + 1; fold adds 4)
constexpr int kMigrationTag = 2000;  // + 4 per direction and axis

double period(const BrickGrid& g, int c) { return g.box_upper()[c] - g.box_lower()[c]; }

// What a ghost receives in an evaluation is folded onto its source: it starts at zero.
void clear_ghost_accumulators(Particles& p) {
  for (std::size_t g = p.size(); g < p.size_with_ghosts(); ++g) {
    p.force[g] = {};
    p.torque[g] = {};
    p.heat[g] = 0.0;
  }
}
}  // namespace

HaloExchange::HaloExchange(const Communicator& comm, BrickGrid grid) : comm_(&comm), grid_(std::move(grid)) {
  if (grid_.ranks() != comm.size())
    throw std::invalid_argument(
        fmt::format("HaloExchange: a grid of {} bricks for {} ranks", grid_.ranks(), comm.size()));
  const int me = comm.rank();
  for (int c = 0; c < 3; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    if (grid_.dims()[cc] == 1 && !grid_.periodic()[cc]) continue;
    stages_.push_back(c);
    const int k = grid_.coords(me)[cc], n = grid_.dims()[cc];
    for (int dir : {-1, +1}) {
      Swap s;
      s.axis = c;
      s.send_to = grid_.neighbour(me, c, dir);
      s.recv_from = grid_.neighbour(me, c, -dir);
      // Through the periodic face: the first brick's particles appear one period up at the last.
      if (dir < 0 && k == 0) s.shift[c] = period(grid_, c);
      if (dir > 0 && k == n - 1) s.shift[c] = -period(grid_, c);
      s.tag = kHaloTag + 8 * static_cast<int>(swaps_.size());
      swaps_.push_back(std::move(s));
    }
  }
}

namespace {
// Moves the records of `a` whose anchor is a key of `leaving` into out[direction] (0 down, 1 up):
// their count, anchors and bytes, appended after the particles of the same message.
void pack_attached(AttachedRecords& a, const std::unordered_map<std::int64_t, int>& leaving,
                   std::vector<std::byte> (&out)[2]) {
  std::vector<std::size_t> go[2];
  for (std::size_t r = 0; r < a.anchor.size(); ++r)
    if (const auto it = leaving.find(a.anchor[r]); it != leaving.end()) go[it->second].push_back(r);
  // Packed before the kept ones are moved together: that overwrites the positions of leaving records.
  for (int d = 0; d < 2; ++d) {
    std::vector<std::byte>& o = out[d];
    const std::uint64_t n = go[d].size();
    const std::size_t at = o.size();
    o.resize(at + sizeof n + n * (sizeof(std::int64_t) + a.bytes));
    std::byte* w = o.data() + at;
    std::memcpy(w, &n, sizeof n);
    w += sizeof n;
    for (std::size_t r : go[d]) {
      std::memcpy(w, &a.anchor[r], sizeof(std::int64_t));
      std::memcpy(w + sizeof(std::int64_t), a.data.data() + r * a.bytes, a.bytes);
      w += sizeof(std::int64_t) + a.bytes;
    }
  }
  std::size_t kept = 0;
  for (std::size_t r = 0; r < a.anchor.size(); ++r) {
    if (leaving.count(a.anchor[r]) > 0) continue;
    if (kept != r) {
      a.anchor[kept] = a.anchor[r];
      std::memmove(a.data.data() + kept * a.bytes, a.data.data() + r * a.bytes, a.bytes);
    }
    ++kept;
  }
  a.anchor.resize(kept);
  a.data.resize(kept * a.bytes);
}

void unpack_attached(AttachedRecords& a, std::span<const std::byte> in, std::size_t& pos) {
  std::uint64_t n = 0;
  if (in.size() - pos < sizeof n) throw std::runtime_error("truncated migration message");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  const std::size_t each = sizeof(std::int64_t) + a.bytes;
  if ((in.size() - pos) / each < n) throw std::runtime_error("truncated migration message");
  for (std::uint64_t r = 0; r < n; ++r) {
    std::int64_t id = 0;
    std::memcpy(&id, in.data() + pos, sizeof id);
    a.anchor.push_back(id);
    a.data.insert(a.data.end(), in.begin() + static_cast<std::ptrdiff_t>(pos + sizeof id),
                  in.begin() + static_cast<std::ptrdiff_t>(pos + each));
    pos += each;
  }
}
}  // namespace

void HaloExchange::migrate(Particles& p, std::span<AttachedRecords* const> attached,
                           std::span<AttachedRecords* const> body_attached) {
  if (p.n_ghost != 0) throw std::logic_error("HaloExchange::migrate: drop the ghosts first");
  // Wrapped first: the brick a particle enters along a periodic axis is the one of its wrapped centre.
  DomainParams box;
  box.bounded = true;
  box.min = grid_.box_lower();
  box.max = grid_.box_upper();
  box.periodic = grid_.periodic();
  PeriodicImages(box).wrap(p);
  const int me = comm_->rank();
  Bodies& bodies = p.bodies;
  for (int c = 0; c < 3; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const int n = grid_.dims()[cc];
    if (n == 1) continue;
    const int k = grid_.coords(me)[cc];
    const int down = grid_.neighbour(me, c, -1), up = grid_.neighbour(me, c, +1);
    const int k_down = grid_.coords(down < 0 ? me : down)[cc], k_up = grid_.coords(up < 0 ? me : up)[cc];
    // The direction (0 down, 1 up) towards the brick holding coordinate x, or -1 to stay.
    const auto direction = [&](double x, std::int64_t id, const char* what) {
      const int b = grid_.brick_along(c, x);
      if (b == k) return -1;
      if (down >= 0 && b == k_down) return 0;
      if (up >= 0 && b == k_up) return 1;
      throw std::runtime_error(
          fmt::format("{} id {} moved from brick {} to brick {} along {} since the last rebuild, past the neighbouring "
                      "brick (x = {:.9g} m): its speed is far beyond what the neighbour lists were built for",
                      what, id, k, b, "xyz"[c], x));
    };
    // A member goes where its body's centre goes, with its body, in the same message.
    const std::vector<Vec3> at = owner_points(p);    // m
    std::vector<std::uint32_t> go[2], go_bodies[2];  // down, up
    std::unordered_map<std::int64_t, int> leaving, bodies_leaving;
    std::vector<char> keep(p.size(), 1), keep_bodies(bodies.size(), 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int d = direction(at[i][c], p.body[i] == kNoBody ? p.id[i] : p.body[i],
                              p.body[i] == kNoBody ? "particle" : "body");
      if (d < 0) continue;
      keep[i] = 0;
      go[d].push_back(static_cast<std::uint32_t>(i));
      leaving.emplace(p.id[i], d);
    }
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const int d = direction(bodies.x[b][c], bodies.id[b], "body");
      if (d < 0) continue;
      keep_bodies[b] = 0;
      go_bodies[d].push_back(static_cast<std::uint32_t>(b));
      bodies_leaving.emplace(bodies.id[b], d);
    }
    migrated_ += go[0].size() + go[1].size();
    migrated_bodies_ += go_bodies[0].size() + go_bodies[1].size();
    std::vector<std::byte> out[2];
    for (int d = 0; d < 2; ++d) {
      pack_particles(p, go[d], {}, out[d]);
      pack_bodies(bodies, go_bodies[d], out[d]);
    }
    for (AttachedRecords* a : attached) pack_attached(*a, leaving, out);
    for (AttachedRecords* a : body_attached) pack_attached(*a, bodies_leaving, out);
    p.compact(keep);
    bodies.compact(keep_bodies);
    // Downwards, then upwards; with two bricks along a periodic axis both go to the same rank.
    const auto in_from_up = comm_->exchange(down, out[0], up, kMigrationTag + 4 * (2 * c));
    const auto in_from_down = comm_->exchange(up, out[1], down, kMigrationTag + 4 * (2 * c + 1));
    for (const auto* in : {&in_from_up, &in_from_down}) {
      if (in->empty()) continue;
      std::size_t pos = 0;
      unpack_particles(p, *in, pos);
      unpack_bodies(bodies, *in, pos);
      for (AttachedRecords* a : attached) unpack_attached(*a, *in, pos);
      for (AttachedRecords* a : body_attached) unpack_attached(*a, *in, pos);
    }
  }
}

void HaloExchange::build(Particles& p, double width) {
  p.drop_ghosts();
  ghosts_ = 0;
  const int me = comm_->rank();
  for (int c : stages_) {
    const auto cc = static_cast<std::size_t>(c);
    if (grid_.dims()[cc] > 1 && !(grid_.narrowest() >= width))
      throw std::invalid_argument(fmt::format(
          "a subdomain is {:.6g} m wide along {}, narrower than the neighbour range {:.6g} m (2 x the largest radius "
          "+ skin + near-field reach, plus a skin for the drift; with clumps, plus twice the largest distance of a "
          "member from its body's centre): run on fewer ranks",
          grid_.narrowest(), "xyz"[c], width));
    if (grid_.periodic()[cc] && !(period(grid_, c) >= 2.0 * width))
      throw std::invalid_argument(fmt::format(
          "the periodic domain is {:.6g} m long along {}, shorter than twice the neighbour range {:.6g} m: enlarge "
          "[domain] min/max along {} or use smaller particles",
          period(grid_, c), "xyz"[c], width, "xyz"[c]));
  }
  for (std::size_t first = 0; first < swaps_.size(); first += 2) {
    // Both swaps of a stage choose from what the rank held before the stage.
    const std::size_t n_before = p.size_with_ghosts();
    std::vector<std::byte> out[2];
    for (std::size_t s = first; s < first + 2; ++s) {
      Swap& w = swaps_[s];
      w.send.clear();
      const int c = w.axis;
      const bool down = s == first;
      const double lo = grid_.lower(me, c), hi = grid_.upper(me, c);
      if (w.send_to >= 0)
        for (std::size_t i = 0; i < n_before; ++i) {
          const double x = p.x[i][c];
          if (down ? x < lo + width : x >= hi - width) w.send.push_back(static_cast<std::uint32_t>(i));
        }
      pack_particles(p, w.send, w.shift, out[s - first]);
    }
    for (std::size_t s = first; s < first + 2; ++s) {
      Swap& w = swaps_[s];
      const auto in = comm_->exchange(w.send_to, out[s - first], w.recv_from, w.tag);
      w.recv_first = p.size_with_ghosts();
      w.recv_count = 0;
      if (!in.empty()) {
        std::size_t pos = 0;
        w.recv_count = unpack_particles(p, in, pos);
      }
      p.n_ghost += w.recv_count;
      ghosts_ += w.recv_count;
    }
  }
  clear_ghost_accumulators(p);  // ghosts start with empty accumulators
}

void HaloExchange::refresh(Particles& p) const {
  if (p.n_ghost != ghosts_) throw std::logic_error("HaloExchange::refresh: the ghosts changed since the build");
  const ParticleArrays which = temperatures_ ? ParticleArrays::kMotionAndTemperature : ParticleArrays::kMotion;
  for (std::size_t first = 0; first < swaps_.size(); first += 2) {
    std::array<std::vector<std::byte>, 2> out;
    std::array<Communicator::KnownTransfer, 2> t;
    for (std::size_t s = 0; s < 2; ++s) {
      const Swap& w = swaps_[first + s];
      pack_particles(p, w.send, w.shift, out[s], which);
      // The neighbour sends the ghosts it sent at the build, so the length is known: one message.
      const std::size_t n_in = w.recv_from < 0 ? 0 : packed_bytes(p, w.recv_count, which);
      t[s] = {w.send_to, out[s], w.recv_from, n_in, w.tag};
    }
    const auto in = comm_->exchange_known(t);
    for (std::size_t s = 0; s < 2; ++s) {
      const Swap& w = swaps_[first + s];
      if (w.recv_count == 0) continue;
      std::size_t pos = 0;
      if (unpack_particles(p, in[s], pos, w.recv_first, which) != w.recv_count)
        throw std::runtime_error("HaloExchange::refresh: a neighbour sent another number of ghosts");
    }
  }
  clear_ghost_accumulators(p);
}

void HaloExchange::fold(Particles& p) const {
  // Per ghost: force (N), torque (N m), and the heat flow (W) with temperatures.
  const std::size_t each = temperatures_ ? 7 : 6;
  for (std::size_t first = swaps_.size(); first > 0;) {
    first -= 2;
    std::array<std::vector<double>, 2> back;
    std::array<Communicator::KnownTransfer, 2> t;
    for (std::size_t s = 0; s < 2; ++s) {
      const Swap& w = swaps_[first + s];
      back[s].resize(w.recv_count * each);
      for (std::size_t k = 0; k < w.recv_count; ++k) {
        const std::size_t g = w.recv_first + k;
        double* b = back[s].data() + k * each;
        for (int c = 0; c < 3; ++c) {
          b[c] = p.force[g][c];
          b[3 + c] = p.torque[g][c];
        }
        if (temperatures_) b[6] = p.heat[g];
      }
      // One value per particle sent at the build comes back (none when nothing was sent);
      // exchange_known refuses a message of another length.
      t[s] = {w.recv_from, std::as_bytes(std::span<const double>(back[s])), w.send_to,
              w.send.size() * each * sizeof(double), w.tag + 4};
    }
    const auto in = comm_->exchange_known(t);
    // The upper swap's first: the order of the sums as when the swaps travelled one by one.
    for (std::size_t s = 2; s-- > 0;) {
      const Swap& w = swaps_[first + s];
      for (std::size_t k = 0; k < w.send.size(); ++k) {
        double r[7] = {};
        std::memcpy(r, in[s].data() + k * each * sizeof(double), each * sizeof(double));
        const std::uint32_t i = w.send[k];
        p.force[i] += Vec3{r[0], r[1], r[2]};
        p.torque[i] += Vec3{r[3], r[4], r[5]};
        if (temperatures_) p.heat[i] += r[6];
      }
    }
  }
}

}  // namespace mpdem
