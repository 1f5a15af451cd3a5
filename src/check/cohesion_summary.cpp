#include "check/cohesion_summary.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "contact/cohesion_reach.hpp"

namespace mpdem {

namespace {

const char* bridge_model_name(BridgeModel m) {
  return m == BridgeModel::willett ? "willett" : m == BridgeModel::rabinovich ? "rabinovich" : "none";
}

// One line for the law of a pair (r*, inv_reach: the two spheres', or R and 0 at a barrier).
std::string law_line(const std::string& what, const PairLaw& c, double r_star) {
  std::string out;
  with_law(c.law, [&]<class Law>(std::type_identity<Law>) {
    if constexpr (Law::kAdhesion) {
      // The pull-off: the most attractive force of the law at rest (its clamp floor).
      const Stiffness s = Law::stiffness(c, r_star, 0.0, 0.0);
      out = fmt::format("  {} {}: pull-off {:.4g} N", what, Law::kCohesion, s.adhesion);
      if constexpr (Law::kHysteresis)
        out += fmt::format(", the neck holds to an overlap of {:.4g} m", break_overlap<Law>(c, r_star));
    }
  });
  return out;
}

std::string bridge_line(const std::string& what, const BridgeLaw& b, double r_star, double inv_reach) {
  if (b.model == BridgeModel::none) return {};
  const BridgeForce f = bridge_force(b, r_star, inv_reach, 0.0, 0.0);
  return fmt::format("  {} liquid bridge ({}): volume {:.4g} m^3, {:.4g} N at touching, ruptures at a gap of {:.4g} m",
                     what, bridge_model_name(b.model), bridge_volume(b, r_star, inv_reach), -f.fn,
                     bridge_rupture_distance(b, r_star, inv_reach));
}

}  // namespace

std::vector<std::string> cohesion_summary_lines(const Scene& scene) {
  ContactTable t;
  t.build(scene.model);
  const bool adhesive = [&] {
    bool any = false;
    for_each_law([&]<class L>(std::type_identity<L>, LawId id) {
      any = any || (L::kAdhesion && (((t.particle_laws() | t.barrier_laws()) >> id) & 1u));
    });
    return any;
  }();
  if (!adhesive && !has_cohesion(t)) return {};
  const double r = largest_radius(scene.model, scene.particles);  // m
  std::vector<std::string> lines;
  lines.push_back(fmt::format("cohesion: for two spheres of radius {:.4g} m (the largest), r* = {:.4g} m", r, 0.5 * r));
  const std::size_t n = t.materials();
  const std::vector<Material>& mats = scene.model.materials;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a; b < n; ++b) {
      const std::string pair = mats[a].name + " - " + mats[b].name;
      for (const std::string& l : {law_line(pair, t.particle_pair(a, b), 0.5 * r),
                                   bridge_line(pair, t.particle_bridge(a, b), 0.5 * r, 0.5 / r)})
        if (!l.empty()) lines.push_back(l);
    }
  const bool barriers = !scene.barriers.material.empty();
  for (std::size_t a = 0; a < n && barriers; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (std::find(scene.barriers.material.begin(), scene.barriers.material.end(), static_cast<int>(b)) ==
          scene.barriers.material.end())
        continue;
      const std::string pair = mats[a].name + " - barrier " + mats[b].name;
      for (const std::string& l :
           {law_line(pair, t.barrier_pair(a, b), r), bridge_line(pair, t.barrier_bridge(a, b), r, 0.0)})
        if (!l.empty()) lines.push_back(l);
    }
  const double pp = particle_cohesion_gap(t, r), pb = barriers ? barrier_cohesion_gap(t, r) : 0.0;
  if (pp > 0.0 || pb > 0.0)
    lines.push_back(fmt::format("  contacts held past touching: the neighbour list reaches {:.4g} m beyond touching{}",
                                pp, barriers ? fmt::format(", the barrier detection {:.4g} m", pb) : ""));
  return lines;
}

}  // namespace mpdem
