#pragma once
// Coarse-graining kernels (Goldhirsch 2010; Weinhart et al. 2012, 2013; MercuryCG): the weight
// phi(r) [1/m^d] that spreads a particle's mass, momentum and contact forces over the d resolved
// axes of a CgGrid (d = 0..3). Each kernel integrates to exactly 1 over R^d, so the coarse-grained
// fields conserve mass and momentum whatever the width.
//
//  - gaussian: phi = exp(-r^2 / (2 w^2)) / ((2 pi w^2)^(d/2) M_d) for r < 3w, 0 beyond. The cut
//    at 3w keeps the support finite; M_d is the mass of the uncut Gaussian inside the cut, so the
//    cut kernel integrates to 1: M_1 = erf(3/sqrt2), M_2 = 1 - exp(-9/2),
//    M_3 = erf(3/sqrt2) - 3 sqrt(2/pi) exp(-9/2) (M_0 = 1).
//  - lucy: phi = A_d (1 - 6q^2 + 8q^3 - 3q^4) = A_d (1-q)^3 (1+3q), q = r/c < 1, with the cutoff
//    c = 2w (MercuryCG's convention for the width of the Lucy function); A_1 = 5/(4c),
//    A_2 = 5/(pi c^2), A_3 = 105/(16 pi c^3) (A_0 = 1). It is C^2 at the cutoff.
// For d = 0 (every axis averaged) phi = 1: the fields become plain volume averages.
#include <cmath>

#include "core/vec3.hpp"

namespace mpdem {

enum class CgKernel { gaussian, lucy };

// Cutoff radius [m] beyond which phi = 0, for a width w [m]: 3w (gaussian), 2w (lucy).
double cg_cutoff(CgKernel kernel, double width);

// One kernel (shape, width, dimension) with its constants precomputed, for the inner loops.
// Distances are over the resolved axes only: the caller zeroes the averaged components of every
// displacement it passes (the kernel is not applied along averaged axes).
class CgKernelFunction {
 public:
  // Throws std::invalid_argument unless width > 0 (finite) and 0 <= dims <= 3.
  CgKernelFunction(CgKernel kernel, double width, int dims);

  CgKernel kind() const { return kind_; }
  double width() const { return width_; }    // m
  double cutoff() const { return cutoff_; }  // m
  int dims() const { return dims_; }
  double peak() const { return prefactor_; }  // 1/m^d, phi(0)

  // phi [1/m^d] at the squared distance r2 [m^2]; 0 for r >= cutoff.
  double operator()(double r2) const {
    if (r2 >= cutoff2_) return 0.0;
    if (kind_ == CgKernel::gaussian) return prefactor_ * std::exp(-r2 * inv_2w2_);
    const double u = 1.0 - std::sqrt(r2) / cutoff_;   // 1 - q
    return prefactor_ * u * u * u * (4.0 - 3.0 * u);  // (1-q)^3 (1+3q)
  }

  // ∫_0^1 phi(|a + s b|) ds [1/m^d]: the kernel along the segment from a to a + b [m] (both
  // already restricted to the resolved axes). Used for the contact stress, which spreads a
  // contact's force along its branch vector (Weinhart et al. 2012, contact stress). Exact up to
  // rounding: the s-interval is clipped to the chord inside the cutoff sphere, then the Gaussian
  // is integrated with erf and the Lucy polynomial with its closed-form antiderivative, or with
  // Gauss-Legendre where that would cancel (short chords, chords close to the cutoff).
  double line_integral(const Vec3& a, const Vec3& b) const;

 private:
  CgKernel kind_;
  double width_;      // m
  double cutoff_;     // m
  double cutoff2_;    // m^2
  double inv_2w2_;    // 1/m^2, 1/(2 w^2) (gaussian)
  double prefactor_;  // 1/m^d, phi(0)
  int dims_;
};

}  // namespace mpdem
