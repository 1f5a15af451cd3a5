// libFuzzer target: the barrier CSV reader (src/io/barrier_csv.cpp via csv_table.cpp). The input
// is the CSV file, read with a source that names a material, a group, a motion law and a
// temperature, into barriers that already hold one triangle with id 0 (so the cross-file
// duplicate-id path is reached). InputError is expected for bad input; anything else is a finding.
#include <cstddef>
#include <cstdint>

#include "io/barrier_csv.hpp"
#include "core/input_error.hpp"
#include "temp_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const mpdem::Model model = [] {
    mpdem::Model m;
    mpdem::Material a;
    a.name = "steel";
    m.materials = {a};
    return m;
  }();
  static const mpdem::BarrierSource source = [] {
    mpdem::BarrierSource s;
    s.material = "steel";
    s.thickness = 0.001;
    s.temperature = 300.0;
    s.motion.A = mpdem::Vec3{0.0, 0.0, 0.01};
    s.motion.w1 = 10.0;
    return s;
  }();
  const auto path = mpdem_fuzz::write_file("barriers.csv", data, size);
  mpdem::Barriers out;
  out.add(0, mpdem::Vec3{0, 0, 0}, mpdem::Vec3{1, 0, 0}, mpdem::Vec3{0, 1, 0}, out.group_index("floor"), 1e7, 0.3,
          mpdem::MotionLaw{}, 0.0, 300.0);
  try {
    mpdem::read_barrier_csv(path, source, model, out);
  } catch (const mpdem::InputError&) {
    // Expected for bad input.
  }
  return 0;
}
