// A periodic [domain]: barriers crossing its periodic faces and periods too short for the
// neighbour search (check/scene_checks.hpp).
#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <vector>

#include "check/scene_checks.hpp"
#include "check/source_lookup.hpp"
#include "field/near_field_forces.hpp"
#include "parallel/periodic_images.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

namespace {
constexpr const char* kAxes = "xyz";

SceneProblem domain_problem(const Scene& scene, std::string message) {
  const SourceLocation where{scene.file.string(), scene.model.params.domain.periodic_line, "domain.periodic", ""};
  return problem_at(where, Severity::Error, true, std::move(message));
}
}  // namespace

void check_periodic_domain(const Scene& scene, SceneProblems& out) {
  const DomainParams& d = scene.model.params.domain;
  if (!d.bounded || !d.any_periodic()) return;
  const Barriers& b = scene.barriers;
  // An element may end on a periodic face (a chute base spanning the period), not beyond it.
  std::map<int, std::vector<std::size_t>> by_source;  // source -> crossing elements, ascending
  for (std::size_t e = 0; e < b.size(); ++e) {
    bool crosses = false;
    for (int c = 0; c < 3; ++c) {
      if (!d.periodic[static_cast<std::size_t>(c)]) continue;
      const double tol = 1e-9 * (d.max[c] - d.min[c]);
      for (int k = 0; k < 3; ++k) {
        const double v = b.vertex(e, k)[c];  // m, as placed at t = 0
        crosses = crosses || v < d.min[c] - tol || v > d.max[c] + tol;
      }
    }
    if (crosses) by_source[barrier_source_of(scene, e)].push_back(e);
  }
  for (const auto& [source, elems] : by_source) {
    const SourceLocation where = barrier_source_location(scene, source);
    std::string list;
    for (std::size_t k = 0; k < elems.size() && k < kListedIds; ++k)
      list += fmt::format("{}{}", k ? ", " : "", b.id[elems[k]]);
    if (elems.size() > kListedIds) list += fmt::format(" and {} more", elems.size() - kListedIds);
    out.push_back(problem_at(
        where, Severity::Error, true,
        fmt::format("{} barrier element{} of {} cross{} a periodic face of the domain [({:.6g}, {:.6g}, {:.6g}), "
                    "({:.6g}, {:.6g}, {:.6g})] (element ids {}): barriers are not repeated across the period, so a "
                    "particle would meet the wall on one side only. Trim the barrier to the period, or make that "
                    "axis non-periodic.",
                    elems.size(), elems.size() == 1 ? "" : "s", where.name, elems.size() == 1 ? "es" : "", d.min.x,
                    d.min.y, d.min.z, d.max.x, d.max.y, d.max.z, list)));
  }
  const Particles& p = scene.particles;
  if (p.size() == 0) return;
  const double rmax = *std::max_element(p.radius.begin(), p.radius.begin() + static_cast<std::ptrdiff_t>(p.size()));
  const double offset = largest_member_offset(scene.model.clumps);  // m, clump members outside the period
  const double width = periodic_image_width(rmax, near_field_extra_range(scene.model.params.near_field, p),
                                            default_skin(scene.model, p), offset);
  for (int c = 0; c < 3; ++c) {
    const double L = d.max[c] - d.min[c];
    if (!d.periodic[static_cast<std::size_t>(c)] || L >= 2.0 * width) continue;
    out.push_back(domain_problem(
        scene,
        fmt::format("the domain is {:.6g} m long along the periodic axis {}, shorter than twice the neighbour "
                    "search's reach {:.6g} m (2 x the largest radius {:.6g} m + near-field reach + 2 skins{}): a "
                    "particle could meet two images of another. Enlarge [domain] min/max along {}.",
                    L, kAxes[c], width, rmax,
                    offset > 0.0 ? fmt::format(" + the largest clump member offset {:.6g} m", offset) : "", kAxes[c])));
  }
}

}  // namespace mpdem
