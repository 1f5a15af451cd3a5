#include "physics/principal_axes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace mpdem {
namespace {
constexpr double kOffDiagonal = 1e-13;  // relative to the largest diagonal term: round-off, dropped
}  // namespace

PrincipalAxes principal_axes(const Mat3& tensor, double tie_rel) {
  Mat3 a = tensor;
  PrincipalAxes out;
  Vec3& values = out.moments;
  Mat3& axes = out.axes;
  const double big = std::max({std::abs(a[0][0]), std::abs(a[1][1]), std::abs(a[2][2])});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j && std::abs(a[i][j]) <= kOffDiagonal * big) a[i][j] = 0.0;
  Mat3 v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 50; ++sweep) {  // cyclic Jacobi; converges quadratically
    bool rotated = false;
    for (const auto& [p, q] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
      const double apq = a[p][q];
      if (apq == 0.0) continue;
      if (std::abs(apq) <= 1e-18 * (std::abs(a[p][p]) + std::abs(a[q][q]))) {
        a[p][q] = a[q][p] = 0.0;
        continue;
      }
      const double theta = (a[q][q] - a[p][p]) / (2.0 * apq);
      const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), sn = t * c;
      a[p][p] -= t * apq;
      a[q][q] += t * apq;
      a[p][q] = a[q][p] = 0.0;
      const int r = 3 - p - q;
      const double arp = a[r][p], arq = a[r][q];
      a[r][p] = a[p][r] = c * arp - sn * arq;
      a[r][q] = a[q][r] = sn * arp + c * arq;
      for (int k = 0; k < 3; ++k) {
        const double vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - sn * vkq;
        v[k][q] = sn * vkp + c * vkq;
      }
      rotated = true;
    }
    if (!rotated) break;
  }
  std::array<double, 3> sorted{a[0][0], a[1][1], a[2][2]};
  std::sort(sorted.begin(), sorted.end());
  const double tie = tie_rel * std::abs(sorted[2]);  // moments closer than this are equal
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] < a[j][j]; });
  for (int pass = 0; pass < 2; ++pass)  // equal moments keep the input order of their axes
    for (int k = 0; k < 2; ++k)
      if (order[k] > order[k + 1] && a[order[k + 1]][order[k + 1]] - a[order[k]][order[k]] <= tie)
        std::swap(order[k], order[k + 1]);
  for (int k = 0; k < 3; ++k) {
    values[k] = sorted[k];
    int big_row = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(v[i][order[k]]) > std::abs(v[big_row][order[k]])) big_row = i;
    const double sign = v[big_row][order[k]] < 0.0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) axes[i][k] = sign * v[i][order[k]];
  }
  const Vec3 c0{axes[0][0], axes[1][0], axes[2][0]}, c1{axes[0][1], axes[1][1], axes[2][1]};
  const Vec3 c2{axes[0][2], axes[1][2], axes[2][2]};
  if (dot(cross(c0, c1), c2) > 0.0) return out;
  for (int k = 0; k < 2; ++k) {  // left-handed: swap two equal moments' axes if there are such
    if (values[k + 1] - values[k] <= tie) {
      for (int i = 0; i < 3; ++i) std::swap(axes[i][k], axes[i][k + 1]);
      return out;
    }
  }
  for (int i = 0; i < 3; ++i) axes[i][2] = -axes[i][2];
  return out;
}

}  // namespace mpdem
