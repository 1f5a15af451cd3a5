// One particle VTU snapshot of 10^4 .. 10^6 particles in each [output] format, written to a
// temporary folder (docs/benchmark.md "Output cost"); run with OMP_NUM_THREADS=1 for one core.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>

#include "io/vtu_writer.hpp"
#include "state/particles.hpp"

namespace {

using namespace mpdem;

// A settled-looking box of particles: positions on a jittered lattice, small random velocities.
Particles make_box(std::size_t n) {
  Particles p;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto side = static_cast<std::size_t>(std::ceil(std::cbrt(static_cast<double>(n))));
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x{0.002 * static_cast<double>(i % side) + 1e-5 * u(rng),
                 0.002 * static_cast<double>((i / side) % side) + 1e-5 * u(rng),
                 0.002 * static_cast<double>(i / (side * side)) + 1e-5 * u(rng)};
    p.add(static_cast<std::int64_t>(i + 1), 0, 0.001 * (1.0 + 0.1 * u(rng)), 2500.0, x,
          {0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng)});
    p.w.back() = {u(rng), u(rng), u(rng)};
    p.force.back() = {1e-4 * u(rng), 1e-4 * u(rng), 1e-3 * u(rng)};
  }
  return p;
}

void write_snapshot(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto format = static_cast<VtkFormat>(state.range(1));
  const Particles p = make_box(n);
  const auto dir = std::filesystem::temp_directory_path() / "mpdem_bench_vtu";
  std::filesystem::create_directories(dir);
  const auto file = dir / "particles.vtu";
  for (auto _ : state) write_particles_vtu(file, p, 0.5, {format, {"glass"}});
  state.counters["bytes_per_particle"] = static_cast<double>(std::filesystem::file_size(file)) / static_cast<double>(n);
  state.SetLabel(vtk_format_name(format));
  std::filesystem::remove_all(dir);
}

}  // namespace

BENCHMARK(write_snapshot)
    ->ArgsProduct({{10000, 100000, 1000000},
                   {static_cast<int>(VtkFormat::Ascii), static_cast<int>(VtkFormat::Binary),
                    static_cast<int>(VtkFormat::Compressed)}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
