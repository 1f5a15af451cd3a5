#pragma once
// Tangential contact: Mindlin spring-dashpot with Coulomb stick-slip (physics.md section 6,
// thesis (57)-(70)). Pure, allocation-free functions; the pair loop owns the spring history.
//
// Conventions: all forces are on particle i (j gets the negative, and its own torque
// r_Pj x (-f_t)); `f_n` is the magnitude of the net normal force |f_n| (N) after the clamp;
// v_t is the tangential relative velocity of i with respect to j at the contact point (m/s).
#include <cmath>
#include <cstdint>

#include "core/vec3.hpp"

namespace mpdem {

// G = E / (2 (1 + nu))   [Pa]
inline double shear_modulus(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

// Mindlin's no-slip effective shear modulus (Departure of section 6, replaces (66)):
// 1/G* = (2 - nu_i)/G_i + (2 - nu_j)/G_j   [Pa]
// Also the finite-stiffness barrier value, with the barrier's own G_j, nu_j (section 7).
inline double effective_shear_modulus(double G_i, double nu_i, double G_j, double nu_j) {
  return 1.0 / ((2.0 - nu_i) / G_i + (2.0 - nu_j) / G_j);
}

// Infinitely stiff barrier (G_j -> infinity): G* = G_i / (2 - nu_i)   [Pa]   (section 7)
inline double effective_shear_modulus_rigid(double G_i, double nu_i) { return G_i / (2.0 - nu_i); }

// Step 1 of section 6, (59): project the stored spring s (m) onto the plane normal to the
// current contact normal n (unit), then rescale it to its previous length, so a rigid rotation
// of the pair turns the spring with it instead of shrinking it. A spring parallel to n (no
// tangential direction left) becomes zero.
// Branch-free (selects, no early return), so that the pair kernel's loops over batches of
// contacts vectorise.
inline Vec3 project_spring(const Vec3& s, const Vec3& n) {
  const Vec3 p = s - dot(s, n) * n;
  const double lp2 = norm2(p), s2 = norm2(s);
  const bool keep = lp2 > 1e-30 * s2;  // false also for s = 0
  return p * (keep ? std::sqrt(s2 / (keep ? lp2 : 1.0)) : 0.0);
}

struct TangentialResult {
  Vec3 force;                     // N, tangential force on i (on j: -force)
  Vec3 spring;                    // m, spring to store for the next step
  bool slipped = false;           // true when the Coulomb limit was hit
  double dissipated_power = 0.0;  // W, estimate: dashpot d_t |v_t|^2 when sticking,
                                  //    friction work rate -f_t.v_t when slipping
};

// Steps 2-5 of section 6 (57)-(58), (68)-(70). Inputs: spring s (m) already projected by
// project_spring, increment ds (m) from (64), v_t (m/s), k_t (N/m), d_t (N s/m), static and
// dynamic friction coefficients mu_s >= mu_d, normal force magnitude f_n (N).
//
// Slip storage (choice documented in docs/contact_model.md): on slip the spring is stored at the
// DYNAMIC limit s = -(mu_d |f_n| / k_t) t, so that k_t |s| equals the applied sliding force and
// the next step starts from a spring consistent with it (thesis (69) uses the static limit;
// physics.md allows either). The same function serves particle and barrier contacts, so the
// choice is consistent across both.
// Stick-or-slip decision: by the Coulomb test (68), or imposed. Within the fixed-point iteration
// of one step the decision of the first iteration is imposed on the later ones: with
// mu_s > mu_d the force jumps at the decision, and a map with a jump has no fixed point (the
// iterates would alternate); with the decision fixed the map is continuous. The commit
// evaluation decides afresh (docs/contact_model.md).
// Eight bytes, the width of the doubles it is used with, so that the pair kernel's batch loops
// vectorise with one lane width (a narrower type makes the compiler pick 32-lane iterations and
// a long scalar remainder).
enum class SlipDecision : std::int64_t { Free, Stick, Slip };

// c ? a : b per component: a select the compiler vectorises (a ternary on whole structs becomes a
// branch).
inline Vec3 pick(bool c, const Vec3& a, const Vec3& b) { return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z}; }

// inv_k_t: 1/k_t (0 for k_t = 0), given by a caller that needs it too.
inline TangentialResult tangential_force(const Vec3& s, const Vec3& ds, const Vec3& v_t, double k_t, double inv_k_t,
                                         double d_t, double mu_s, double mu_d, double f_n, SlipDecision decide) {
  TangentialResult out;
  const Vec3 s_tent = s + ds;                        // (58)
  const Vec3 f_trial = -(k_t * s_tent + d_t * v_t);  // (57)
  const double ft2 = norm2(f_trial);
  const double limit_s = mu_s * std::abs(f_n);
  const bool coulomb = ft2 <= limit_s * limit_s;                        // (68)
  const bool imposed = (decide == SlipDecision::Stick) | (ft2 == 0.0);  // | : no short circuit
  const bool free = decide == SlipDecision::Free;
  const bool stick = (free & coulomb) | (!free & imposed);  // bitwise: a select, not a branch
  // Both outcomes are computed and one is selected (no branch, see project_spring); the slip
  // values use safe operands when sticking (ft2 > 0 whenever it slips).
  const Vec3 t = f_trial * (1.0 / std::sqrt(stick ? 1.0 : ft2));  // (70)
  const double f_slide = mu_d * std::abs(f_n);
  const Vec3 f_slip = f_slide * t;
  const double s_slip = -f_slide * inv_k_t;  // (69), dynamic limit
  out.force = pick(stick, f_trial, f_slip);  // stick (68) or slide
  out.spring = pick(stick, s_tent, s_slip * t);
  out.slipped = !stick;
  out.dissipated_power = stick ? d_t * norm2(v_t) : -dot(f_slip, v_t);
  return out;
}

inline TangentialResult tangential_force(const Vec3& s, const Vec3& ds, const Vec3& v_t, double k_t, double d_t,
                                         double mu_s, double mu_d, double f_n,
                                         SlipDecision decide = SlipDecision::Free) {
  return tangential_force(s, ds, v_t, k_t, k_t > 0.0 ? 1.0 / (k_t > 0.0 ? k_t : 1.0) : 0.0, d_t, mu_s, mu_d, f_n,
                          decide);
}

}  // namespace mpdem
