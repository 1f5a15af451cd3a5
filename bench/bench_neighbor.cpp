// Neighbour-search benchmarks: Verlet list build (spatially ordered and shuffled input), the
// rebuild check, the spatial reordering and the barrier broad phase, on a dense polydisperse
// packing (radii 1:2, ~9 neighbours per particle within contact + skin).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "neighbor/barrier_broadphase.hpp"
#include "neighbor/spatial_order.hpp"
#include "neighbor/verlet_list.hpp"
#include "state/barriers.hpp"

namespace {

using mpdem::Vec3;

constexpr double kR = 1e-3;       // m, smallest radius
constexpr double kSkin = 0.2e-3;  // m

struct Packing {
  std::vector<Vec3> x;    // m
  std::vector<double> r;  // m
  double side = 0.0;      // m, cube edge
};

// Jittered cubic lattice of spacing 2.2 R, random radii in [R, 1.1 R], shuffled indices unless
// `ordered` (then Morton-ordered as the engine would keep them).
Packing packing(std::size_t n, bool ordered) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> jit(-0.1 * kR, 0.1 * kR), rad(kR, 1.1 * kR);
  const auto m = static_cast<std::size_t>(std::ceil(std::cbrt(static_cast<double>(n))));
  const double a = 2.2 * kR;
  Packing p;
  p.side = static_cast<double>(m) * a;
  for (std::size_t k = 0; k < n; ++k) {
    const double i = static_cast<double>(k % m), j = static_cast<double>((k / m) % m),
                 l = static_cast<double>(k / (m * m));
    p.x.push_back({i * a + jit(rng), j * a + jit(rng), l * a + jit(rng)});
    p.r.push_back(rad(rng));
  }
  std::vector<std::uint32_t> order(n);
  if (ordered) {
    order = mpdem::spatial_order(p.x, 2.2 * kR + kSkin);
  } else {
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), rng);
  }
  Packing q = p;
  for (std::size_t k = 0; k < n; ++k) {
    q.x[k] = p.x[order[k]];
    q.r[k] = p.r[order[k]];
  }
  return q;
}

void BM_VerletBuild(benchmark::State& st) {
  const Packing p = packing(static_cast<std::size_t>(st.range(0)), st.range(1) != 0);
  mpdem::VerletList l;
  l.build(p.x, p.r, kSkin);  // warm-up: first-touch page faults are not the steady state
  for (auto _ : st) {
    l.build(p.x, p.r, kSkin);
    benchmark::DoNotOptimize(l.indices().data());
  }
  st.counters["pairs_per_particle"] = static_cast<double>(l.num_pairs()) / static_cast<double>(p.x.size());
  st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_VerletBuild)
    ->ArgsProduct({{10000, 100000, 1000000}, {1, 0}})
    ->ArgNames({"N", "ordered"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_NeedsRebuild(benchmark::State& st) {
  const Packing p = packing(static_cast<std::size_t>(st.range(0)), true);
  mpdem::VerletList l;
  l.build(p.x, p.r, kSkin);
  for (auto _ : st) benchmark::DoNotOptimize(l.needs_rebuild(p.x));
  st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_NeedsRebuild)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_SpatialOrder(benchmark::State& st) {
  const Packing p = packing(static_cast<std::size_t>(st.range(0)), false);
  for (auto _ : st) benchmark::DoNotOptimize(mpdem::spatial_order(p.x, 2.2 * kR + kSkin).data());
  st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_SpatialOrder)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The packing inside a closed box of 12 large triangles plus a floor of 2 x 40 x 40 small ones.
void BM_BarrierBroadphase(benchmark::State& st) {
  const Packing p = packing(static_cast<std::size_t>(st.range(0)), true);
  mpdem::Barriers b;
  const double s = p.side;
  const Vec3 c[8] = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}, {0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  std::int64_t id = 0;
  for (const auto& f : faces) {
    b.add(id++, c[f[0]], c[f[1]], c[f[2]], 0, 1e9, 0.3, {}, 0.0, 300.0);
    b.add(id++, c[f[0]], c[f[2]], c[f[3]], 0, 1e9, 0.3, {}, 0.0, 300.0);
  }
  const int m = 40;
  const double h = s / m;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const Vec3 o{i * h, j * h, 0.5 * s};
      b.add(id++, o, o + Vec3{h, 0, 0}, o + Vec3{h, h, 0}, 0, 1e9, 0.3, {}, 0.0, 300.0);
      b.add(id++, o, o + Vec3{h, h, 0}, o + Vec3{0, h, 0}, 0, 1e9, 0.3, {}, 0.0, 300.0);
    }
  mpdem::BarrierBroadphase bp;
  bp.build(p.x, p.r, b, kSkin);  // warm-up
  for (auto _ : st) {
    bp.build(p.x, p.r, b, kSkin);
    benchmark::DoNotOptimize(bp.indices().data());
  }
  st.counters["candidates"] = static_cast<double>(bp.num_candidates());
  st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_BarrierBroadphase)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
