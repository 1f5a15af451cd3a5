// Template against solid: relative errors and the printed table (tools/clump_report.hpp).
#include "tools/clump_report.hpp"

#include <cmath>

#include <fmt/format.h>

#include "physics/principal_axes.hpp"

namespace mpdem {

ShapeError shape_error(const MeshMassProperties& solid, const ClumpMassProperties& tpl) {
  ShapeError e;
  e.volume = (tpl.volume - solid.volume) / solid.volume;
  e.centroid = norm(tpl.centroid - solid.centroid) / std::cbrt(solid.volume);
  const Vec3 moments = principal_axes(solid.inertia).moments;
  for (int k = 0; k < 3; ++k) e.principal[k] = (tpl.principal[k] - moments[k]) / moments[k];
  return e;
}

std::string shape_error_table(const MeshMassProperties& solid, const ClumpMassProperties& tpl) {
  const ShapeError e = shape_error(solid, tpl);
  const Vec3 moments = principal_axes(solid.inertia).moments;
  std::string s = fmt::format("{:<16} {:>20} {:>20} {:>16}\n", "per unit density", "solid (exact)", "template",
                              "relative error");
  const auto row = [&](const char* name, double a, double b, const std::string& err) {
    std::string line = fmt::format("{:<16} {:>20.12g} {:>20.12g} {:>16}", name, a, b, err);
    line.erase(line.find_last_not_of(' ') + 1);
    s += line + '\n';
  };
  row("volume (m^3)", solid.volume, tpl.volume, fmt::format("{:.3e}", e.volume));
  const char* axis[3] = {"centroid x (m)", "centroid y (m)", "centroid z (m)"};
  for (int a = 0; a < 3; ++a)
    row(axis[a], solid.centroid[a], tpl.centroid[a], a == 0 ? fmt::format("{:.3e}", e.centroid) : "");
  const char* moment[3] = {"I1 (m^5)", "I2 (m^5)", "I3 (m^5)"};
  for (int k = 0; k < 3; ++k) row(moment[k], moments[k], tpl.principal[k], fmt::format("{:.3e}", e.principal[k]));
  return s;
}

}  // namespace mpdem
