#include "model/body_members.hpp"

#include "core/parallel.hpp"

namespace mpdem {

namespace {

template <bool kPositions>
void set_members(const std::vector<ClumpTemplate>& clumps, Particles& p) {
  Bodies& B = p.bodies;
  B.index_members(p);
  const std::size_t nb = B.size();
#pragma omp parallel for schedule(static) if (nb > kParallelThreshold / 4)
  for (std::size_t b = 0; b < nb; ++b) {
    const Mat3 R = quat_matrix(B.q[b]);
    const std::vector<ClumpMember>& m = clumps[static_cast<std::size_t>(B.clump[b])].members();
    for (std::uint32_t k = 0; k < B.first[b + 1] - B.first[b]; ++k) {
      const std::size_t i = B.index[B.first[b] + k];
      const Vec3 d = mat_apply(R, m[k].x);  // m, member centre relative to the centre of mass
      p.v[i] = B.v[b] + cross(B.w[b], d);
      p.w[i] = B.w[b];
      if constexpr (kPositions) {
        p.x[i] = B.x[b] + d;
        p.q[i] = B.q[b];
        p.T[i] = B.T[b];
      }
    }
  }
}

}  // namespace

void place_members(const std::vector<ClumpTemplate>& clumps, Particles& p) { set_members<true>(clumps, p); }
void move_members(const std::vector<ClumpTemplate>& clumps, Particles& p) { set_members<false>(clumps, p); }

}  // namespace mpdem
