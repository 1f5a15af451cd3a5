#include "sim/run_summary.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace mpdem {

double energy_drift(const RunRecord& r) {
  RunSummary closed;  // the closed system's reference (drift_reference)
  closed.record = r;
  return energy_drift(closed);
}

DriftReference drift_reference(const RunSummary& s) {
  const RunRecord& r = s.record;
  DriftReference ref{std::max(std::abs(r.start_balance), r.start_active), "the start balance"};
  if (r.start_active > std::abs(r.start_balance)) ref.what = "the start kinetic + rotational + elastic energy";
  if (s.open && s.dissipated > ref.energy) ref = {s.dissipated, "the energy dissipated"};
  if ((s.open || !(ref.energy > 0.0)) && r.peak_active > ref.energy)
    ref = {r.peak_active, "the largest kinetic + rotational + elastic energy"};
  return ref;
}

double energy_drift(const RunSummary& s) {
  const double scale = drift_reference(s).energy;
  return scale > 0.0 ? (s.record.balance - s.record.start_balance) / scale : 0.0;
}

namespace {
std::string contact_text(const OverlapReport& o) {
  if (o.element >= 0) return fmt::format("particle id {} and barrier element id {}", o.particle, o.element);
  return fmt::format("particles id {} and id {}", o.particle, o.other);
}

// "of the start balance (1 J -> 1.01 J)", or for an open system "of the energy dissipated,
// 5.6 J (an open system: the balance 0 J at the start, 0.12 J at the end; inlets brought 5.7 J)"
std::string reference_text(const RunSummary& s) {
  const RunRecord& r = s.record;
  if (!s.open) return fmt::format("of the start balance ({:.6g} J -> {:.6g} J)", r.start_balance, r.balance);
  const DriftReference ref = drift_reference(s);
  return fmt::format("of {}, {:.6g} J (an open system: the balance {:.6g} J at the start, {:.6g} J at the end; "
                     "inlets brought {:.6g} J)",
                     ref.what, ref.energy, r.start_balance, r.balance, s.inserted_energy);
}
}  // namespace

std::string summary_line(const RunSummary& s) {
  const RunRecord& r = s.record;
  std::string line = "energy balance not booked ([checks] energy_ledger = false)";
  if (s.booked) {
    line = fmt::format("energy balance drift {:+.3g}% {}", 100.0 * energy_drift(s), reference_text(s));
    if (!s.drift_unchecked.empty()) line += fmt::format(" (not checked: {})", s.drift_unchecked);
  }
  if (r.deepest.particle < 0) return line + "; no contacts";
  return line + fmt::format("; largest overlap {:.3g}% of the radius between {} at t = {:.9g} s",
                            100.0 * r.deepest.ratio, contact_text(r.deepest), r.deepest_time);
}

std::string counts_line(const RunSummary& s) {
  std::string line = fmt::format("{} steps, {} interaction evaluations, {} particles removed at the domain boundary",
                                 s.steps, s.evaluations, s.removed);
  if (s.sinks) line += fmt::format(", {} in sinks", s.sunk);
  return line;
}

std::string drift_warning(const RunSummary& s) {
  if (!(s.drift_limit > 0.0) || !s.drift_unchecked.empty() || !s.booked) return "";
  const RunRecord& r = s.record;
  const double d = energy_drift(s);
  if (!(std::abs(d) > s.drift_limit)) return "";
  const std::string over = s.open ? fmt::format("{} over the run (to t = {:.9g} s)", reference_text(s), s.time)
                                  : fmt::format("over the run ({:.6g} J at the start, {:.6g} J at t = {:.9g} s)",
                                                r.start_balance, r.balance, s.time);
  const std::string what = fmt::format(
      "warning: the energy balance {} by {:.3g}% {}, more than checks.energy_drift = {:.3g}%",
      d > 0.0 ? "rose" : "fell", 100.0 * std::abs(d), over, 100.0 * s.drift_limit);
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
