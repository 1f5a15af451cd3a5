// Particles outside the domain at t = 0 (check/scene_checks.hpp).
#include <fmt/core.h>

#include <map>
#include <vector>

#include "check/scene_checks.hpp"
#include "check/source_lookup.hpp"
#include "integrate/health_scan.hpp"

namespace mpdem {

void check_outside_domain(const Scene& scene, SceneProblems& out) {
  const DomainParams& d = scene.model.params.domain;
  if (!d.bounded) return;
  const Particles& p = scene.particles;
  std::map<int, std::vector<std::size_t>> by_source;  // source -> particle indices, ascending
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!inside_domain(d, p.x[i])) by_source[particle_source_of(scene, i)].push_back(i);
  const bool stop = d.on_exit == ExitPolicy::Stop;
  for (const auto& [source, idx] : by_source) {
    const SourceLocation where = particle_source_location(scene, source);
    std::string list;
    for (std::size_t k = 0; k < idx.size() && k < kListedIds; ++k) {
      const std::size_t i = idx[k];
      list += fmt::format("{}id {} at ({:.6g}, {:.6g}, {:.6g})", k ? ", " : "", p.id[i], p.x[i].x, p.x[i].y, p.x[i].z);
    }
    if (idx.size() > kListedIds) list += fmt::format(" and {} more", idx.size() - kListedIds);
    SceneProblem pr;
    pr.severity = Severity::Error;
    pr.file = where.file;
    pr.line = where.line;
    pr.key = where.key;
    pr.stops_run = stop;
    pr.message = fmt::format("{} particle{} of {} {} outside the domain [({:.6g}, {:.6g}, {:.6g}), ({:.6g}, {:.6g}, "
                             "{:.6g})] at t = 0: {}; with "
                             "domain.on_exit = \"{}\" {}. Move them inside or enlarge [domain] min/max.",
                             idx.size(), idx.size() == 1 ? "" : "s", where.name, idx.size() == 1 ? "lies" : "lie",
                             d.min.x, d.min.y, d.min.z, d.max.x, d.max.y, d.max.z, list, stop ? "stop" : "remove",
                             stop ? "the run would stop at its first step" : "they would be removed at the first step");
    out.push_back(std::move(pr));
  }
}

}  // namespace mpdem
