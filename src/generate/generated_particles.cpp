// Generated particles into the scene's arrays (docs/scene.md "Generated particles").
#include "generate/generated_particles.hpp"

#include <algorithm>

#include "generate/generator.hpp"
#include "model/particle_defaults.hpp"

namespace mpdem {

void add_generated_particles(const GenerateSpec& spec, const Model& model, int default_material, Particles& out) {
  int mat = spec.material.empty() ? default_material : model.material_index(spec.material);
  if (mat < 0 || mat >= static_cast<int>(model.materials.size())) mat = 0;
  const Material& m = model.materials.at(static_cast<std::size_t>(mat));
  std::int64_t next_id = 0;
  for (const std::int64_t pid : out.id) next_id = std::max(next_id, pid + 1);

  for (const GeneratedParticle& p : generate_particles(spec).particles) {
    out.add(next_id++, mat, p.radius, m.density, p.x, p.v);
    const std::size_t i = out.size() - 1;
    out.w[i] = Vec3{};
    take_material_properties(out, i, m);
    out.force[i] = Vec3{};
    out.torque[i] = Vec3{};
    out.heat[i] = 0.0;
  }
}

}  // namespace mpdem
