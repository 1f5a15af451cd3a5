// Generated clump bodies (docs/scene.md "Clumps").
#include "generate/generated_bodies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "core/random.hpp"
#include "core/rotation.hpp"
#include "core/value_range.hpp"
#include "generate/generator.hpp"
#include "generate/region.hpp"
#include "model/body_members.hpp"

namespace mpdem {

// Four standard normals are isotropic in R^4, so their direction is uniform on the unit 3-sphere,
// which is the Haar measure on the rotations (q and -q alike).
Quat uniform_rotation(Rng& rng) {
  for (;;) {
    const Quat q{rng.normal(), rng.normal(), rng.normal(), rng.normal()};
    if (q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z > 1e-12) return quat_normalized(q);
  }
}

namespace {

// Cells of width h (m) holding the placed member spheres, by integer cell coordinates.
class MemberCells {
 public:
  explicit MemberCells(double h) : h_(h) {}
  // True when a sphere (c, r) keeps `gap` from every placed member.
  bool free(const Vec3& c, double r, double gap) const {
    const Key k0 = key(c);
    for (std::int64_t i = -1; i <= 1; ++i)
      for (std::int64_t j = -1; j <= 1; ++j)
        for (std::int64_t k = -1; k <= 1; ++k) {
          const auto at = cells_.find({k0[0] + i, k0[1] + j, k0[2] + k});
          if (at == cells_.end()) continue;
          for (const std::size_t m : at->second) {
            const double d = r + radius_[m] + gap;
            if (norm2(x_[m] - c) < d * d) return false;
          }
        }
    return true;
  }
  void insert(const Vec3& c, double r) {
    cells_[key(c)].push_back(x_.size());
    x_.push_back(c);
    radius_.push_back(r);
  }

 private:
  using Key = std::array<std::int64_t, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>((k[0] * 73856093) ^ (k[1] * 19349663) ^ (k[2] * 83492791));
    }
  };
  Key key(const Vec3& c) const {
    return {static_cast<std::int64_t>(std::floor(c.x / h_)), static_cast<std::int64_t>(std::floor(c.y / h_)),
            static_cast<std::int64_t>(std::floor(c.z / h_))};
  }
  double h_;                    // m, at least the largest contact distance of two members
  std::vector<Vec3> x_;         // m, placed members' centres [placed members]
  std::vector<double> radius_;  // m [placed members]
  std::unordered_map<Key, std::vector<std::size_t>, Hash> cells_;  // members per cell
};

// Random sequential addition of whole bodies tested member by member: a candidate is a centre
// drawn in the region and an orientation; it is kept when every member lies inside the region
// with `gap` and keeps `gap` from every member placed before. `templates[n]` is body n's; fills
// `placed` with the centres and orientations (template as written -> world).
void place_by_members(const GenerateSpec& spec, const Model& model, const std::vector<int>& templates,
                      std::vector<std::pair<Vec3, Quat>>& placed) {
  const Region region(spec.region, spec.origin, spec.line);
  double r_max = 0.0;  // m, the largest member radius
  for (const int c : templates)
    for (const ClumpMember& m : model.clumps[static_cast<std::size_t>(c)].members()) r_max = std::max(r_max, m.r);
  MemberCells cells(2.0 * r_max + spec.gap);
  Rng rng(spec.seed);
  std::vector<Vec3> x;  // m, the candidate's members [members]
  for (std::size_t n = 0; n < templates.size(); ++n) {
    const ClumpTemplate& t = model.clumps[static_cast<std::size_t>(templates[n])];
    x.resize(t.members().size());
    bool done = false;
    for (std::size_t a = 0; a < spec.max_attempts && !done; ++a) {
      Vec3 c;
      if (!region.sample(rng, 0.0, c)) continue;
      const Quat q = uniform_rotation(rng);
      // The members as add_body places them: principal frame -> world is q * to_input.
      const Mat3 R = quat_matrix(quat_normalized(quat_multiply(q, t.shape.to_input)));
      bool ok = true;
      for (std::size_t k = 0; k < x.size() && ok; ++k) {
        const ClumpMember& m = t.members()[k];
        x[k] = c + mat_apply(R, m.x);
        ok = region.holds(x[k], m.r + spec.gap) && cells.free(x[k], m.r, spec.gap);
      }
      if (!ok) continue;
      for (std::size_t k = 0; k < x.size(); ++k) cells.insert(x[k], t.members()[k].r);
      placed.push_back({c, q});
      done = true;
    }
    if (!done)
      throw InputError(spec.origin, spec.line, "generate",
                       "could not place body " + std::to_string(n + 1) + " of " + std::to_string(templates.size()) +
                           " of clump '" + t.name + "' in " + std::to_string(spec.max_attempts) +
                           " random attempts (centre and orientation, tested member by member); lower "
                           "count/solid_fraction or gap, enlarge the region, or raise max_attempts");
  }
}

// "clump 'a'" or "clumps 'a', 'b'": the templates of a mix, for messages.
std::string mix_names(const Model& model, const ClumpMix& mix) {
  std::string out = mix.clumps.size() == 1 ? "clump " : "clumps ";
  for (std::size_t i = 0; i < mix.clumps.size(); ++i)
    out += (i ? ", '" : "'") + model.clumps[static_cast<std::size_t>(mix.clumps[i])].name + "'";
  return out;
}

}  // namespace

void add_generated_bodies(const GenerateSpec& spec, const Model& model, int material, const ClumpMix& mix,
                          Particles& out) {
  const auto fail = [&](const std::string& msg) { throw InputError(spec.origin, spec.line, "generate", msg); };
  const Material& m = model.materials.at(static_cast<std::size_t>(material));
  const std::string names = mix_names(model, mix);
  const double reach = mix.reach(model.clumps);  // m
  GenerateSpec bounding = spec;
  bounding.radius = RadiusDistribution{};
  bounding.radius.value = reach;
  if (spec.count == 0) {
    // A solid fraction of the bodies' own volume: the count whose volume is closest to it.
    if (!(spec.solid_fraction > 0.0 && spec.solid_fraction < 1.0))
      fail("give a count >= 1 or a solid_fraction in (0, 1)");
    const double n = spec.solid_fraction * Region(spec.region, spec.origin, spec.line).volume() /
                     mix.mean_volume(model.clumps);
    if (!(n >= 0.5)) fail("the requested solid fraction is smaller than one body of " + names);
    if (!(n < 5e7)) fail("the solid fraction needs more than 5e7 bodies of " + names + "; check units");
    bounding.count = static_cast<std::size_t>(std::llround(n));
    bounding.solid_fraction = 0.0;
  }
  // Each body's template, from a stream of its own (none drawn for a single template).
  std::vector<int> templates(bounding.count);
  Rng trng(spec.seed ^ 0xA0761D6478BD642Full);
  for (int& c : templates) c = mix.draw(trng);
  std::vector<std::pair<Vec3, Quat>> placed;  // centre of mass (m) and orientation of each body
  std::vector<Vec3> v;                        // m/s, initial velocity of each body
  if (spec.placement == BodyPlacement::Members) {
    if (!(spec.gap >= 0.0) || !std::isfinite(spec.gap)) fail("expected a gap >= 0, got " + number_text(spec.gap));
    if (spec.max_attempts == 0) fail("expected max_attempts >= 1");
    place_by_members(spec, model, templates, placed);
    // Velocities as the sphere generator draws them (generate/generator.cpp).
    Rng vrng(spec.seed ^ 0x9E3779B97F4A7C15ull);
    for (std::size_t b = 0; b < placed.size(); ++b)
      v.push_back(spec.speed > 0.0 ? vrng.unit_vector() * spec.speed : spec.velocity.value_or(Vec3{}));
  } else {
    // Orientations from their own stream: the centres are the sphere generator's for the same seed.
    Rng qrng(spec.seed ^ 0xD1B54A32D192ED03ull);
    GenerateResult spheres;
    try {
      spheres = generate_particles(bounding);
    } catch (const InputError& e) {  // its message speaks of spheres: say they are the bodies' bounding spheres
      const std::string what = e.what();
      const std::size_t at = what.find("'generate': ");
      fail(names + " bodies placed by their bounding spheres (radius " + number_text(reach) + " m): " +
           (at == std::string::npos ? what : what.substr(at + 12)) + "; placement = \"members\" packs denser");
    }
    for (const GeneratedParticle& g : spheres.particles) {
      placed.push_back({g.x, uniform_rotation(qrng)});
      v.push_back(g.v);
    }
  }

  std::int64_t next_id = 0;
  for (const std::int64_t b : out.bodies.id) next_id = std::max(next_id, b + 1);
  for (std::size_t b = 0; b < placed.size(); ++b) {
    BodyInit init;
    init.id = next_id++;
    init.x = placed[b].first;
    init.v = v[b];
    init.q = placed[b].second;
    init.T = m.temperature;
    init.charge = m.charge;
    init.fixed = spec.fixed;
    add_body(model, material, templates[b], init, out);
  }
}

}  // namespace mpdem
