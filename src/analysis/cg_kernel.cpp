#include "analysis/cg_kernel.hpp"

#include <algorithm>
#include <array>
#include <numbers>
#include <stdexcept>

namespace mpdem {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kShortChord = 0.02;  // -, chords shorter than this (in kernel units) use Gauss-Legendre

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (exact for polynomials up to degree 15).
constexpr std::array<double, 4> kGlX = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGlW = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

template <class F>
double gauss_legendre(F&& f, double lo, double hi) {
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  double sum = 0.0;
  for (std::size_t k = 0; k < kGlX.size(); ++k) sum += kGlW[k] * (f(mid - half * kGlX[k]) + f(mid + half * kGlX[k]));
  return sum * half;
}

// ∫_{x1}^{x2} exp(-x^2) dx for |x| <= 3/sqrt2 (inside the Gaussian's cut). erfc on the side where
// both ends have one sign keeps the difference accurate; short intervals use Gauss-Legendre,
// whose error there is far below rounding (the integrand is entire).
double gauss_area(double x1, double x2) {
  if (x2 - x1 < kShortChord) return gauss_legendre([](double x) { return std::exp(-x * x); }, x1, x2);
  const double c = 0.5 * std::sqrt(kPi);
  if (x1 >= 0.0) return c * (std::erfc(x1) - std::erfc(x2));
  if (x2 <= 0.0) return c * (std::erfc(-x2) - std::erfc(-x1));
  return c * (std::erf(x2) - std::erf(x1));
}

// Lucy's shape (1-q)^3 (1+3q) at q = sqrt(eta^2 + tau^2) (all in units of the cutoff).
double lucy_shape(double eta, double tau) {
  const double u = std::max(0.0, 1.0 - std::sqrt(eta * eta + tau * tau));
  return u * u * u * (4.0 - 3.0 * u);
}

// Antiderivative in tau of 1 - 6q^2 + 8q^3 - 3q^4, q^2 = eta^2 + tau^2; the q^3 term from
// ∫(e^2+t^2)^(3/2) dt = t (2t^2 + 5e^2) sqrt(e^2+t^2)/8 + 3e^4/8 asinh(t/e).
double lucy_antiderivative(double eta, double tau) {
  const double e2 = eta * eta, t2 = tau * tau;
  double g = tau * (1.0 - 6.0 * e2 - 3.0 * e2 * e2) - tau * t2 * (2.0 + 2.0 * e2) - 0.6 * tau * t2 * t2 +
             tau * (2.0 * t2 + 5.0 * e2) * std::sqrt(e2 + t2);
  if (eta > 0.0) g += 3.0 * e2 * e2 * std::asinh(tau / eta);
  return g;
}

// ∫_a^b (1-q)^3 (1+3q) dtau for 0 <= a < b (one side of the closest point, q increasing).
// Gauss-Legendre where it converges fast and keeps full relative accuracy: pieces with q >= 1/2
// throughout (the branch points tau = ±i eta of q are then >= c/2 away; subintervals of <= c/4,
// error ~1e-15), where the closed form would cancel since the integrand vanishes like (1-q)^3 at
// the cutoff; and short pieces (two subintervals). Elsewhere the closed form, free of
// cancellation there: the integrand reaches g(1/2) = 5/16 or more on the piece.
double lucy_piece(double eta, double a, double b) {
  const bool outer = eta * eta + a * a >= 0.25;
  if (b - a >= kShortChord && !outer) return lucy_antiderivative(eta, b) - lucy_antiderivative(eta, a);
  const auto f = [eta](double tau) { return lucy_shape(eta, tau); };
  const int pieces = outer ? 1 + static_cast<int>((b - a) / 0.25) : 2;
  double sum = 0.0;
  for (int k = 0; k < pieces; ++k) sum += gauss_legendre(f, a + (b - a) * k / pieces, a + (b - a) * (k + 1) / pieces);
  return sum;
}

// ∫_{tau1}^{tau2} (1-q)^3 (1+3q) dtau along a line at distance eta from the centre (units of c,
// chord inside q <= 1), split at the closest point tau = 0 where q has its kink as eta -> 0.
double lucy_area(double eta, double tau1, double tau2) {
  if (tau1 < 0.0 && tau2 > 0.0) return lucy_piece(eta, 0.0, -tau1) + lucy_piece(eta, 0.0, tau2);
  if (tau2 <= 0.0) return lucy_piece(eta, -tau2, -tau1);
  return lucy_piece(eta, tau1, tau2);
}

}  // namespace

double cg_cutoff(CgKernel kernel, double width) { return (kernel == CgKernel::gaussian ? 3.0 : 2.0) * width; }

CgKernelFunction::CgKernelFunction(CgKernel kernel, double width, int dims)
    : kind_(kernel), width_(width), cutoff_(cg_cutoff(kernel, width)), cutoff2_(cutoff_ * cutoff_),
      inv_2w2_(0.5 / (width * width)), prefactor_(1.0), dims_(dims) {
  if (!(width > 0.0) || !std::isfinite(width)) throw std::invalid_argument("CgKernelFunction: width must be > 0");
  if (dims < 0 || dims > 3) throw std::invalid_argument("CgKernelFunction: dims must be in [0, 3]");
  if (kernel == CgKernel::gaussian) {
    // Mass of the uncut unit Gaussian inside r < 3 (in units of w), per dimension.
    const double m1 = std::erf(3.0 / std::numbers::sqrt2);
    const double mass[4] = {1.0, m1, 1.0 - std::exp(-4.5), m1 - std::sqrt(2.0 / kPi) * 3.0 * std::exp(-4.5)};
    prefactor_ = 1.0 / (std::pow(2.0 * kPi * width * width, 0.5 * dims) * mass[dims]);
  } else {
    const double c = cutoff_;
    const double a[4] = {1.0, 5.0 / (4.0 * c), 5.0 / (kPi * c * c), 105.0 / (16.0 * kPi * c * c * c)};
    prefactor_ = a[dims];
  }
}

double CgKernelFunction::line_integral(const Vec3& a, const Vec3& b) const {
  const double b2 = norm2(b);  // m^2
  // A segment much shorter than the cutoff (or none along the resolved axes, e.g. a horizontal
  // branch in a vertical profile): phi is constant on it to ~(len/cutoff)^2.
  if (b2 <= 1e-18 * cutoff2_) return (*this)(norm2(a + 0.5 * b));
  const double s0 = -dot(a, b) / b2;    // -, s of the line's closest approach to the centre
  const double h2 = norm2(a + s0 * b);  // m^2, squared distance of the line from the centre
  if (h2 >= cutoff2_) return 0.0;
  const double len = std::sqrt(b2);                    // m
  const double half = std::sqrt(cutoff2_ - h2) / len;  // -, half of the chord inside the cutoff, in s
  const double s1 = std::max(0.0, s0 - half), s2 = std::min(1.0, s0 + half);
  if (s1 >= s2) return 0.0;
  const double t1 = len * (s1 - s0), t2 = len * (s2 - s0);  // m, along the line from the closest point
  if (kind_ == CgKernel::gaussian) {
    // exp(-(h^2 + t^2)/(2w^2)): a constant times a 1-D Gaussian in t; ds = dt / len.
    const double k = std::numbers::sqrt2 * width_;  // m
    return prefactor_ * std::exp(-h2 * inv_2w2_) * (k / len) * gauss_area(t1 / k, t2 / k);
  }
  return prefactor_ * (cutoff_ / len) * lucy_area(std::sqrt(h2) / cutoff_, t1 / cutoff_, t2 / cutoff_);
}

}  // namespace mpdem
