// Cyclic Jacobi eigenvalue iteration for symmetric 3x3 matrices (core/symmetric_eigen.hpp).
#include "core/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>

namespace mpdem {

SymmetricEigen symmetric_eigen(const Mat3& m) {
  Mat3 a = m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j) a[i][j] = a[j][i];
  Mat3 v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  double scale2 = 0.0;  // squared Frobenius norm: the convergence threshold is relative to it
  for (const auto& row : a)
    for (double x : row) scale2 += x * x;
  constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int sweep = 0; sweep < 64; ++sweep) {
    const double off2 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (!(off2 > 1e-36 * scale2)) break;  // also stops on NaN
    for (const auto& pq : kPairs) {
      const int p = pq[0], q = pq[1];
      if (a[p][q] == 0.0) continue;
      // Rotation in the (p, q) plane by the smaller angle that zeroes a[p][q]: t = tan(angle).
      const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
      const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
      // a <- J^T a J and v <- v J with J = I except J[p][p] = J[q][q] = c, J[p][q] = s, J[q][p] = -s.
      for (int k = 0; k < 3; ++k) {  // columns p and q: a J
        const double akp = a[k][p], akq = a[k][q];
        a[k][p] = c * akp - s * akq;
        a[k][q] = s * akp + c * akq;
        const double vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
      for (int k = 0; k < 3; ++k) {  // rows p and q: J^T (a J)
        const double apk = a[p][k], aqk = a[q][k];
        a[p][k] = c * apk - s * aqk;
        a[q][k] = s * apk + c * aqk;
      }
      a[p][q] = a[q][p] = 0.0;
    }
  }
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] < a[j][j]; });
  SymmetricEigen out;
  for (int k = 0; k < 3; ++k) {
    out.values[k] = a[order[k]][order[k]];
    for (int i = 0; i < 3; ++i) out.vectors[i][k] = v[i][order[k]];
  }
  return out;
}

}  // namespace mpdem
