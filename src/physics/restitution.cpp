// Restitution -> damping-ratio calibration (physics.md section 5 Departure); the scaling that
// makes it depend on e alone is written out in restitution.hpp.
#include "physics/restitution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <stdexcept>

namespace mpdem {
namespace {

// Dimensionless acceleration x'' = -max(0, x^(3/2) + c x^(1/4) x'), c = sqrt(6) xi.
double accel(double x, double y, double c) {
  if (x <= 0.0) return 0.0;
  const double q = std::sqrt(std::sqrt(x));  // x^(1/4)
  const double f = x * std::sqrt(x) + c * q * y;
  return f > 0.0 ? -f : 0.0;
}

struct State {
  double x, y;  // dimensionless overlap and its rate
};

State rk4_step(const State& s, double h, double c) {
  const double k1x = s.y, k1y = accel(s.x, s.y, c);
  const double k2x = s.y + 0.5 * h * k1y, k2y = accel(s.x + 0.5 * h * k1x, s.y + 0.5 * h * k1y, c);
  const double k3x = s.y + 0.5 * h * k2y, k3y = accel(s.x + 0.5 * h * k2x, s.y + 0.5 * h * k2y, c);
  const double k4x = s.y + h * k3y, k4y = accel(s.x + h * k3x, s.y + h * k3y, c);
  return {s.x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x), s.y + h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y)};
}

// True once the pair has separated: recovering (x' < 0) and either the clamp is engaged
// (x^(5/4) + c x' <= 0, after which the motion is force-free) or the overlap has closed.
bool separated(const State& s, double c) {
  if (s.y >= 0.0) return false;
  if (s.x <= 0.0) return true;
  return s.x * std::sqrt(std::sqrt(s.x)) + c * s.y <= 0.0;
}

// Step control. Near tau = 0 the solution contains tau^(5/4) terms, so a uniform RK4 step loses
// its order; a step proportional to tau (ratio kGrade) keeps the summed error ~kGrade^4.
constexpr double kGrade = 0.01;       // h / tau in the graded start
constexpr double kMaxStep = 1e-3;     // uniform step afterwards (dimensionless time)
constexpr double kFirstStep = 1e-12;  // first step
constexpr double kMinStep = 1e-10;    // resolution of the separation instant: the force is ~0
                                      // there, so x' errs by ~h^2 |dF/dtau|; much finer steps
                                      // drown in rounding where x^(5/4) ~ -c x'
constexpr double kMaxTime = 1e4;      // guard: far beyond any e >= kMinRestitution collision

}  // namespace

double restitution_for_damping_ratio(double xi) {
  if (!(xi >= 0.0) || !std::isfinite(xi))
    throw std::invalid_argument("restitution_for_damping_ratio: xi must be finite and >= 0");
  if (xi == 0.0) return 1.0;  // undamped Hertz is conservative
  const double c = std::sqrt(6.0) * xi;
  State s{0.0, 1.0};
  double tau = 0.0;
  double h_cap = kMaxStep;  // shrinks while the separation instant is being located
  while (tau < kMaxTime) {
    const double h = std::min(h_cap, std::max(kGrade * tau, kFirstStep));
    const State next = rk4_step(s, h, c);
    if (separated(next, c)) {
      if (h <= kMinStep) return -next.y;  // force-free after this instant: x' is final
      h_cap = 0.5 * h;                    // separation inside the step: retry shorter
      continue;
    }
    s = next;
    tau += h;
  }
  throw std::runtime_error("restitution_for_damping_ratio: no separation (xi too large)");
}

namespace {

double solve_damping_ratio(double e) {
  // e(xi) decreases monotonically from 1 at xi = 0. Bracket, then Illinois regula falsi.
  double lo = 0.0, g_lo = 1.0 - e;  // g = e(xi) - e_target, > 0 at lo
  double hi = 0.25, g_hi = restitution_for_damping_ratio(hi) - e;
  while (g_hi > 0.0) {
    lo = hi;
    g_lo = g_hi;
    hi *= 2.0;
    g_hi = restitution_for_damping_ratio(hi) - e;
  }
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    const double mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    const double g = restitution_for_damping_ratio(mid) - e;
    if (std::abs(g) < 1e-13 || hi - lo < 1e-14 * hi) return mid;
    if (g > 0.0) {
      lo = mid;
      g_lo = g;
      if (side == -1) g_hi *= 0.5;  // Illinois: halve the stale end to keep superlinear speed
      side = -1;
    } else {
      hi = mid;
      g_hi = g;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double damping_ratio_for_restitution(double e) {
  if (!(e >= kMinRestitution && e <= 1.0)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "damping_ratio_for_restitution: e must be in [%g, 1] (no finite damping ratio gives e = 0; "
                  "give a damping ratio instead), got %.9g",
                  kMinRestitution, e);
    throw std::invalid_argument(text);
  }
  if (e == 1.0) return 0.0;
  // Small cache: a run asks for a handful of distinct e (one per contact class / material pair).
  static std::mutex mutex;
  static std::array<double, 32> keys{}, values{};
  static std::size_t count = 0;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (std::size_t k = 0; k < std::min(count, keys.size()); ++k)
      if (keys[k] == e) return values[k];
  }
  const double xi = solve_damping_ratio(e);
  const std::lock_guard<std::mutex> lock(mutex);
  keys[count % keys.size()] = e;
  values[count % keys.size()] = xi;
  ++count;
  return xi;
}

}  // namespace mpdem
