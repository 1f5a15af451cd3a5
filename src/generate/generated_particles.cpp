// Generated particles into the scene's arrays (docs/scene.md "Generated particles").
#include "generate/generated_particles.hpp"

#include <algorithm>
#include <vector>

#include "generate/generator.hpp"
#include "core/input_error.hpp"
#include "model/derived_limits.hpp"
#include "model/particle_defaults.hpp"

namespace mpdem {

namespace {

// A radius whose mass or time scales over- or underflow with the material
// (model/derived_limits.hpp); `what` names the radius in the message.
void check_radius(const GenerateSpec& spec, const Material& m, bool thermal, double r, const std::string& what) {
  if (const std::string p = radius_problem(r, m, thermal); !p.empty())
    throw InputError(spec.origin, spec.line, "particles.generate.radius", what + ": " + p);
}

}  // namespace

void add_generated_particles(const GenerateSpec& spec, const Model& model, int default_material, Particles& out) {
  int mat = spec.material.empty() ? default_material : model.material_index(spec.material);
  if (mat < 0 || mat >= static_cast<int>(model.materials.size())) mat = 0;
  const Material& m = model.materials.at(static_cast<std::size_t>(mat));
  const bool thermal = model.params.analysis.thermal;
  // Before generating: a radius of 1e-300 m would otherwise be placed first, then fail at step 1.
  for (const double r : spec.radius.bounding_radii(false))
    check_radius(spec, m, thermal, r, "material '" + m.name + "'");
  std::int64_t next_id = 0;
  for (const std::int64_t pid : out.id) next_id = std::max(next_id, pid + 1);

  for (const GeneratedParticle& p : generate_particles(spec).particles) {
    check_radius(spec, m, thermal, p.radius, "generated particle id " + std::to_string(next_id));
    out.add(next_id++, mat, p.radius, m.density, p.x, p.v);
    const std::size_t i = out.size() - 1;
    out.w[i] = Vec3{};
    take_material_properties(out, i, m);
    out.force[i] = Vec3{};
    out.torque[i] = Vec3{};
    out.heat[i] = 0.0;
    out.fixed[i] = spec.fixed ? 1 : 0;
  }
}

}  // namespace mpdem
