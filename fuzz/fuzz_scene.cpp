// libFuzzer target: the TOML scene reader (src/scene/scene_reader.cpp, toml_section.cpp,
// generate_spec_reader.cpp). The input is the scene file. An InputError is the expected outcome
// for bad input; any other exception, crash, hang or sanitizer report is a finding.
//
// After a successful parse_scene_file, load_scene reads the sources too, so that the CSV and STL
// readers are reached through scene paths. The scratch folder holds small valid sources the
// fuzzer can name (p.csv, b.csv, m.stl, seeded in the corpus). Scenes that generate particles
// stop after parsing: the generator's run time grows with the requested count by design.
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "temp_input.hpp"
#include "scene/scene_reader.hpp"

namespace {

void write_sources() {
  mpdem_fuzz::write_file("p.csv", "id,x,y,z,radius\n0,0,0,0,0.01\n1,0.1,0,0,0.01\n");
  mpdem_fuzz::write_file("b.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1,0,0,0,1,0\n");
  mpdem_fuzz::write_file("m.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                                  "endloop\nendfacet\nendsolid t\n");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool sources_written = (write_sources(), true);
  (void)sources_written;
  const auto path = mpdem_fuzz::write_file("scene.toml", data, size);
  try {
    const mpdem::Scene parsed = mpdem::parse_scene_file(path);
    for (const auto& src : parsed.particle_sources)
      if (src.generate) return 0;
    const mpdem::Scene loaded = mpdem::load_scene(path);
    (void)loaded;
  } catch (const mpdem::InputError&) {
    // Expected for bad input.
  }
  return 0;
}
