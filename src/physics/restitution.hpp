#pragma once
// Restitution -> damping-ratio calibration for the Hertz law with nonlinear damping
// (physics.md section 5, the Departure from thesis (55)).
//
// Why the mapping depends on e alone. A binary collision (pair or sphere-barrier) obeys, with
// overlap delta >= 0, impact speed v, K = 4/3 E* sqrt(r*) and the zero clamp of (49):
//
//   m* delta'' = -max(0, K delta^(3/2) + 2 xi sqrt(2 m* E* sqrt(r*)) delta^(1/4) delta')
//
// Scale delta = delta0 x and t = T tau with delta0 = (m* v^2 / K)^(2/5) and T = delta0 / v.
// Dividing by m* v^2 / delta0 and using delta0^(5/4) = v sqrt(m*/K), the elastic coefficient is
// K delta0^(5/2) / (m* v^2) = 1 and the damping coefficient is
// 2 xi sqrt(2 E* sqrt(r*) / m*) delta0^(5/4) / v = 2 xi sqrt(2 E* sqrt(r*) / K) = sqrt(6) xi:
//
//   x'' = -max(0, x^(3/2) + sqrt(6) xi x^(1/4) x'),   x(0) = 0, x'(0) = 1,
//
// and the restitution is e = -x' at separation. No m*, E*, r* or v is left: e depends on xi
// only, so one integration per e serves every speed, radius and material (and barriers).
// Note: once the clamp engages (during recovery) it stays engaged, because x^(5/4) keeps
// falling while x' stays constant; so the separation speed is x' at the clamp instant.

namespace mpdem {

// Smallest restitution the calibration accepts (the scene reader refuses smaller ones). No
// finite damping ratio gives e = 0: strongly damped, the pair separates just after the deepest
// overlap and e -> 5 / (24 xi^2) (xi = 14.35 at e = 1e-3), so e -> 0 needs xi -> infinity; a
// smaller e would rebound at under 1/1000 of the impact speed, practically not at all.
inline constexpr double kMinRestitution = 1e-3;

// Rebound restitution of the dimensionless collision above for damping ratio xi >= 0
// (xi = 0 -> 1). Integrated with RK4 on a graded step (fine near first touch, where x^(1/4) is
// not smooth) and the clamp instant located by step halving; accuracy ~1e-10.
double restitution_for_damping_ratio(double xi);

// The damping ratio xi_n that, used in (50) with the zero clamp, rebounds a binary Hertz
// collision with restitution e (Departure of section 5). e in [kMinRestitution, 1]; e = 1 -> 0.
// Root of restitution_for_damping_ratio(xi) = e by bracketed regula falsi (Illinois) to ~1e-12
// in e. Results are cached (thread-safe); meant for setup, not per contact.
// Throws std::invalid_argument for e outside [kMinRestitution, 1].
double damping_ratio_for_restitution(double e);

}  // namespace mpdem
