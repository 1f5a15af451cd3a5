#include "check/clump_summary.hpp"

#include <fmt/core.h>

namespace mpdem {

namespace {

// "exact" for a closed-form value, else the relative estimate.
std::string error_text(double e) { return e == 0.0 ? std::string("exact") : fmt::format("{:.2g}", e); }

std::string moments_text(const Vec3& I) { return fmt::format("{:.6g}, {:.6g}, {:.6g}", I.x, I.y, I.z); }

}  // namespace

int clump_material(const Scene& scene, const std::string& name) {
  for (const ParticleSource& src : scene.particle_sources)
    if (src.clump.contains(scene.model.clump_index(name)))
      return src.material.empty() ? 0 : scene.model.material_index(src.material);
  for (const InletSpec& in : scene.model.params.inlets)
    if (in.clump.contains(scene.model.clump_index(name)))
      return in.material.empty() ? 0 : scene.model.material_index(in.material);
  return -1;
}

std::vector<std::string> clump_summary_lines(const Scene& scene) {
  const std::vector<ClumpTemplate>& clumps = scene.model.clumps;
  std::vector<std::string> out;
  if (clumps.empty()) return out;
  std::size_t members = 0;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) members += scene.particles.body[i] == kNoBody ? 0 : 1;
  out.push_back(fmt::format("clumps: {} template{}, {} bod{}, {} member sphere{}", clumps.size(),
                            clumps.size() == 1 ? "" : "s", scene.particles.bodies.size(),
                            scene.particles.bodies.size() == 1 ? "y" : "ies", members, members == 1 ? "" : "s"));
  for (const ClumpTemplate& t : clumps) {
    const ClumpMassProperties& s = t.shape;
    std::string line = fmt::format("  {:<16} {} member{}, volume {:.6g} m^3", t.name, t.members().size(),
                                   t.members().size() == 1 ? "" : "s", s.volume);
    const int k = clump_material(scene, t.name);
    const Material* m = k >= 0 ? &scene.model.materials[static_cast<std::size_t>(k)] : nullptr;
    const double rho = m ? m->density : 1.0;  // kg/m^3
    line += fmt::format(", {}mass {:.6g} kg, principal moments {} kg m^2",
                        m ? "" : "per unit density: ", t.body_mass(rho), moments_text(t.body_inertia(rho)));
    line += m ? fmt::format(" (material '{}', {:.6g} kg/m^3)", m->name, rho)
              : std::string(" (no [[particles]] entry uses it)");
    line += fmt::format("; integration error: volume {}, moments {}", error_text(s.volume_error),
                        error_text(s.inertia_error));
    if (t.mass || t.inertia)
      line += fmt::format("; overrides: {}{}{} (computed from the members: mass {:.6g} kg, moments {} kg m^2)",
                          t.mass ? "mass" : "", t.mass && t.inertia ? " and " : "", t.inertia ? "inertia" : "",
                          rho * s.volume, moments_text(rho * s.principal));
    else line += "; overrides: none";
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace mpdem
