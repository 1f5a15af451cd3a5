// Particles and clump bodies outside the domain at t = 0 (check/scene_checks.hpp).
#include <fmt/core.h>

#include <map>
#include <set>
#include <vector>

#include "check/scene_checks.hpp"
#include "check/source_lookup.hpp"
#include "integrate/health_scan.hpp"

namespace mpdem {

void check_outside_domain(const Scene& scene, SceneProblems& out) {
  const DomainParams& d = scene.model.params.domain;
  if (!d.bounded) return;
  const Particles& p = scene.particles;
  // source -> particle indices, ascending; a clump body is listed once, by its first member outside
  // (one member outside is enough: the run would remove or stop on it).
  std::map<int, std::vector<std::size_t>> by_source;
  std::set<std::int64_t> bodies_listed;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!inside_domain(d, p.x[i]) && (p.body[i] == kNoBody || bodies_listed.insert(p.body[i]).second))
      by_source[particle_source_of(scene, i)].push_back(i);
  const bool stop = d.on_exit == ExitPolicy::Stop;
  for (const auto& [source, idx] : by_source) {
    const SourceLocation where = particle_source_location(scene, source);
    std::size_t bodies = 0;
    for (const std::size_t i : idx) bodies += p.body[i] == kNoBody ? 0 : 1;
    std::string list;
    for (std::size_t k = 0; k < idx.size() && k < kListedIds; ++k) {
      const std::size_t i = idx[k];
      const std::string at = fmt::format("at ({:.6g}, {:.6g}, {:.6g})", p.x[i].x, p.x[i].y, p.x[i].z);
      list += k ? ", " : "";
      list += p.body[i] == kNoBody ? fmt::format("id {} {}", p.id[i], at)
                                   : fmt::format("body id {} (its member id {} {})", p.body[i], p.id[i], at);
    }
    if (idx.size() > kListedIds) list += fmt::format(" and {} more", idx.size() - kListedIds);
    const std::size_t n = idx.size();
    const std::string what = bodies == n ? (n == 1 ? "clump body" : "clump bodies")
                                         : (bodies == 0 ? (n == 1 ? "particle" : "particles") : "particles and bodies");
    SceneProblem pr;
    pr.severity = Severity::Error;
    pr.file = where.file;
    pr.line = where.line;
    pr.key = where.key;
    pr.stops_run = stop;
    pr.message = fmt::format("{} {} of {} {} outside the domain [({:.6g}, {:.6g}, {:.6g}), ({:.6g}, {:.6g}, "
                             "{:.6g})] at t = 0: {}; with "
                             "domain.on_exit = \"{}\" {}. Move them inside or enlarge [domain] min/max.",
                             n, what, where.name, n == 1 ? "lies" : "lie", d.min.x, d.min.y, d.min.z, d.max.x, d.max.y,
                             d.max.z, list, stop ? "stop" : "remove",
                             stop ? "the run would stop at its first step" : "they would be removed at the first step");
    out.push_back(std::move(pr));
  }
}

}  // namespace mpdem
