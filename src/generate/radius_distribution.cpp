// Radius distributions (docs/tools.md "Radius distributions").
#include "generate/radius_distribution.hpp"

#include <algorithm>

#include <cmath>
#include <stdexcept>

#include "io/value_range.hpp"

namespace mpdem {

namespace {

constexpr int kMaxRejections = 10'000'000;  // a window this improbable is a parameter mistake

// Standard normal CDF; only decides the sampling method, never a sampled value.
double phi(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

[[noreturn]] void too_many_rejections(const RadiusDistribution& d) {
  throw std::runtime_error("radius distribution " + d.describe() +
                           ": the [min, max] window is too improbable to sample");
}

// Normal(mean, std) truncated to [lo, hi]. A window holding a fair share of the parent is sampled
// by plain rejection; a narrow or far-tail window by a uniform proposal under the density's
// maximum over the window, which stays efficient where the parent rarely lands.
double truncated_normal(const RadiusDistribution& d, Rng& rng, double mu, double sigma, double lo, double hi) {
  const double p = phi((hi - mu) / sigma) - phi((lo - mu) / sigma);
  if (p >= 0.25) {
    for (int k = 0; k < kMaxRejections; ++k) {
      const double x = mu + sigma * rng.normal();
      if (x >= lo && x <= hi) return x;
    }
  } else {
    const double peak = std::min(std::max(mu, lo), hi);  // where the density is largest
    for (int k = 0; k < kMaxRejections; ++k) {
      const double x = rng.uniform(lo, hi);
      const double a = (x - mu) / sigma, b = (peak - mu) / sigma;
      if (rng.uniform() < std::exp(0.5 * (b * b - a * a))) return x;
    }
  }
  too_many_rejections(d);
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

std::string RadiusDistribution::problem() const {
  const auto finite_pos = [](double v) { return std::isfinite(v) && v > 0.0; };
  switch (law) {
    case RadiusLaw::Constant:
      if (!finite_pos(value)) return "expected a radius 'value' > 0, got " + number_text(value);
      return "";
    case RadiusLaw::Uniform:
      if (!finite_pos(min) || !finite_pos(max) || min > max)
        return "expected 0 < min <= max, got min = " + number_text(min) + ", max = " + number_text(max);
      return "";
    case RadiusLaw::Normal:
      if (!finite_pos(mean) || !finite_pos(std))
        return "expected mean > 0 and std > 0, got mean = " + number_text(mean) + ", std = " + number_text(std);
      if (!finite_pos(min) || !finite_pos(max) || min >= max)
        return "expected 0 < min < max (defaults mean -/+ 3 std), got min = " + number_text(min) +
               ", max = " + number_text(max);
      return "";
    case RadiusLaw::LogNormal:
      if (!finite_pos(mean) || !finite_pos(std))
        return "expected mean > 0 and std > 0, got mean = " + number_text(mean) + ", std = " + number_text(std);
      if (min < 0.0 || max < 0.0 || (max > 0.0 && min >= max))
        return "expected 0 <= min < max (0 = no bound), got min = " + number_text(min) + ", max = " + number_text(max);
      return "";
    case RadiusLaw::Discrete: {
      if (radii.empty()) return "expected at least one radius in 'radii'";
      if (radii.size() != fractions.size())
        return "expected as many 'fractions' as 'radii', got " + std::to_string(fractions.size()) + " and " +
               std::to_string(radii.size());
      double sum = 0.0;
      for (double r : radii)
        if (!finite_pos(r)) return "expected every radius > 0, got " + number_text(r);
      for (double f : fractions) {
        if (!std::isfinite(f) || f < 0.0) return "expected every fraction >= 0, got " + number_text(f);
        sum += f;
      }
      if (!(sum > 0.0)) return "expected fractions with a positive sum";
      return "";
    }
  }
  return "unknown distribution";
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
    case RadiusLaw::Normal: return truncated_normal(*this, rng, mean, std, min, max);
    case RadiusLaw::LogNormal: {
      // ln r ~ Normal(m, s) with E[r] = mean and Var[r] = std^2.
      const double s2 = std::log1p((std * std) / (mean * mean));
      const double m = std::log(mean) - 0.5 * s2;
      const double lo = min > 0.0 ? std::log(min) : -INFINITY;
      const double hi = max > 0.0 ? std::log(max) : INFINITY;
      return std::exp(truncated_normal(*this, rng, m, std::sqrt(s2), lo, hi));
    }
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
