// Moving barriers that cross a periodic face of the domain after t = 0 (check/scene_checks.hpp).
// Each vertex's coordinate along a periodic axis is bounded over the element's active part of
// [0, duration] from its motion law: the range of each term of the translation (linear, sine,
// cosine) and of the rotation (a sinusoid of the angle, whose range follows from the angle's
// extremes), summed. Exact when one term moves the element (a conveyor, a vibrating plate, a
// turning drum); an upper bound otherwise.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "check/scene_checks.hpp"
#include "check/source_lookup.hpp"

namespace mpdem {

namespace {

struct Range {
  double lo = 0.0, hi = 0.0;
  Range& operator+=(const Range& o) {
    lo += o.lo;
    hi += o.hi;
    return *this;
  }
};

// amplitude x cos(x) over x in [a, b] (either order).
Range cos_range(double amplitude, double a, double b) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (a > b) std::swap(a, b);
  double lo = std::min(std::cos(a), std::cos(b)), hi = std::max(std::cos(a), std::cos(b));
  if (!(b - a < kTwoPi)) lo = -1.0, hi = 1.0;
  if (std::floor(b / kTwoPi) >= std::ceil(a / kTwoPi)) hi = 1.0;  // 2 pi k inside
  if (std::floor((b - std::numbers::pi) / kTwoPi) >= std::ceil((a - std::numbers::pi) / kTwoPi))
    lo = -1.0;  // pi + 2 pi k
  return amplitude >= 0.0 ? Range{amplitude * lo, amplitude * hi} : Range{amplitude * hi, amplitude * lo};
}

// rad, the extremes of the angle over [t0, t1] (s): at the ends, the rate table's rows, and where
// the piecewise-linear rate changes sign (the angle is piecewise quadratic).
Range angle_range(const RotationLaw& r, double t0, double t1) {
  std::vector<double> times{t0, t1, r.since};
  const auto& tab = r.omega_table;
  for (std::size_t i = 0; i < tab.size(); ++i) {
    times.push_back(r.since + tab[i][0]);
    if (i + 1 < tab.size() && tab[i][1] * tab[i + 1][1] < 0.0)
      times.push_back(r.since + tab[i][0] + tab[i][1] * (tab[i + 1][0] - tab[i][0]) / (tab[i][1] - tab[i + 1][1]));
  }
  Range out{r.angle(t0), r.angle(t0)};
  for (const double t : times) {
    if (t < t0 || t > t1) continue;
    out.lo = std::min(out.lo, r.angle(t));
    out.hi = std::max(out.hi, r.angle(t));
  }
  return out;
}

// m, the range of coordinate c of the element's rest point x0 carried by its motion over [t0, t1].
Range coordinate_range(const Barriers& b, std::size_t e, const Vec3& x0, int c, double t0, double t1) {
  const MotionLaw& m = b.motion[e];
  const double s0 = m.law_time(t0), s1 = m.law_time(t1);  // s, the law's own time
  Range out{std::min(m.a[c] * s0, m.a[c] * s1), std::max(m.a[c] * s0, m.a[c] * s1)};
  out += cos_range(m.A[c], m.w1 * s0 - 0.5 * std::numbers::pi, m.w1 * s1 - 0.5 * std::numbers::pi);  // sin
  out += cos_range(m.B[c], m.w2 * s0, m.w2 * s1);
  const std::int32_t l = b.rotation_of[e];
  if (l < 0) return out += Range{x0[c], x0[c]};
  // x = u + R(theta) (x0 - o) + o; about the unit axis k the turned part's coordinate c is
  // (k.p) k_c + p_perp,c cos(theta) + (k x p)_c sin(theta) = const + rho cos(theta - phi).
  const RotationLaw& r = b.rotations[static_cast<std::size_t>(l)];
  const Vec3 p = x0 - r.origin, k = r.axis;
  const Vec3 along = k * dot(k, p), perp = p - along, side = cross(k, p);
  const double rho = std::hypot(perp[c], side[c]), phi = std::atan2(side[c], perp[c]);
  const Range theta = angle_range(r, t0, t1);
  out += Range{r.origin[c] + along[c], r.origin[c] + along[c]};
  return out += cos_range(rho, theta.lo - phi, theta.hi - phi);
}

}  // namespace

void check_periodic_motion(const Scene& scene, SceneProblems& out) {
  const DomainParams& d = scene.model.params.domain;
  if (!d.bounded || !d.any_periodic()) return;
  const Barriers& b = scene.barriers;
  const double end = scene.model.params.time.duration;  // s
  struct Crossing {
    std::vector<std::size_t> elements;  // ascending
    double beyond = 0.0;                // m, farthest past a periodic face
    std::string axes;                   // "x", "x, z"
  };
  std::map<int, Crossing> by_source;
  for (std::size_t e = 0; e < b.size(); ++e) {
    const MotionLaw& m = b.motion[e];
    const double t0 = std::max(0.0, m.active_from), t1 = std::min(end, m.active_until);  // s, while it takes part
    if (m.is_static() || !(t1 >= t0)) continue;
    double beyond = 0.0;
    std::string axes;
    for (int c = 0; c < 3; ++c) {
      if (!d.periodic[static_cast<std::size_t>(c)]) continue;
      const double tol = 1e-9 * (d.max[c] - d.min[c]);
      bool at_start = false;  // crossing at t = 0 already: check_periodic_domain reports it
      double far = 0.0;       // m
      for (int k = 0; k < 3; ++k) {
        const double v = b.vertex(e, k)[c];
        at_start = at_start || v < d.min[c] - tol || v > d.max[c] + tol;
        const Range r = coordinate_range(b, e, k == 0 ? b.p0[e] : (k == 1 ? b.p1[e] : b.p2[e]), c, t0, t1);
        far = std::max({far, d.min[c] - r.lo - tol, r.hi - d.max[c] - tol});
      }
      if (at_start || !(far > 0.0)) continue;
      beyond = std::max(beyond, far + tol);
      axes += fmt::format("{}{}", axes.empty() ? "" : ", ", "xyz"[c]);
    }
    if (axes.empty()) continue;
    Crossing& x = by_source[barrier_source_of(scene, e)];
    x.elements.push_back(e);
    x.beyond = std::max(x.beyond, beyond);
    if (x.axes.find(axes) == std::string::npos) x.axes += x.axes.empty() ? axes : ", " + axes;
  }
  for (const auto& [source, x] : by_source) {
    SourceLocation where = barrier_source_location(scene, source);
    if (where.key == "barriers") where.key = "barriers.motion";
    std::string list;
    for (std::size_t k = 0; k < x.elements.size() && k < kListedIds; ++k)
      list += fmt::format("{}{}", k ? ", " : "", b.id[x.elements[k]]);
    if (x.elements.size() > kListedIds) list += fmt::format(" and {} more", x.elements.size() - kListedIds);
    const std::size_t n = x.elements.size();
    out.push_back(problem_at(
        where, Severity::Error, false,
        fmt::format("the motion of {} barrier element{} of {} (element ids {}) carries {} across a periodic face of "
                    "the domain [({:.6g}, {:.6g}, {:.6g}), ({:.6g}, {:.6g}, {:.6g})] along {} before the run's end "
                    "t = {:.6g} s, up to {:.3g} m beyond it: barriers are not repeated across the period, so from "
                    "then on a particle would meet the wall on one side only. Keep the motion within the period "
                    "(or end its active window before), or make that axis non-periodic; a wall sliding along a "
                    "periodic axis is better made of fixed particles moving at the wall's velocity.",
                    n, n == 1 ? "" : "s", where.name, list, n == 1 ? "it" : "them", d.min.x, d.min.y, d.min.z, d.max.x,
                    d.max.y, d.max.z, x.axes, end, x.beyond)));
  }
}

}  // namespace mpdem
