// Radius distributions (docs/tools.md "Radius distributions").
#include "model/radius_distribution.hpp"

#include <algorithm>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/value_range.hpp"

namespace mpdem {

namespace {

constexpr int kMaxRejections = 10'000'000;  // a window this improbable is a parameter mistake

// Standard normal CDF; only decides the sampling method, never a sampled value.
double phi(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

[[noreturn]] void too_many_rejections(const RadiusDistribution& d) {
  throw std::runtime_error("radius distribution " + d.describe() +
                           ": the [min, max] window is too improbable to sample");
}

// The normal a Normal or LogNormal law draws from (of r, or of ln r), and its window.
struct NormalWindow {
  double mu, sigma, lo, hi;
};

NormalWindow normal_window(const RadiusDistribution& d) {
  if (d.law == RadiusLaw::Normal) return {d.mean, d.std, d.min, d.max};
  // ln r ~ Normal(m, s) with E[r] = mean and Var[r] = std^2.
  const double s2 = std::log1p((d.std * d.std) / (d.mean * d.mean));
  return {std::log(d.mean) - 0.5 * s2, std::sqrt(s2), d.min > 0.0 ? std::log(d.min) : -INFINITY,
          d.max > 0.0 ? std::log(d.max) : INFINITY};
}

// In units of sigma, how far the window lies from the mean (0 when it holds the mean).
double window_offset(const NormalWindow& w) {
  const double peak = std::min(std::max(w.mu, w.lo), w.hi);
  return std::abs(peak - w.mu) / w.sigma;
}

// Normal(mu, sigma) truncated to [lo, hi]. A window holding a fair share of the parent is sampled
// by plain rejection; a narrow or far-tail window by a uniform proposal under the density's
// maximum over the window, which stays efficient where the parent rarely lands. The proposal
// stops where the density has fallen by e^-40 from its peak (40 sigma / b beyond a peak b sigma
// from the mean): a one-sided window is then sampled too, and a long one no less efficiently.
double truncated_normal(const RadiusDistribution& d, Rng& rng, const NormalWindow& w) {
  const double mu = w.mu, sigma = w.sigma, lo = w.lo, hi = w.hi;
  const double p = phi((hi - mu) / sigma) - phi((lo - mu) / sigma);
  if (p >= 0.25) {
    for (int k = 0; k < kMaxRejections; ++k) {
      const double x = mu + sigma * rng.normal();
      if (x >= lo && x <= hi) return x;
    }
  } else {
    const double peak = std::min(std::max(mu, lo), hi);  // where the density is largest
    const double reach = 40.0 * sigma / std::max(window_offset(w), 1.0);
    const double a_lo = std::max(lo, peak - reach), a_hi = std::min(hi, peak + reach);
    for (int k = 0; k < kMaxRejections; ++k) {
      const double x = rng.uniform(a_lo, a_hi);
      const double a = (x - mu) / sigma, b = (peak - mu) / sigma;
      if (rng.uniform() < std::exp(0.5 * (b * b - a * a))) return x;
    }
  }
  too_many_rejections(d);
}

// Why the normal a Normal or LogNormal law draws from cannot be sampled ("" when it can); sets
// `key` to the key to blame.
std::string normal_window_problem(const RadiusDistribution& d, std::string& key) {
  const NormalWindow w = normal_window(d);
  key = "std";
  if (d.law == RadiusLaw::LogNormal && !(std::isfinite(w.mu) && std::isfinite(w.sigma)))
    return "the log-normal's spread overflows: ln r has variance ln(1 + std^2 / mean^2) = " +
           number_text(w.sigma * w.sigma) + " for mean = " + number_text(d.mean) + ", std = " + number_text(d.std) +
           "; expected std / mean below about 1e150";
  if (!(w.sigma >= std::numeric_limits<double>::min()))
    return "the spread is too small to sample (" +
           std::string(d.law == RadiusLaw::Normal ? "std = " : "the std of ln r = ") + number_text(w.sigma) +
           "); use a constant radius instead";
  key = "min";
  if (const double b = window_offset(w); !std::isfinite(b * b))
    return "the [min, max] window lies " + number_text(b) +
           " standard deviations from the mean, beyond what can be sampled; expected a window within about 1e150 "
           "standard deviations of the mean";
  return "";
}

// Why `d` is unusable ("" when it is usable); sets `key` to the key to blame.
std::string problem_of(const RadiusDistribution& d, std::string& key) {
  const auto finite_pos = [](double v) { return std::isfinite(v) && v > 0.0; };
  switch (d.law) {
    case RadiusLaw::Constant:
      key = "value";
      if (!finite_pos(d.value)) return "expected a radius 'value' > 0, got " + number_text(d.value);
      return "";
    case RadiusLaw::Uniform:
      key = "min";
      if (!finite_pos(d.min) || !finite_pos(d.max) || d.min > d.max)
        return "expected 0 < min <= max, got min = " + number_text(d.min) + ", max = " + number_text(d.max);
      return "";
    case RadiusLaw::Normal:
    case RadiusLaw::LogNormal:
      key = "std";
      if (!finite_pos(d.mean) || !finite_pos(d.std))
        return "expected mean > 0 and std > 0, got mean = " + number_text(d.mean) + ", std = " + number_text(d.std);
      key = "min";
      if (d.law == RadiusLaw::Normal && (!finite_pos(d.min) || !finite_pos(d.max) || d.min >= d.max))
        return "expected 0 < min < max (defaults mean -/+ 3 std), got min = " + number_text(d.min) +
               ", max = " + number_text(d.max);
      if (d.law == RadiusLaw::LogNormal && (d.min < 0.0 || d.max < 0.0 || (d.max > 0.0 && d.min >= d.max)))
        return "expected 0 <= min < max (0 = no bound), got min = " + number_text(d.min) +
               ", max = " + number_text(d.max);
      return normal_window_problem(d, key);
    case RadiusLaw::Discrete: {
      key = "radii";
      if (d.radii.empty()) return "expected at least one radius in 'radii'";
      key = "fractions";
      if (d.radii.size() != d.fractions.size())
        return "expected as many 'fractions' as 'radii', got " + std::to_string(d.fractions.size()) + " and " +
               std::to_string(d.radii.size());
      key = "radii";
      for (double r : d.radii)
        if (!finite_pos(r)) return "expected every radius > 0, got " + number_text(r);
      key = "fractions";
      double sum = 0.0;
      for (double f : d.fractions) {
        if (!std::isfinite(f) || f < 0.0) return "expected every fraction >= 0, got " + number_text(f);
        sum += f;
      }
      if (!(sum > 0.0)) return "expected fractions with a positive sum";
      if (d.mass_fractions) {
        // Number shares fraction / r^3 (number_fractions): each and their sum must be finite.
        key = "radii";
        double shares = 0.0;
        for (std::size_t k = 0; k < d.radii.size(); ++k) {
          const double r = d.radii[k], share = d.fractions[k] / (r * r * r);
          if (!std::isfinite(share) || (d.fractions[k] > 0.0 && !(share > 0.0)))
            return "the number share fraction / r^3 of radius " + number_text(r) + " m " +
                   (std::isfinite(share) ? "underflows" : "overflows") +
                   " (fractions_of = \"mass\"); expected radii whose cubes are finite and > 0";
          shares += share;
        }
        if (!std::isfinite(shares))
          return "the number shares fraction / r^3 overflow their sum (fractions_of = \"mass\")";
      }
      return "";
    }
  }
  return "unknown distribution";
}

}  // namespace

bool parse_radius_law(const std::string& name, RadiusLaw& out) {
  if (name == "constant") out = RadiusLaw::Constant;
  else if (name == "uniform") out = RadiusLaw::Uniform;
  else if (name == "normal") out = RadiusLaw::Normal;
  else if (name == "lognormal") out = RadiusLaw::LogNormal;
  else if (name == "discrete") out = RadiusLaw::Discrete;
  else return false;
  return true;
}

std::string RadiusDistribution::problem(std::string* key) const {
  std::string k;
  std::string p = problem_of(*this, k);
  if (key) *key = p.empty() ? "" : k;
  return p;
}

std::vector<double> RadiusDistribution::number_fractions() const {
  std::vector<double> w(radii.size());
  double sum = 0.0;
  for (std::size_t k = 0; k < radii.size(); ++k) {
    // Equal density: mass share m_k ~ n_k r_k^3, so n_k ~ m_k / r_k^3.
    w[k] = mass_fractions ? fractions[k] / (radii[k] * radii[k] * radii[k]) : fractions[k];
    sum += w[k];
  }
  for (double& x : w) x /= sum;
  return w;
}

double RadiusDistribution::sample(Rng& rng) const {
  switch (law) {
    case RadiusLaw::Constant: return value;
    case RadiusLaw::Uniform: return rng.uniform(min, max);
    case RadiusLaw::Normal: return truncated_normal(*this, rng, normal_window(*this));
    case RadiusLaw::LogNormal: return std::exp(truncated_normal(*this, rng, normal_window(*this)));
    case RadiusLaw::Discrete: {
      const std::vector<double> p = number_fractions();  // small: a handful of radii
      double u = rng.uniform();
      for (std::size_t k = 0; k + 1 < p.size(); ++k) {
        if (u < p[k]) return radii[k];
        u -= p[k];
      }
      return radii.back();
    }
  }
  return value;
}

std::string RadiusDistribution::describe() const {
  switch (law) {
    case RadiusLaw::Constant: return "constant " + number_text(value) + " m";
    case RadiusLaw::Uniform: return "uniform [" + number_text(min) + ", " + number_text(max) + "] m";
    case RadiusLaw::Normal:
      return "normal(mean " + number_text(mean) + ", std " + number_text(std) + ") truncated to [" + number_text(min) +
             ", " + number_text(max) + "] m";
    case RadiusLaw::LogNormal: return "lognormal(mean " + number_text(mean) + ", std " + number_text(std) + ") m";
    case RadiusLaw::Discrete: return "discrete (" + std::to_string(radii.size()) + " radii)";
  }
  return "";
}

std::vector<double> RadiusDistribution::bounding_radii(bool tails) const {
  switch (law) {
    case RadiusLaw::Constant: return {value};
    case RadiusLaw::Uniform:
    case RadiusLaw::Normal: return {min, max};
    case RadiusLaw::LogNormal: {
      const NormalWindow w = normal_window(*this);
      std::vector<double> r;
      for (const double b : {min, max})
        if (b > 0.0) r.push_back(b);
      if (tails && !(min > 0.0)) r.push_back(std::exp(w.mu - 8.0 * w.sigma));
      if (tails && !(max > 0.0)) r.push_back(std::exp(w.mu + 8.0 * w.sigma));
      return r;
    }
    case RadiusLaw::Discrete: return radii;
  }
  return {};
}

double RadiusDistribution::smallest() const {
  switch (law) {
    case RadiusLaw::Constant: return value;
    case RadiusLaw::Discrete: return radii.empty() ? 0.0 : *std::min_element(radii.begin(), radii.end());
    case RadiusLaw::Uniform:
    case RadiusLaw::Normal:
    case RadiusLaw::LogNormal: return min > 0.0 ? min : 0.5 * mean;
  }
  return 0.0;
}

double RadiusDistribution::largest() const {
  switch (law) {
    case RadiusLaw::Constant: return value;
    case RadiusLaw::Discrete: return radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
    case RadiusLaw::Uniform:
    case RadiusLaw::Normal:
    case RadiusLaw::LogNormal: return max > 0.0 ? max : mean + 3.0 * std;
  }
  return 0.0;
}

}  // namespace mpdem
