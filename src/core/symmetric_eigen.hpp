#pragma once
// Eigenvalues and eigenvectors of a symmetric 3x3 matrix by cyclic Jacobi rotations: each rotation
// zeroes one off-diagonal pair, the sum of the squared off-diagonal entries falls quadratically,
// and the eigenvalues come out to a few ulps of the matrix's norm (what principal moments of
// inertia need; a closed-form cubic loses digits when two eigenvalues nearly coincide).
#include <array>

#include "core/rotation.hpp"

namespace mpdem {

struct SymmetricEigen {
  std::array<double, 3> values{};  // ascending
  Mat3 vectors{};                  // column k (vectors[i][k], i = 0..2) is the unit eigenvector of values[k]
};

// `a` must be symmetric; only its upper triangle is read.
SymmetricEigen symmetric_eigen(const Mat3& a);

}  // namespace mpdem
