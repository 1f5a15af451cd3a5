#include "cli/radius_options.hpp"

#include "core/input_error.hpp"

namespace mpdem::cli {

void add_radius_options(CLI::App& c, RadiusArgs& a) {
  c.add_option("--radius,-r", a.radius, "constant radius (m)");
  c.add_option("--distribution", a.distribution, "constant, uniform, normal, lognormal or discrete");
  c.add_option("--rmin", a.rmin, "uniform/normal/lognormal: smallest radius (m)");
  c.add_option("--rmax", a.rmax, "uniform/normal/lognormal: largest radius (m)");
  c.add_option("--mean", a.mean, "normal: mean of the parent normal; lognormal: mean radius (m)");
  c.add_option("--std", a.std, "normal: std of the parent normal; lognormal: std of the radius (m)");
  c.add_option("--radii", a.radii, "discrete: radii (m)");
  c.add_option("--fractions", a.fractions, "discrete: fractions (default equal)");
  c.add_option("--fractions-of", a.fractions_of, "discrete: fractions are of 'number' (default) or 'mass'");
}

RadiusDistribution to_distribution(const RadiusArgs& a, const std::string& command) {
  const auto bad = [&](const std::string& option, const std::string& msg) {
    throw InputError(command, 0, option, msg);
  };
  RadiusDistribution d;
  if (a.distribution.empty() || a.distribution == "constant") {
    if (!(a.radius > 0)) bad("--radius", "give --radius R > 0 or a --distribution");
    d.law = RadiusLaw::Constant;
    d.value = a.radius;
  } else if (!parse_radius_law(a.distribution, d.law)) {
    bad("--distribution", "expected constant, uniform, normal, lognormal or discrete, got '" + a.distribution + "'");
  }
  d.min = a.rmin;
  d.max = a.rmax;
  d.mean = a.mean;
  d.std = a.std;
  if (d.law == RadiusLaw::Normal) {  // default window mean -/+ 3 std
    if (d.min == 0.0) d.min = a.mean - 3.0 * a.std;
    if (d.max == 0.0) d.max = a.mean + 3.0 * a.std;
  }
  d.radii = a.radii;
  d.fractions = a.fractions.empty() ? std::vector<double>(a.radii.size(), 1.0) : a.fractions;
  if (a.fractions_of != "number" && a.fractions_of != "mass") bad("--fractions-of", "expected number or mass");
  d.mass_fractions = a.fractions_of == "mass";
  if (const std::string p = d.problem(); !p.empty()) bad("--distribution", p);
  return d;
}

}  // namespace mpdem::cli
