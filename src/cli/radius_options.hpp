#pragma once
// The radius options shared by `mpdem generate` and `mpdem agglomerate` (docs/tools.md "Radius
// distributions"): --radius, or --distribution with its parameters.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "model/radius_distribution.hpp"

namespace mpdem::cli {

struct RadiusArgs {
  double radius = 0.0;  // m, constant radius
  std::string distribution;
  double rmin = 0.0, rmax = 0.0, mean = 0.0, std = 0.0;  // m
  std::vector<double> radii;                             // m, discrete radii
  std::vector<double> fractions;                         // -, discrete fractions
  std::string fractions_of = "number";
};

void add_radius_options(CLI::App& c, RadiusArgs& a);
// The distribution the options give. Throws InputError(command, 0, option, ...) naming the
// option at fault.
RadiusDistribution to_distribution(const RadiusArgs& a, const std::string& command);

}  // namespace mpdem::cli
