// Loads a scene through the installed engine library: prints its particle and barrier counts.
// Usage: install_test SCENE.toml
#include <cstdio>
#include <exception>

#include "model/scene.hpp"
#include "scene/scene_reader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml\n", argv[0]);
    return 2;
  }
  try {
    const mpdem::Scene scene = mpdem::load_scene(argv[1]);
    std::printf("mpdem %s: %zu particles, %zu barrier elements\n", MPDEM_VERSION, scene.particles.size(),
                scene.barriers.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
