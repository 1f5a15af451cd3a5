#pragma once
// Triangle meshes for the barrier contact-detection tests (built triangle by triangle, grid plates
// with optional holes, a grid plate with a reference triangle) and detection against all elements.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "state/barrier_topology.hpp"
#include "state/barriers.hpp"

namespace mpdem::test {

struct Mesh {
  Barriers b;
  MotionLaw law{};
  double thickness = 0.0;  // m
  void tri(const Vec3& p, const Vec3& q, const Vec3& r) {
    ASSERT_TRUE(b.add(static_cast<std::int64_t>(b.size()), p, q, r, 0, 1e9, 0.3, law, thickness,
                      std::numeric_limits<double>::quiet_NaN()));
  }
  // Quad p00 p10 p11 p01 split along p00-p11.
  void quad(const Vec3& p00, const Vec3& p10, const Vec3& p11, const Vec3& p01) {
    tri(p00, p10, p11);
    tri(p00, p11, p01);
  }
};

// Grid vertex (i, j) of the plate z = z0, origin o, spacing h; computed identically everywhere so
// shared vertices are bit-identical.
inline Vec3 gv(const Vec3& o, double h, int i, int j) { return {o.x + i * h, o.y + j * h, o.z}; }

// n x n squares, each split in two (interior vertices are shared by 6 triangles). Cells with
// hole(i, j) true are left out.
template <class Hole>
void add_grid(Mesh& m, const Vec3& o, double h, int n, Hole hole) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (!hole(i, j)) m.quad(gv(o, h, i, j), gv(o, h, i + 1, j), gv(o, h, i + 1, j + 1), gv(o, h, i, j + 1));
}
inline void add_grid(Mesh& m, const Vec3& o, double h, int n) {
  add_grid(m, o, h, n, [](int, int) { return false; });
}

inline std::vector<std::uint32_t> all_of(const Barriers& b) {
  std::vector<std::uint32_t> c(b.size());
  std::iota(c.begin(), c.end(), 0u);
  return c;
}

inline std::vector<BarrierContact> detect(const Barriers& b, const BarrierTopology& t, const Vec3& x, double R) {
  std::vector<BarrierContact> out;
  const auto cand = all_of(b);
  detect_barrier_contacts(b, t, x, R, cand, out);
  return out;
}

// An n x n grid plate of spacing h in z = 0 and, in the same plane, one large triangle: the
// reference surface the plate's contacts are compared with.
struct Plate {
  Mesh m;
  BarrierTopology topo;
  Mesh big;  // one large triangle in the same plane: the reference surface
  BarrierTopology big_topo;
  static constexpr double h = 0.1;
  static constexpr int n = 8;
  Vec3 o{-0.4, -0.4, 0.0};
  explicit Plate(double thickness = 0.0) {
    m.thickness = big.thickness = thickness;
    add_grid(m, o, h, n);
    big.tri({-10, -10, 0}, {10, -10, 0}, {0, 10, 0});
    topo = BarrierTopology::build(m.b);
    big_topo = BarrierTopology::build(big.b);
  }
};

}  // namespace mpdem::test
