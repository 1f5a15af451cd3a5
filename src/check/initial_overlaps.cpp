// Overlaps at t = 0 (check/initial_overlaps.hpp) and their report (check/scene_checks.hpp).
#include "check/initial_overlaps.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "check/scene_checks.hpp"
#include "check/source_lookup.hpp"
#include "neighbor/barrier_broadphase.hpp"
#include "neighbor/verlet_list.hpp"
#include "physics/barrier_contact_detect.hpp"
#include "state/barrier_topology.hpp"

namespace mpdem {

std::vector<PairOverlap> particle_overlaps(const Particles& p, double min_ratio) {
  std::vector<PairOverlap> found;
  if (p.size() < 2) return found;
  VerletList list;  // without skin it lists exactly the pairs closer than R_i + R_j
  // The members of one rigid body overlap by design: only members of different bodies count.
  list.build(p.x, p.radius, 0.0, 0.0, p.size(), {}, [&] {
    if (p.has_bodies()) list.drop_pairs_within_groups(p.body);
  });
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const std::uint32_t j : list.neighbors(i)) {
      const double overlap = p.radius[i] + p.radius[j] - norm(p.x[i] - p.x[j]);
      const double ratio = overlap / std::min(p.radius[i], p.radius[j]);
      if (ratio > min_ratio) found.push_back({i, j, overlap, ratio});
    }
  std::sort(found.begin(), found.end(), [](const PairOverlap& a, const PairOverlap& b) {
    return a.ratio != b.ratio ? a.ratio > b.ratio : std::pair(a.i, a.j) < std::pair(b.i, b.j);
  });
  return found;
}

std::vector<BarrierOverlap> barrier_overlaps(const Particles& p, const Barriers& b, double min_ratio) {
  std::vector<BarrierOverlap> found;
  if (p.size() == 0 || b.size() == 0) return found;
  BarrierBroadphase broad;
  broad.build(p.x, p.radius, b, 0.0);
  const BarrierTopology topo = BarrierTopology::build(b);
  std::vector<CurrentTriangle> tris(b.size());
  for (std::size_t e = 0; e < b.size(); ++e) tris[e] = current_triangle(b, e);
  std::vector<BarrierContact> contacts;
  for (const std::uint32_t i : broad.active()) {
    detect_barrier_contacts(b, topo, tris, p.x[i], p.radius[i], broad.candidates(i), contacts);
    for (const BarrierContact& c : contacts) {
      const double ratio = c.overlap / p.radius[i];
      if (ratio > min_ratio) found.push_back({i, c.element, c.overlap, ratio});
    }
  }
  std::sort(found.begin(), found.end(), [](const BarrierOverlap& x, const BarrierOverlap& y) {
    return x.ratio != y.ratio ? x.ratio > y.ratio : std::pair(x.i, x.e) < std::pair(y.i, y.e);
  });
  return found;
}

namespace {

struct Limit {
  double ratio;  // -, overlaps deeper than this are reported
  bool checked;  // checks.max_overlap > 0: the run stops on them
  std::string text;
};

Limit overlap_limit(const Params& prm) {
  const double m = prm.checks.max_overlap;
  if (m > 0.0) return {m, true, fmt::format("checks.max_overlap = {:.3g}%", 100.0 * m)};
  return {kInitialOverlapWarning, false,
          fmt::format("{:.3g}% (checks.max_overlap = 0: the check is off)", 100.0 * kInitialOverlapWarning)};
}

SceneProblem problem_at(const SourceLocation& where, const Limit& limit) {
  SceneProblem pr;
  pr.severity = limit.checked ? Severity::Error : Severity::Warning;
  pr.stops_run = limit.checked;
  pr.file = where.file;
  pr.line = where.line;
  pr.key = where.key;
  return pr;
}

std::string consequence(const Limit& limit) {
  return limit.checked ? "the run would stop at its first step with an overlap error, which a smaller time.dt does "
                         "not cure"
                       : "the contacts would push the particles apart violently at the first steps";
}

// " (bodies 3 and 4)", " (body 3 and a free sphere)" or "" for two free spheres.
std::string bodies_text(const Particles& p, std::size_t i, std::size_t j) {
  const auto one = [&](std::size_t k) {
    return p.body[k] == kNoBody ? std::string("a free sphere") : fmt::format("body {}", p.body[k]);
  };
  if (p.body[i] == kNoBody && p.body[j] == kNoBody) return "";
  if (p.body[i] != kNoBody && p.body[j] != kNoBody)
    return fmt::format(" (members of bodies {} and {})", p.body[i], p.body[j]);
  return " (member of " + one(p.body[i] == kNoBody ? j : i) + " and " + one(p.body[i] == kNoBody ? i : j) + ")";
}

void report_pairs(const Scene& scene, const Limit& limit, SceneProblems& out) {
  const Particles& p = scene.particles;
  std::map<std::pair<int, int>, std::vector<PairOverlap>> groups;  // by the two particles' sources
  for (const PairOverlap& o : particle_overlaps(p, limit.ratio)) {
    int a = particle_source_of(scene, o.i), b = particle_source_of(scene, o.j);
    groups[std::minmax(a, b)].push_back(o);
  }
  for (const auto& [sources, pairs] : groups) {
    const SourceLocation a = particle_source_location(scene, sources.first);
    const std::string of = sources.first == sources.second ? "particles of " + a.name
                                                           : "particles of " + a.name + " and of " +
                                                                 particle_source_location(scene, sources.second).name;
    std::string list;
    for (std::size_t k = 0; k < pairs.size() && k < kListedIds; ++k)
      list += fmt::format("{}ids {} and {}{} by {:.3g} m ({:.3g}%)", k ? ", " : "", p.id[pairs[k].i], p.id[pairs[k].j],
                          bodies_text(p, pairs[k].i, pairs[k].j), pairs[k].overlap, 100.0 * pairs[k].ratio);
    if (pairs.size() > kListedIds) list += fmt::format(" and {} more pairs", pairs.size() - kListedIds);
    SceneProblem pr = problem_at(a, limit);
    pr.message = fmt::format(
        "{} pair{} of {} overlap{} at t = 0 by more than {} of the smaller radius, deepest first: {}; {}. Move "
        "them apart (generate them with a gap) or raise checks.max_overlap.",
        pairs.size(), pairs.size() == 1 ? "" : "s", of, pairs.size() == 1 ? "s" : "", limit.text, list,
        consequence(limit));
    out.push_back(std::move(pr));
  }
}

void report_barriers(const Scene& scene, const Limit& limit, SceneProblems& out) {
  const Particles& p = scene.particles;
  const Barriers& b = scene.barriers;
  std::map<std::pair<int, int>, std::vector<BarrierOverlap>> groups;  // by barrier and particle source
  for (const BarrierOverlap& o : barrier_overlaps(p, b, limit.ratio))
    groups[{barrier_source_of(scene, o.e), particle_source_of(scene, o.i)}].push_back(o);
  for (const auto& [sources, contacts] : groups) {
    const SourceLocation bar = barrier_source_location(scene, sources.first);
    const SourceLocation par = particle_source_location(scene, sources.second);
    std::string list;
    for (std::size_t k = 0; k < contacts.size() && k < kListedIds; ++k)
      list += fmt::format(
          "{}particle id {}{} and element id {} by {:.3g} m ({:.3g}%)", k ? ", " : "", p.id[contacts[k].i],
          p.body[contacts[k].i] == kNoBody ? "" : fmt::format(" (member of body {})", p.body[contacts[k].i]),
          b.id[contacts[k].e], contacts[k].overlap, 100.0 * contacts[k].ratio);
    if (contacts.size() > kListedIds) list += fmt::format(" and {} more", contacts.size() - kListedIds);
    SceneProblem pr = problem_at(bar, limit);
    pr.message = fmt::format(
        "{} contact{} of particles of {} with barrier elements of {} overlap{} at t = 0 by more than {} of the "
        "particle radius, deepest first: {}; {}. Move the particles (or the barrier) apart or raise "
        "checks.max_overlap.",
        contacts.size(), contacts.size() == 1 ? "" : "s", par.name, bar.name, contacts.size() == 1 ? "s" : "",
        limit.text, list, consequence(limit));
    out.push_back(std::move(pr));
  }
}

}  // namespace

void check_initial_overlaps(const Scene& scene, SceneProblems& out) {
  const Limit limit = overlap_limit(scene.model.params);
  report_pairs(scene, limit, out);
  report_barriers(scene, limit, out);
}

}  // namespace mpdem
