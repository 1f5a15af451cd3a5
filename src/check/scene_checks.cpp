#include "check/scene_checks.hpp"

namespace mpdem {

SceneProblems check_scene(const Scene& scene) {
  SceneProblems out;
  check_outside_domain(scene, out);
  check_periodic_domain(scene, out);
  check_periodic_motion(scene, out);
  check_inlets(scene, out);
  check_initial_overlaps(scene, out);
  check_region_walls(scene, out);
  check_impact_overlaps(scene, out);
  return out;
}

}  // namespace mpdem
