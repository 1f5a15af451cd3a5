// [[inlet]] entries that cannot insert what they promise (check/scene_checks.hpp): a volume
// outside a bounded domain, a start after the run's end.
#include <fmt/core.h>

#include <string>

#include "check/scene_checks.hpp"
#include "sim/inlets.hpp"

namespace mpdem {

namespace {

constexpr const char* kAxes = "xyz";

SceneProblem inlet_problem(const Scene& scene, const InletSpec& in, const char* key, Severity severity, bool stops,
                           std::string message) {
  SceneProblem pr;
  pr.severity = severity;
  pr.file = scene.file.string();
  pr.line = in.line;
  pr.key = key;
  pr.stops_run = stops;
  pr.message = std::move(message);
  return pr;
}

// Where the centres of an inlet's particles may lie, against the domain along its bounded axes.
void check_inlet_in_domain(const Scene& scene, const InletSpec& in, SceneProblems& out) {
  const DomainParams& d = scene.model.params.domain;
  if (!d.bounded) return;
  Vec3 lo, hi;  // m, the box of the centres of the smallest particles (they come nearest the faces)
  smallest_centre_box(in, lo, hi);
  bool apart = false, beyond = false;  // no centre / some centres outside the domain
  std::string axes;                    // the axes along which it reaches out
  for (int c = 0; c < 3; ++c) {
    if (d.periodic[static_cast<std::size_t>(c)]) continue;  // wrapped into the period
    const double tol = 1e-9 * (d.max[c] - d.min[c]);
    apart = apart || hi[c] < d.min[c] - tol || lo[c] > d.max[c] + tol;
    if (lo[c] < d.min[c] - tol || hi[c] > d.max[c] + tol) {
      beyond = true;
      axes += axes.empty() ? std::string(1, kAxes[c]) : std::string(", ") + kAxes[c];
    }
  }
  if (!beyond) return;
  const bool stop = d.on_exit == ExitPolicy::Stop;
  const std::string where = fmt::format(
      "the particles of [[inlet]] '{}' would be placed with centres in ({:.6g}, {:.6g}, {:.6g}) .. "
      "({:.6g}, {:.6g}, {:.6g}) m, {} the domain [({:.6g}, {:.6g}, {:.6g}), ({:.6g}, {:.6g}, {:.6g})] "
      "(along {})",
      in.name, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, apart ? "entirely outside" : "partly outside", d.min.x, d.min.y,
      d.min.z, d.max.x, d.max.y, d.max.z, axes);
  const std::string fate = stop ? "with domain.on_exit = \"stop\" the run would stop at the first one placed outside"
                                : "with domain.on_exit = \"remove\" those placed outside would be removed after the "
                                  "next step, so the inlet inserts less than its rate";
  const std::string remedy = "Move the inlet's region inside the domain or enlarge [domain] min/max.";
  if (apart)
    out.push_back(inlet_problem(scene, in, "inlet", Severity::Error, stop,
                                fmt::format("{}: it would insert nothing that stays; {}. {}", where, fate, remedy)));
  else
    out.push_back(inlet_problem(scene, in, "inlet", stop ? Severity::Error : Severity::Warning, false,
                                fmt::format("{}: {}. {}", where, fate, remedy)));
}

}  // namespace

void check_inlets(const Scene& scene, SceneProblems& out) {
  const Params& prm = scene.model.params;
  for (const InletSpec& in : prm.inlets) {
    check_inlet_in_domain(scene, in, out);
    if (in.start >= prm.time.duration)
      out.push_back(inlet_problem(
          scene, in, "inlet.start", Severity::Warning, false,
          fmt::format("[[inlet]] '{}' starts at t = {:.6g} s, not before the run's end time.duration = {:.6g} s: it "
                      "inserts nothing in this run (a resume with a longer duration would start it). Give an "
                      "earlier start or a longer duration.",
                      in.name, in.start, prm.time.duration)));
  }
}

}  // namespace mpdem
