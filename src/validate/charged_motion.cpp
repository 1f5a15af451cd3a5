// Closed-form motion of a charge in uniform E and B (charged_motion.hpp).
#include "validate/charged_motion.hpp"

#include <complex>

namespace mpdem::validate {

ChargedState charged_motion(const Vec3& x0, const Vec3& v0, double q, double m, const Vec3& E, const Vec3& B,
                            const Vec3& g, double t) {
  if (B.x != 0.0 || B.y != 0.0) throw std::invalid_argument("charged_motion: B must be along z");
  using C = std::complex<double>;
  const double a = q / m;           // C/kg
  const Vec3 Ee = E + g * (m / q);  // V/m, gravity as an equivalent field
  ChargedState s;
  s.x.z = x0.z + v0.z * t + 0.5 * a * Ee.z * t * t;
  s.v.z = v0.z + a * Ee.z * t;
  const C X0(x0.x, x0.y), V0(v0.x, v0.y), Ep(Ee.x, Ee.y);
  C X, V;
  if (B.z == 0.0) {
    V = V0 + a * Ep * t;
    X = X0 + V0 * t + 0.5 * a * Ep * t * t;
  } else {
    const double w = a * B.z;                               // rad/s
    const C vd = C(Ee.y * B.z, -Ee.x * B.z) / (B.z * B.z);  // E x B / B^2
    const C u0 = V0 - vd, rot = std::exp(C(0.0, -w * t));
    V = vd + u0 * rot;
    X = X0 + vd * t + u0 * (1.0 - rot) / C(0.0, w);
  }
  s.x.x = X.real();
  s.x.y = X.imag();
  s.v.x = V.real();
  s.v.y = V.imag();
  return s;
}

}  // namespace mpdem::validate
