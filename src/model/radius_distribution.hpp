#pragma once
// Radius distributions of generated particles: constant, uniform, truncated normal, log-normal
// (optionally truncated) and discrete (radii with number or mass fractions). Sampling uses Rng so
// that a seed gives the same radii on every platform.
#include <string>
#include <vector>

#include "core/random.hpp"

namespace mpdem {

enum class RadiusLaw { Constant, Uniform, Normal, LogNormal, Discrete };

struct RadiusDistribution {
  RadiusLaw law = RadiusLaw::Constant;
  double value = 0.0;             // m, Constant: the radius
  double min = 0.0;               // m, Uniform/Normal/LogNormal: lower bound (0 = none for LogNormal)
  double max = 0.0;               // m, Uniform/Normal/LogNormal: upper bound (0 = none for LogNormal)
  double mean = 0.0;              // m, Normal: mean of the parent normal; LogNormal: mean of r
  double std = 0.0;               // m, Normal: std of the parent normal; LogNormal: std of r
  std::vector<double> radii;      // m, Discrete: the radii
  std::vector<double> fractions;  // -, Discrete: weights (normalised internally)
  bool mass_fractions = false;    // Discrete: fractions are of mass (equal density) not number

  // "" when the parameters are usable, else what is wrong (names the keys of docs/tools.md);
  // `key`, when given, is set to the key to blame ("std", "min", "radii", ...). Usable includes
  // what sampling derives from them (a log-normal's spread of ln r, the window in standard
  // deviations, a mass fraction's number share).
  std::string problem(std::string* key = nullptr) const;
  // One radius (m). Requires problem() == "".
  double sample(Rng& rng) const;
  // Number probabilities of the discrete radii: fractions, or mass fractions / r^3, normalised.
  std::vector<double> number_fractions() const;
  // m, the radii bounding what it draws: its bounds (value, min and max, the radii). An unbounded
  // log-normal side gives none, or with `tails` the radius 8 standard deviations of ln r out
  // (drawn with a probability below 1e-15).
  std::vector<double> bounding_radii(bool tails) const;
  // m, the smallest radius it gives (its lower bound; for a log-normal without one, half its
  // mean), for defaults that scale with the particles (the neighbour skin).
  double smallest() const;
  // m, the largest radius it gives (its upper bound; for a log-normal without one, its mean + 3
  // std), for estimates that need the largest particles (the checks' impact overlap).
  double largest() const;
  // Human-readable summary for messages and the CLI ("uniform [0.001, 0.002] m").
  std::string describe() const;
};

// Parses a law name ("constant", "uniform", "normal", "lognormal", "discrete"); false if unknown.
bool parse_radius_law(const std::string& name, RadiusLaw& out);

}  // namespace mpdem
