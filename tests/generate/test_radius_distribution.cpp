// Radius distributions of the particle generator (src/model/radius_distribution.cpp): mean and sd of 10^4
// generated radii within 2 % of the analytic values for every law, and of 10^6 sampler draws within 0.5 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "generate/generator.hpp"
#include "model/radius_distribution.hpp"
#include "support/generate_box_spec.hpp"

using namespace mpdem;
using mpdem::test::box_spec;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Moments {
  double mean = 0, sd = 0;
};
Moments moments(const std::vector<GeneratedParticle>& ps) {
  Moments m;
  if (ps.size() < 2) return m;
  for (const auto& p : ps) m.mean += p.radius;
  m.mean /= static_cast<double>(ps.size());
  for (const auto& p : ps) m.sd += (p.radius - m.mean) * (p.radius - m.mean);
  m.sd = std::sqrt(m.sd / static_cast<double>(ps.size() - 1));
  return m;
}

// 10^4 particles in a box 4x larger than needed for the packing: fast, and every radius fits.
std::vector<GeneratedParticle> sample_radii(const RadiusDistribution& d, double r_typ) {
  GenerateSpec s = box_spec(60 * r_typ * 4, 10000, 0.0);
  s.radius = d;
  s.seed = 7;
  return generate_particles(s).particles;
}

// Prints the measured/expected ratios (for the record; the checks follow).
void report(const char* what, const Moments& m, double mean, double sd) {
  std::printf("  %-22s mean/expected %.5f  sd/expected %.5f\n", what, m.mean / mean, m.sd / sd);
}

double normal_pdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2 * kPi); }
double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

}  // namespace

TEST(Generator, RadiusMomentsMatchDistributions) {
  // Sample mean and standard deviation of 10^4 generated radii within 2 % of the analytic values.
  const double tol = 0.02;
  {
    RadiusDistribution d;
    d.law = RadiusLaw::Uniform;
    d.min = 0.001;
    d.max = 0.003;
    const Moments m = moments(sample_radii(d, 0.002));
    report("uniform", m, 0.002, (0.002 / std::sqrt(12.0)));
    EXPECT_NEAR(m.mean / 0.002, 1.0, tol);
    EXPECT_NEAR(m.sd / (0.002 / std::sqrt(12.0)), 1.0, tol);
  }
  {
    // Normal(2 mm, 0.5 mm) truncated to [1.5, 2.8] mm: alpha = -1, beta = 1.6.
    RadiusDistribution d;
    d.law = RadiusLaw::Normal;
    d.mean = 0.002;
    d.std = 0.0005;
    d.min = 0.0015;
    d.max = 0.0028;
    const double a = -1.0, b = 1.6, Z = normal_cdf(b) - normal_cdf(a);
    const double mean = 0.002 + 0.0005 * (normal_pdf(a) - normal_pdf(b)) / Z;
    const double var = 0.0005 * 0.0005 *
                       (1 + (a * normal_pdf(a) - b * normal_pdf(b)) / Z -
                        std::pow((normal_pdf(a) - normal_pdf(b)) / Z, 2));
    const Moments m = moments(sample_radii(d, 0.002));
    report("truncated normal", m, mean, std::sqrt(var));
    EXPECT_NEAR(m.mean / mean, 1.0, tol);
    EXPECT_NEAR(m.sd / std::sqrt(var), 1.0, tol);
  }
  {
    // Far-tail window (the uniform-proposal branch): Normal(1 mm, 0.2 mm) on [1.4, 1.6] mm.
    RadiusDistribution d;
    d.law = RadiusLaw::Normal;
    d.mean = 0.001;
    d.std = 0.0002;
    d.min = 0.0014;
    d.max = 0.0016;
    const double a = 2.0, b = 3.0, Z = normal_cdf(b) - normal_cdf(a);
    const double mean = 0.001 + 0.0002 * (normal_pdf(a) - normal_pdf(b)) / Z;
    const double var = 0.0002 * 0.0002 *
                       (1 + (a * normal_pdf(a) - b * normal_pdf(b)) / Z -
                        std::pow((normal_pdf(a) - normal_pdf(b)) / Z, 2));
    const Moments m = moments(sample_radii(d, 0.0015));
    report("normal far tail", m, mean, std::sqrt(var));
    EXPECT_NEAR(m.mean / mean, 1.0, tol);
    EXPECT_NEAR(m.sd / std::sqrt(var), 1.0, tol);
  }
  {
    RadiusDistribution d;  // log-normal given by the mean and std of r itself
    d.law = RadiusLaw::LogNormal;
    d.mean = 0.002;
    d.std = 0.0004;
    const Moments m = moments(sample_radii(d, 0.003));
    report("lognormal", m, 0.002, 0.0004);
    EXPECT_NEAR(m.mean / 0.002, 1.0, tol);
    EXPECT_NEAR(m.sd / 0.0004, 1.0, tol);
  }
  {
    // Number fractions 0.3 / 0.7 of 1 mm / 2 mm: mean 1.7 mm, variance 0.21 mm^2.
    RadiusDistribution d;
    d.law = RadiusLaw::Discrete;
    d.radii = {0.001, 0.002};
    d.fractions = {0.3, 0.7};
    const Moments m = moments(sample_radii(d, 0.002));
    report("discrete by number", m, 0.0017, (std::sqrt(0.21) * 0.001));
    EXPECT_NEAR(m.mean / 0.0017, 1.0, tol);
    EXPECT_NEAR(m.sd / (std::sqrt(0.21) * 0.001), 1.0, tol);
  }
  {
    // Equal mass fractions of 1 mm and 2 mm: numbers in ratio 8 : 1, mean 10/9 mm,
    // E[r^2] = (8 + 4)/9 mm^2.
    RadiusDistribution d;
    d.law = RadiusLaw::Discrete;
    d.radii = {0.001, 0.002};
    d.fractions = {0.5, 0.5};
    d.mass_fractions = true;
    const Moments m = moments(sample_radii(d, 0.002));
    const double mean = 10.0 / 9.0, sd = std::sqrt(12.0 / 9.0 - mean * mean);
    report("discrete by mass", m, (mean * 0.001), (sd * 0.001));
    EXPECT_NEAR(m.mean / (mean * 0.001), 1.0, tol);
    EXPECT_NEAR(m.sd / (sd * 0.001), 1.0, tol);
  }
}

TEST(Generator, SamplerMomentsLargeSample) {
  // The samplers alone, 10^6 draws: statistical error of the sd below 0.1 %, tolerance 0.5 %.
  // (The 10^4-particle test above has ~0.8 % statistical error on the log-normal sd, so a bias
  // of the sampler smaller than its 2 % tolerance would only show here.)
  const auto check = [](const RadiusDistribution& d, double mean, double sd) {
    Rng rng(12345);
    const int n = 1000000;
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
      const double r = d.sample(rng);
      s += r;
      s2 += r * r;
    }
    const double m = s / n, v = (s2 - n * m * m) / (n - 1);
    EXPECT_NEAR(m / mean, 1.0, 0.005) << d.describe();
    EXPECT_NEAR(std::sqrt(v) / sd, 1.0, 0.005) << d.describe();
  };
  RadiusDistribution ln;
  ln.law = RadiusLaw::LogNormal;
  ln.mean = 0.002;
  ln.std = 0.0004;
  check(ln, 0.002, 0.0004);
  RadiusDistribution nt;  // Normal(2, 0.5) mm on [1.5, 2.8] mm, as above
  nt.law = RadiusLaw::Normal;
  nt.mean = 0.002;
  nt.std = 0.0005;
  nt.min = 0.0015;
  nt.max = 0.0028;
  const double a = -1.0, b = 1.6, Z = normal_cdf(b) - normal_cdf(a);
  const double mean = 0.002 + 0.0005 * (normal_pdf(a) - normal_pdf(b)) / Z;
  const double var = 0.0005 * 0.0005 *
                     (1 + (a * normal_pdf(a) - b * normal_pdf(b)) / Z -
                      std::pow((normal_pdf(a) - normal_pdf(b)) / Z, 2));
  check(nt, mean, std::sqrt(var));
  RadiusDistribution un;
  un.law = RadiusLaw::Uniform;
  un.min = 0.001;
  un.max = 0.003;
  check(un, 0.002, 0.002 / std::sqrt(12.0));
}

TEST(Generator, OneSidedFarTailWindowIsSampled) {
  // A log-normal cut below at min far in its upper tail, without max (issue 45): the uniform
  // proposal spanned [ln min, inf) and every draw failed ("the [min, max] window is too improbable
  // to sample"). Now the draws lie in the window with the right mean excess: in units of sigma of
  // ln r, the excess t = (ln r - ln min) / sigma has density ~ exp(-b t - t^2 / 2) (b: ln min's
  // distance from the mean of ln r). 2*10^4 draws: statistical error of the mean about 0.7 %,
  // tolerance 3 %.
  RadiusDistribution d;
  d.law = RadiusLaw::LogNormal;
  d.mean = 0.001;
  d.std = 0.0001;
  d.min = 0.003;
  ASSERT_EQ(d.problem(), "");
  const double s2 = std::log1p((d.std * d.std) / (d.mean * d.mean)), sigma = std::sqrt(s2);
  const double b = (std::log(d.min) - (std::log(d.mean) - 0.5 * s2)) / sigma;
  // The exact mean excess by the trapezoidal rule over [0, 40 / b] (the density falls by e^-40).
  double num = 0.0, den = 0.0;
  const int steps = 100000;
  const double h = 40.0 / b / steps;
  for (int k = 0; k <= steps; ++k) {
    const double t = k * h, w = (k == 0 || k == steps ? 0.5 : 1.0) * std::exp(-b * t - 0.5 * t * t);
    num += w * t;
    den += w;
  }
  const double expected = num / den;
  Rng rng(3);
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = d.sample(rng);
    ASSERT_GE(r, d.min);
    ASSERT_TRUE(std::isfinite(r));
    sum += (std::log(r) - std::log(d.min)) / sigma;
  }
  EXPECT_NEAR(sum / n / expected, 1.0, 0.03);
}
