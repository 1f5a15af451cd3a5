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

namespace mpdem {

std::string ImpactSpeed::origin() const {
  if (speed <= 0.0) return "no initial motion and no fall";
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
  if (g > 0.0 && p.size() > 0) {
    const Vec3 down = prm.fields.gravity / g;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const auto take = [&](const Vec3& x) {
      lo = std::min(lo, dot(down, x));
      hi = std::max(hi, dot(down, x));
    };
    for (const Vec3& x : p.x) take(x);
    for (std::size_t e = 0; e < b.size(); ++e)
      for (int k = 0; k < 3; ++k) take(b.vertex(e, k));
    s.fall_height = hi - lo;
    if (prm.domain.bounded) {
      const Vec3 ext = prm.domain.max - prm.domain.min;
      s.fall_height = std::min(s.fall_height,
                               std::abs(down.x) * ext.x + std::abs(down.y) * ext.y + std::abs(down.z) * ext.z);
    }
  }
  s.speed = std::max(s.fastest, std::sqrt(2.0 * g * s.fall_height));
  return s;
}

namespace {

struct RadiusRange {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  std::size_t count = 0;
};

// Peak overlap of one impact: the law's Hertz modulus or linear stiffness, effective mass m (kg)
// and radius r (m) of the pair.
double peak_overlap(const PairLaw& law, double E_star, double m, double r, double v) {
  return law.law == ContactLawKind::Linear ? linear_peak_overlap(m, law.cn, v) : hertz_peak_overlap(m, E_star, r, v);
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
    const bool hertz = est.law == ContactLawKind::Hertz;
    // Hertz: delta ~ E*^(-2/5); linear: delta ~ k^(-1/2).
    const double stiffer = std::pow(est.ratio / limit, hertz ? 2.5 : 2.0);
    SceneProblem pr;
    pr.severity = Severity::Warning;
    pr.file = scene.file.string();
    pr.key = "checks.max_overlap";
    pr.message = fmt::format(
        "an impact at {:.3g} m/s ({}) between {} would overlap by about {:.3g} m, {:.3g}% of the {}radius ({} "
        "estimate without damping, an upper bound), more than checks.max_overlap = {:.3g}%: the run may stop with an "
        "overlap error. Use a stiffer material ({} x {:.3g} reaches the limit), a lower impact speed, or raise "
        "checks.max_overlap above {:.3g}.",
        speed.speed, speed.origin(), pair, est.overlap, 100.0 * est.ratio, est.barrier ? "" : "smaller ",
        hertz ? "Hertz" : "linear spring", 100.0 * limit, hertz ? "young" : "stiffness_normal", stiffer, est.ratio);
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
