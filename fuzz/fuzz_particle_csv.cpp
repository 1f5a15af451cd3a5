// libFuzzer target: the particle CSV reader (src/io/particle_csv_reader.cpp via csv_table.cpp). The
// input is the CSV file, read against a model with two materials ("glass" and "steel", so that
// names and indices in the `material` column resolve) into particles that already hold one
// particle with id 0 (so the cross-file duplicate-id path is reached). InputError is expected for
// bad input; anything else is a finding. The reader adds a material variant for a row with its own
// constants, so each input gets a fresh copy of the model.
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "io/particle_csv_reader.hpp"
#include "temp_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const mpdem::Model base = [] {
    mpdem::Model m;
    mpdem::Material a;
    a.name = "glass";
    mpdem::Material b;
    b.name = "steel";
    b.density = 7800.0;
    m.materials = {a, b};
    return m;
  }();
  const auto path = mpdem_fuzz::write_file("particles.csv", data, size);
  mpdem::Model model = base;
  mpdem::Particles out;
  out.add(0, 0, 0.01, 2500.0, mpdem::Vec3{}, mpdem::Vec3{});
  try {
    mpdem::read_particle_csv(path, model, 1, out);
  } catch (const mpdem::InputError&) {
    // Expected for bad input.
  }
  return 0;
}
