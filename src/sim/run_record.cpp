#include "sim/run_record.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace mpdem {

double energy_drift(const RunRecord& r) {
  double scale = std::max(std::abs(r.start_balance), r.start_active);
  if (!(scale > 0.0)) scale = r.peak_active;
  if (!(scale > 0.0)) return 0.0;
  return (r.balance - r.start_balance) / scale;
}

namespace {
std::string contact_text(const OverlapReport& o) {
  if (o.element >= 0) return fmt::format("particle id {} and barrier element id {}", o.particle, o.element);
  return fmt::format("particles id {} and id {}", o.particle, o.other);
}
}  // namespace

std::string summary_line(const RunSummary& s) {
  const RunRecord& r = s.record;
  std::string line = fmt::format("energy balance drift {:+.3g}% of the start balance ({:.6g} J -> {:.6g} J)",
                                 100.0 * energy_drift(r), r.start_balance, r.balance);
  if (!s.drift_unchecked.empty()) line += fmt::format(" (not checked: {})", s.drift_unchecked);
  if (r.deepest.particle < 0) return line + "; no contacts";
  return line + fmt::format("; largest overlap {:.3g}% of the radius between {} at t = {:.9g} s",
                            100.0 * r.deepest.ratio, contact_text(r.deepest), r.deepest_time);
}

std::string drift_warning(const RunSummary& s) {
  if (!(s.drift_limit > 0.0) || !s.drift_unchecked.empty()) return "";
  const RunRecord& r = s.record;
  const double d = energy_drift(r);
  if (!(std::abs(d) > s.drift_limit)) return "";
  const std::string what = fmt::format(
      "warning: the energy balance {} by {:.3g}% over the run ({:.6g} J at the start, {:.6g} J at t = {:.9g} s), "
      "more than checks.energy_drift = {:.3g}%",
      d > 0.0 ? "rose" : "fell", 100.0 * std::abs(d), r.start_balance, r.balance, s.time, 100.0 * s.drift_limit);
  if (d > 0.0)
    return what + fmt::format(
                      ": the integration created energy and the results are not to be trusted. The step is too large "
                      "for the contacts (the deepest reached {:.3g}% of the radius); reduce time.dt (see `mpdem check` "
                      "for a recommended step).",
                      100.0 * r.deepest.ratio);
  return what +
         ": energy was lost beyond the booked damping and friction (numerical damping, e.g. time.phi above 0.5, or "
         "a step too large for the contacts); reduce time.dt.";
}

}  // namespace mpdem
