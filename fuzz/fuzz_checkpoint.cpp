// libFuzzer target: the checkpoint reader and the whole resume path (src/io/checkpoint_format.cpp,
// binary_stream.hpp, checkpoint.cpp: Simulation::resume_from, then Interactions::restore - the
// neighbour lists rebuilt from the stored build positions, particle and barrier contact
// history). The input is the checkpoint file. A fixed small scene (fixed_scene.toml below: four
// spheres of two materials on a floor triangle, rotation, rolling resistance, conduction, fields
// and a near field) is loaded once; each input builds a fresh Simulation of it and resumes from
// the input. An InputError from resume_from is the expected outcome for a bad checkpoint; after
// a successful resume the target takes one step, where a RunError (a state the run refuses:
// non-finite values, non-convergence, a particle outside the domain) is expected too. Any other
// exception, a crash, a hang or a sanitizer report is a finding.
//
// Checksums: every section carries a CRC-32, so almost every mutation would stop at "section ...
// is damaged". Each input is therefore read twice: as given by CheckpointReader alone (the
// framing and checksum checks), then with the checksum of every complete section recomputed
// through the full resume path, so that mutations of the payloads reach the section readers.
//
// Seeds: real checkpoints of the fixed scene, written by the engine at run time. With
//   MPDEM_FUZZ_WRITE_SEEDS=<dir> build-fuzz/fuzz_checkpoint
// the target writes <dir>/step_{1,10,200}.ckp and exits (docs/fuzzing.md: regenerate them after
// a checkpoint format change).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/checkpoint_format.hpp"
#include "core/crc32.hpp"
#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "core/run_error.hpp"
#include "sim/simulation.hpp"
#include "temp_input.hpp"
#include "scene/scene_reader.hpp"

namespace {

constexpr const char* kSceneToml = R"([time]
duration = 1.0
integrator = "trapezoidal"
dt = 1e-5
max_iterations = 10
[analysis]
rotation = true
thermal = true
[gravity]
vector = [0, 0, -9.81]
[fields]
electric = [0, 0, 1e3]
magnetic = [0.1, 0, 0]
[contact.particle_particle]
damping_ratio = 0.1
mu_static = 0.5
mu_dynamic = 0.4
mu_rolling = 0.01
[contact.particle_barrier]
restitution = 0.8
mu_static = 0.3
mu_dynamic = 0.3
[thermal]
conduction = true
convection = true
radiation = true
[[material]]
name = "glass"
density = 2500
young = 1e7
poisson = 0.3
conductivity = 1.0
heat_capacity = 800
emissivity = 0.9
[[material]]
name = "steel"
density = 7800
young = 2e7
poisson = 0.29
[near_field]
a1 = 1e-6
b1 = 2
cutoff = 0.002
[[particles]]
file = "p.csv"
[[barriers]]
file = "b.csv"
material = "steel"
temperature = 350
[domain]
min = [-1, -1, -1]
max = [1, 1, 1]
on_exit = "remove"
)";

// Touching in a row on the floor (overlaps of a few um), one above the others; charged.
constexpr const char* kParticlesCsv = "id,x,y,z,vx,vy,vz,wx,wy,wz,radius,material,charge,temperature\n"
                                      "1,0,0,0.00999,0.01,0,0,0,0,1,0.01,glass,1e-12,300\n"
                                      "2,0.01998,0,0.00999,0,0,0,0,0,0,0.01,steel,0,320\n"
                                      "3,0.04,0,0.00999,0,0.02,0,0,1,0,0.01,glass,-1e-12,280\n"
                                      "4,0.01,0,0.02725,0,0,-0.01,0,0,0,0.008,steel,0,300\n";
constexpr const char* kBarriersCsv = "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n"
                                     "1,-0.5,-0.5,0,0.5,-0.5,0,0,0.5,0\n";

const mpdem::Scene& fixed_scene() {
  static const mpdem::Scene scene = [] {
    mpdem_fuzz::write_file("p.csv", kParticlesCsv);
    mpdem_fuzz::write_file("b.csv", kBarriersCsv);
    return mpdem::load_scene(mpdem_fuzz::write_file("fixed_scene.toml", kSceneToml));
  }();
  return scene;
}

mpdem::RunOptions no_output() {
  mpdem::RunOptions o;
  o.output_dir = mpdem_fuzz::scratch_dir() / "out";
  o.progress = false;
  o.write_output = false;
  return o;
}

// The bytes with the CRC-32 of every complete section recomputed (the framing of
// io/checkpoint_format.hpp; an incomplete tail is left as it is).
std::vector<char> with_fixed_checksums(const std::uint8_t* data, std::size_t size) {
  std::vector<char> b(reinterpret_cast<const char*>(data), reinterpret_cast<const char*>(data) + size);
  std::size_t at = 12;  // magic and version
  while (at < b.size()) {
    std::uint16_t name_size = 0;
    std::uint64_t payload_size = 0;
    if (b.size() - at < sizeof(name_size)) break;
    std::memcpy(&name_size, b.data() + at, sizeof(name_size));
    const std::size_t name_at = at + sizeof(name_size);
    if (b.size() - name_at < name_size + sizeof(payload_size)) break;
    std::memcpy(&payload_size, b.data() + name_at + name_size, sizeof(payload_size));
    const std::size_t payload_at = name_at + name_size + sizeof(payload_size);
    if (b.size() - payload_at < sizeof(std::uint32_t) || payload_size > b.size() - payload_at - sizeof(std::uint32_t))
      break;
    const std::size_t crc_at = payload_at + static_cast<std::size_t>(payload_size);
    const std::uint32_t crc = mpdem::crc32(b.data() + payload_at, static_cast<std::size_t>(payload_size),
                                           mpdem::crc32(b.data() + name_at, name_size));
    std::memcpy(b.data() + crc_at, &crc, sizeof(crc));
    at = crc_at + sizeof(crc);
  }
  return b;
}

// How far the inputs got, printed at exit: how deep the campaign reaches (docs/fuzzing.md).
struct Reach {
  unsigned long inputs = 0, framing_ok = 0, resumed = 0, stepped = 0, run_error = 0;
};
Reach reach;

void print_reach() {
  std::fprintf(stderr,
               "fuzz_checkpoint: %lu inputs; as given, %lu pass framing and checksums; with checksums fixed, %lu "
               "resume, %lu of them take the step, %lu end in a RunError\n",
               reach.inputs, reach.framing_ok, reach.resumed, reach.stepped, reach.run_error);
}

void write_seeds(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  mpdem::Scene s = fixed_scene();
  mpdem::Simulation sim(std::move(s), no_output());
  const double dt = sim.model().params.time.dt;
  int done = 0;
  for (int steps : {1, 10, 200}) {
    while (done < steps) {
      sim.advance(dt);
      ++done;
    }
    const auto file = dir / ("step_" + std::to_string(steps) + ".ckp");
    sim.write_checkpoint(file);
    std::printf("wrote %s (%ju bytes, format %u)\n", file.c_str(),
                static_cast<std::uintmax_t>(std::filesystem::file_size(file)), mpdem::kCheckpointFormat);
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("MPDEM_FUZZ_WRITE_SEEDS"); dir != nullptr && *dir != '\0') {
    write_seeds(dir);
    std::exit(0);
  }
  (void)fixed_scene();
  std::atexit(print_reach);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ++reach.inputs;
  // 1. The bytes as given: magic, version, framing, checksums.
  try {
    mpdem::CheckpointReader r(reinterpret_cast<const char*>(data), size);
    ++reach.framing_ok;
  } catch (const std::runtime_error&) {
    // Expected for a damaged file.
  }
  // 2. With valid checksums, the whole resume path and one step.
  const std::vector<char> bytes = with_fixed_checksums(data, size);
  const auto path = mpdem_fuzz::write_file("checkpoint.bin", reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                           bytes.size());
  mpdem::Scene scene = fixed_scene();
  mpdem::Simulation sim(std::move(scene), no_output());
  try {
    sim.resume_from(path);
  } catch (const mpdem::InputError&) {
    return 0;  // expected for a bad checkpoint
  }
  ++reach.resumed;
  try {
    sim.advance(sim.model().params.time.dt);
    ++reach.stepped;
  } catch (const mpdem::RunError&) {
    ++reach.run_error;  // the run refuses the restored state: expected for nonsense values
  }
  return 0;
}
