#include "check/source_lookup.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <vector>

namespace mpdem {

namespace {
// Sources are appended in order, so their ranges ascend: the last one starting at or before
// `index` holds it, if its range does.
template <class Source>
int source_of(const std::vector<Source>& sources, std::size_t index) {
  const auto after = std::upper_bound(sources.begin(), sources.end(), index,
                                      [](std::size_t k, const Source& s) { return k < s.first; });
  if (after == sources.begin()) return -1;
  const auto& s = *(after - 1);
  return index < s.first + s.count ? static_cast<int>(after - 1 - sources.begin()) : -1;
}
}  // namespace

int particle_source_of(const Scene& scene, std::size_t i) {
  if (i >= scene.particles.size()) return -1;
  return source_of(scene.particle_sources, i);
}

int barrier_source_of(const Scene& scene, std::size_t e) {
  if (e >= scene.barriers.size()) return -1;
  return source_of(scene.barrier_sources, e);
}

SourceLocation particle_source_location(const Scene& scene, int s) {
  if (s < 0 || static_cast<std::size_t>(s) >= scene.particle_sources.size())
    return {scene.file.string(), 0, "", "the scene"};
  const ParticleSource& src = scene.particle_sources[static_cast<std::size_t>(s)];
  if (src.generate)
    return {scene.file.string(), src.line, "particles.generate",
            fmt::format("[[particles]] entry {} (generated)", s + 1)};
  return {src.file.string(), 0, "", fmt::format("'{}'", src.file.filename().string())};
}

SourceLocation barrier_source_location(const Scene& scene, int s) {
  if (s < 0 || static_cast<std::size_t>(s) >= scene.barrier_sources.size())
    return {scene.file.string(), 0, "", "the scene"};
  const BarrierSource& src = scene.barrier_sources[static_cast<std::size_t>(s)];
  const std::filesystem::path& f = src.stl.empty() ? src.file : src.stl;
  std::string name = fmt::format("'{}'", f.filename().string());
  if (!src.group.empty()) name += fmt::format(" (group {})", src.group);
  return {scene.file.string(), src.line, "barriers", name};
}

SceneProblem problem_at(const SourceLocation& where, Severity severity, bool stops_run, std::string message) {
  SceneProblem pr;
  pr.severity = severity;
  pr.file = where.file;
  pr.line = where.line;
  pr.key = where.key;
  pr.stops_run = stops_run;
  pr.message = std::move(message);
  return pr;
}

}  // namespace mpdem
