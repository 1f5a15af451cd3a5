// Impact overlap estimates (check/impact_overlap.hpp) and their report (check/scene_checks.hpp).
#include "check/impact_overlap.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "check/scene_checks.hpp"
#include "contact/contact_table.hpp"
#include "physics/barrier_moduli.hpp"
#include "physics/hertz.hpp"
#include "physics/time_step_estimate.hpp"
#include "sim/inlets.hpp"

namespace mpdem {

std::string ImpactSpeed::origin() const {
  if (speed <= 0.0) return "no initial motion and no fall";
  if (!inlet.empty())
    return inlet_fall > 0.0 ? fmt::format("inlet '{}': inserted at {:.3g} m/s, then a fall of {:.3g} m under gravity",
                                          inlet, insertion_speed, inlet_fall)
                            : fmt::format("inlet '{}': inserted at {:.3g} m/s", inlet, insertion_speed);
  if (fastest >= speed) return "the fastest initial particle speed";
  return fmt::format("a fall of {:.3g} m under gravity", fall_height);
}

ImpactSpeed expected_impact_speed(const Scene& scene) {
  const Particles& p = scene.particles;
  const Barriers& b = scene.barriers;
  const Params& prm = scene.model.params;
  ImpactSpeed s;
  for (std::size_t i = 0; i < p.size(); ++i) s.fastest = std::max(s.fastest, norm(p.v[i]));
  const double g = norm(prm.fields.gravity);
  const Vec3 down = g > 0.0 ? prm.fields.gravity / g : Vec3{};
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;  // m, along gravity
  const auto take = [&](const Vec3& x) {
    lo = std::min(lo, dot(down, x));
    hi = std::max(hi, dot(down, x));
  };
  for (const Vec3& x : p.x) take(x);
  for (std::size_t e = 0; e < b.size(); ++e)
    for (int k = 0; k < 3; ++k) take(b.vertex(e, k));
  // m, the domain's extent along gravity and its lowest point
  double extent = std::numeric_limits<double>::infinity(), bottom = extent;
  if (prm.domain.bounded) {
    const Vec3 ext = prm.domain.max - prm.domain.min;
    extent = std::abs(down.x) * ext.x + std::abs(down.y) * ext.y + std::abs(down.z) * ext.z;
    bottom = dot(down, (prm.domain.min + prm.domain.max) * 0.5) + 0.5 * extent;
  }
  if (g > 0.0 && p.size() > 0) s.fall_height = std::min(hi - lo, extent);
  s.speed = std::max(s.fastest, std::sqrt(2.0 * g * s.fall_height));
  // The inlets' particles: the top of each volume (the centres of its smallest particles) falls
  // to the lowest point of everything, its own and the other inlets' volumes included.
  std::vector<std::pair<double, double>> tops;  // per inlet: m, top along gravity; m/s, insertion speed
  for (const InletSpec& in : prm.inlets) {
    Vec3 a, c;
    smallest_centre_box(in, a, c);
    double top = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 8; ++k) {
      const Vec3 x{k & 1 ? c.x : a.x, k & 2 ? c.y : a.y, k & 4 ? c.z : a.z};
      take(x);
      top = std::min(top, dot(down, x));
    }
    tops.emplace_back(top, norm(in.velocity) + std::sqrt(3.0) * in.velocity_spread);
  }
  for (std::size_t j = 0; j < tops.size(); ++j) {
    const double fall = g > 0.0 ? std::max(0.0, std::min(hi, bottom) - tops[j].first) : 0.0;  // m
    const double v = std::sqrt(tops[j].second * tops[j].second + 2.0 * g * fall);             // m/s
    if (v > s.speed) {
      s.speed = v;
      s.inlet = prm.inlets[j].name;
      s.insertion_speed = tops[j].second;
      s.inlet_fall = fall;
    }
  }
  return s;
}

namespace {

struct RadiusRange {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  std::size_t count = 0;
};

// Peak overlap of one impact by the pair's law (contact/laws/), from the materials' effective
// modulus E* (Pa), effective mass m (kg) and radius r (m) of the pair.
double peak_overlap(const PairLaw& law, double E_star, double m, double r, double v) {
  return with_law(law.law, [&]<class Law>(std::type_identity<Law>) { return Law::peak_overlap(law, E_star, m, r, v); });
}

}  // namespace

std::vector<ImpactEstimate> impact_estimates(const Scene& scene, double speed) {
  std::vector<ImpactEstimate> out;
  if (!(speed > 0.0)) return out;
  const std::vector<Material>& mats = scene.model.materials;
  const Particles& p = scene.particles;
  const Barriers& bars = scene.barriers;
  std::vector<RadiusRange> radii(mats.size());
  std::vector<char> barrier_material(mats.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    RadiusRange& r = radii[static_cast<std::size_t>(p.material[i])];
    r.lo = std::min(r.lo, p.radius[i]);
    r.hi = std::max(r.hi, p.radius[i]);
    ++r.count;
  }
  for (const InletSpec& in : scene.model.params.inlets) {  // many particles each, from the smallest to the largest
    const int k = in.material.empty() ? 0 : scene.model.material_index(in.material);
    if (k < 0 || static_cast<std::size_t>(k) >= mats.size() || !(in.radius.smallest() > 0.0)) continue;
    RadiusRange& r = radii[static_cast<std::size_t>(k)];
    r.lo = std::min(r.lo, in.radius.smallest());
    r.hi = std::max(r.hi, in.radius.largest());
    r.count += 2;
  }
  for (const int m : bars.material)
    if (m >= 0) barrier_material[static_cast<std::size_t>(m)] = 1;
  ContactTable table;  // the laws the run's kernels will use
  table.build(scene.model);
  for (std::size_t a = 0; a < mats.size(); ++a) {
    if (radii[a].count == 0) continue;
    const Material& ma = mats[a];
    for (std::size_t b = a; b < mats.size(); ++b) {
      if (radii[b].count == 0 || (a == b && radii[a].count < 2)) continue;  // no such pair
      const Material& mb = mats[b];
      const PairLaw& law = table.particle_pair(a, b);
      const double E = effective_modulus(ma.young, ma.poisson, mb.young, mb.poisson);
      ImpactEstimate est{static_cast<int>(a), static_cast<int>(b), false, law.law};
      // The smaller sphere of one against the larger of the other, both ways.
      for (const auto& [Ra, Rb] : {std::pair(radii[a].lo, radii[b].hi), std::pair(radii[a].hi, radii[b].lo)}) {
        const double m = effective_mass(sphere_mass(Ra, ma.density), sphere_mass(Rb, mb.density));
        const double delta = peak_overlap(law, E, m, effective_radius(Ra, Rb), speed);
        const double R = std::min(Ra, Rb);
        if (delta / R > est.ratio) {
          est.overlap = delta;
          est.radius = R;
          est.ratio = delta / R;
        }
      }
      out.push_back(est);
    }
    for (std::size_t b = 0; b < mats.size(); ++b) {
      if (!barrier_material[b]) continue;
      const Material& mb = mats[b];
      const PairLaw& law = table.barrier_pair(a, b);
      // Against a barrier (r* = R, m* = m) the Hertz ratio does not depend on R; the linear one
      // grows with it, so take the largest sphere.
      const double R = radii[a].hi;
      const double delta = peak_overlap(law, barrier_effective_modulus(ma.young, ma.poisson, mb.young, mb.poisson),
                                        sphere_mass(R, ma.density), R, speed);
      out.push_back({static_cast<int>(a), static_cast<int>(b), true, law.law, delta, R, delta / R});
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const ImpactEstimate& x, const ImpactEstimate& y) { return x.ratio > y.ratio; });
  return out;
}

void check_impact_overlaps(const Scene& scene, SceneProblems& out) {
  const double limit = scene.model.params.checks.max_overlap;
  if (!(limit > 0.0)) return;
  const ImpactSpeed speed = expected_impact_speed(scene);
  const std::vector<Material>& mats = scene.model.materials;
  std::size_t over = 0;
  for (const ImpactEstimate& est : impact_estimates(scene, speed.speed)) {
    if (!(est.ratio > limit)) break;  // deepest first
    if (++over > kListedIds) continue;
    const Material& ma = mats[static_cast<std::size_t>(est.a)];
    const Material& mb = mats[static_cast<std::size_t>(est.b)];
    const std::string pair = est.barrier
                                 ? fmt::format("a particle of material '{}' on a barrier of material '{}'{}", ma.name,
                                               mb.name, is_rigid(mb) ? " (rigid)" : "")
                                 : (est.a == est.b
                                        ? fmt::format("two particles of material '{}'", ma.name)
                                        : fmt::format("particles of materials '{}' and '{}'", ma.name, mb.name));
    // The law's estimate, its stiffness key and how the overlap falls with it (Hertz: delta ~
    // E*^(-2/5); linear: delta ~ k^(-1/2)).
    std::string_view spring, stiffness_key;
    double exponent = 0.0;
    with_law(est.law, [&]<class Law>(std::type_identity<Law>) {
      spring = Law::kSpringName, stiffness_key = Law::kStiffnessKey, exponent = Law::kOverlapExponent;
    });
    const double stiffer = std::pow(est.ratio / limit, exponent);
    SceneProblem pr;
    pr.severity = Severity::Warning;
    pr.file = scene.file.string();
    pr.key = "checks.max_overlap";
    pr.message = fmt::format(
        "an impact at {:.3g} m/s ({}) between {} would overlap by about {:.3g} m, {:.3g}% of the {}radius ({} "
        "estimate without damping, an upper bound), more than checks.max_overlap = {:.3g}%: the run may stop with an "
        "overlap error. Use a stiffer material ({} x {:.3g} reaches the limit), a lower impact speed, or raise "
        "checks.max_overlap above {:.3g}.",
        speed.speed, speed.origin(), pair, est.overlap, 100.0 * est.ratio, est.barrier ? "" : "smaller ", spring,
        100.0 * limit, stiffness_key, stiffer, est.ratio);
    out.push_back(std::move(pr));
  }
  if (over > kListedIds) {
    SceneProblem pr;
    pr.severity = Severity::Warning;
    pr.file = scene.file.string();
    pr.key = "checks.max_overlap";
    pr.message = fmt::format("{} more material pairs exceed checks.max_overlap at that speed", over - kListedIds);
    out.push_back(std::move(pr));
  }
}

}  // namespace mpdem
