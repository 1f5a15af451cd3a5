// libFuzzer target: the STL reader (src/io/stl_reader.cpp), ASCII and binary. The input is the
// STL file; read_stl_barriers (read_stl + scale, rotation, translation) turns it into barriers.
// InputError is expected for bad input; anything else is a finding.
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "io/stl_reader.hpp"
#include "temp_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const mpdem::Model model = [] {
    mpdem::Model m;
    m.materials.resize(1);
    m.materials[0].name = "steel";
    return m;
  }();
  mpdem::BarrierSource src;
  src.stl = mpdem_fuzz::write_file("mesh.stl", data, size);
  src.material = "steel";
  src.scale = 0.001;
  src.rotate_deg = mpdem::Vec3{0.0, 0.0, 90.0};
  src.translate = mpdem::Vec3{0.0, 0.0, 1.0};
  mpdem::Barriers out;
  try {
    mpdem::read_stl_barriers(src, model, out);
  } catch (const mpdem::InputError&) {
    // Expected for bad input.
  }
  return 0;
}
