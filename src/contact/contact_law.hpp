#pragma once
// The one evaluation of a contact that the particle-pair and particle-barrier kernels and the
// tests all call, for any law of contact/laws/law_list.hpp.
//
// A law (contact/laws/<law>.hpp) gives the overlap-dependent normal stiffness, elastic force,
// tangential stiffness and stored normal energy from the pair's constants (PairLaw). Everything
// else of a contact (damping from the calibrated ratio, the projected spring, Coulomb stick-slip,
// energy and the damping/friction split) is common and lives here. The kernels are templates over
// the law, so no law is dispatched per contact; MixedLaw serves a table that mixes laws (all
// evaluated, one selected per lane). Everything is branch-free (selects), so that the kernels'
// loops over batches vectorise.
#include <cmath>

#include "contact/laws/law_list.hpp"
#include "core/vec3.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

// One contact as the kernel's geometry gives it.
struct ContactState {
  double overlap = 0.0;      // m, > 0 in contact
  double r_star = 0.0;       // m, (52) (barrier: R)
  double m_star = 0.0;       // kg, (53) (barrier: m)
  double inv_reach = 0.0;    // 1/m, 1 / (R_i + R_j) (barrier: 0)
  Vec3 normal;               // -, unit, towards the body the force acts on
  double normal_rate = 0.0;  // m/s, v_rel . n (negative approaching)
  Vec3 vt;                   // m/s, tangential relative velocity (60)
  Vec3 spring;               // m (N: incremental form), stored spring (any plane; projected here (59))
  Vec3 increment;            // m, spring increment of the step (64)
  SlipDecision decide = SlipDecision::Free;
};

struct ContactResult {
  double fn = 0.0;        // N, net normal force along n, >= -adhesion where the law clamps
  double fn_limit = 0.0;  // N, max(fn + load_offset, 0): what Coulomb's limit and rolling resistance scale with
  Vec3 ft;                // N, tangential force
  Vec3 spring;            // m (N: incremental form, k_t s), spring for the next step
  bool slipped = false;
  double energy = 0.0;   // J, elastic energy stored (normal + tangential spring)
  double damping = 0.0;  // W, dissipated by the normal dashpot
  // J, removed by the tangential spring-dashpot in the step at this step's stiffness: the work
  // the contact's tangential force took from the bodies, -f_t . ds, less what the spring gained,
  // 1/2 k_t (|s_new|^2 - |s|^2) (s: the stored spring). Sliding, that is the friction work plus
  // the spring energy cut at the limit (at a stick-to-slip transition: the drop from the static
  // to the dynamic limit); sticking, the dashpot's work. What the change of k_t(delta) since the
  // last step does to the stored energy is booked by the caller, for all contacts at once
  // (Interactions::evaluate), from spring_energy_before.
  double tangential_loss = 0.0;
  double spring_energy_before = 0.0;  // J, 1/2 k_t |s|^2: the stored spring at this step's stiffness
  double spring_energy = 0.0;         // J, 1/2 k_t |s_new|^2: the spring for the next step (in energy)
};

// The normal half of a contact: what the tangential half and the sums need of it.
struct NormalContact {
  double fn = 0.0;        // N, net normal force (ContactResult::fn)
  double fn_limit = 0.0;  // N, max(fn + load_offset, 0)
  double k_t = 0.0;       // N/m, tangential stiffness
  double d_t = 0.0;       // N s/m, tangential damping
  double energy = 0.0;    // J, elastic energy of the normal spring
  double damping = 0.0;   // W, dissipated by the normal dashpot
};

// Damping d_n = 2 xi_n sqrt(m* k_n) (50) and d_t = 2 xi_t sqrt(m* k_t) (67), which shares the
// root: sqrt(m* k_t) = sqrt(m* k_n) sqrt(k_t / k_n), and k_t / k_n is constant for every law
// (shear_root). The net normal force f = f_el - d_n rate (49); the power removed
// (f_el - f_n) rate (tests/support/hertz_oracle.hpp's damped_normal_force explains the clamped case).
// An adhesive law (Law::kAdhesion) clamps at the pull-off instead of zero: the dashpot never makes
// the force more attractive than -adhesion, and Coulomb's limit and rolling resistance scale with
// the load pressing the surfaces together, fn + load_offset (DMT: the adhesion acts as an extra
// load; JKR: fn + 2 F_c, Thornton's).
// inv_reach: 1 / (R_i + R_j) (m^-1; 0 at a barrier), for laws that need the overlap's exact geometry.
template <class Law>
inline NormalContact normal_contact(const PairLaw& c, double r_star, double m_star, double overlap, double normal_rate,
                                    double inv_reach = 0.0) {
  NormalContact out;
  const Stiffness k = Law::stiffness(c, r_star, overlap, inv_reach);
  const double mass_root = std::sqrt(m_star * k.k_n);  // sqrt(kg N/m)
  const double d_n = 2.0 * c.c[kXiN] * mass_root;
  out.d_t = 2.0 * c.c[kXiT] * mass_root * c.c[kShearRoot];
  const double f = k.f_el - d_n * normal_rate;
  if constexpr (Law::kAdhesion) {
    const double floor = 0.0 - k.adhesion;  // +0 without adhesion, as the clamp at zero gives
    out.fn = (k.clamp & (f < floor)) ? floor : f;
    const double load = out.fn + k.load_offset;
    out.fn_limit = load > 0.0 ? load : 0.0;
  } else {
    out.fn = (k.clamp & (f < 0.0)) ? 0.0 : f;
    out.fn_limit = out.fn > 0.0 ? out.fn : 0.0;
  }
  out.damping = (k.f_el - out.fn) * normal_rate;
  out.k_t = k.k_t;
  out.energy = k.energy;
  return out;
}

// The tangential half (57)-(70): the stored spring projected onto the tangent plane (59), plus
// the increment, Coulomb stick or slip against mu_s, mu_d and the normal force.
// The total spring (thesis (57)-(58)) stores s (m): f_t = -k_t(delta) (s + ds). The incremental
// one (Mindlin; physics.md section 6) stores k_t s (N), the elastic force of the last step,
// and this step's stiffness scales only the increment: f_t = -(k_t' s' + k_t ds) (a select: one
// law, either form, no branch).
inline ContactResult tangential_contact(double mu_s, double mu_d, TangentialSpring form, const NormalContact& n,
                                        const Vec3& spring, const Vec3& normal, const Vec3& increment, const Vec3& vt,
                                        SlipDecision decide) {
  ContactResult out;
  out.fn = n.fn;
  out.fn_limit = n.fn_limit;
  const bool positive = n.k_t > 0.0;
  const double inv_k_t = positive ? 1.0 / (positive ? n.k_t : 1.0) : 0.0;  // m/N
  const bool scaled = (form == TangentialSpring::Incremental) & positive;
  const double kept = scaled ? n.k_t : 1.0;  // stored = kept s
  const Vec3 projected = project_spring(spring, normal);
  const double to_m = scaled ? inv_k_t : 1.0;
  const Vec3 s{to_m * projected.x, to_m * projected.y, to_m * projected.z};  // m
  const TangentialResult t = tangential_force(s, increment, vt, n.k_t, inv_k_t, n.d_t, mu_s, mu_d, n.fn_limit, decide);
  // Component by component: a whole-Vec3 copy between the two result records keeps GCC from
  // splitting them into scalars, and the kernels' loops would not vectorise.
  out.ft.x = t.force.x, out.ft.y = t.force.y, out.ft.z = t.force.z;
  out.spring.x = kept * t.spring.x, out.spring.y = kept * t.spring.y, out.spring.z = kept * t.spring.z;
  out.slipped = t.slipped;
  out.spring_energy = 0.5 * n.k_t * (t.spring.x * t.spring.x + t.spring.y * t.spring.y + t.spring.z * t.spring.z);
  out.spring_energy_before = 0.5 * n.k_t * (s.x * s.x + s.y * s.y + s.z * s.z);
  out.energy = n.energy + out.spring_energy;
  out.damping = n.damping;
  const double work = -(out.ft.x * increment.x + out.ft.y * increment.y + out.ft.z * increment.z);  // J
  out.tangential_loss = work - (out.spring_energy - out.spring_energy_before);
  return out;
}

// One contact: the normal half, then the tangential half. The pair kernel runs the halves in two
// loops over a batch (fewer live values per loop); everything else calls this.
template <class Law>
inline ContactResult evaluate_contact(const PairLaw& c, const ContactState& s) {
  return tangential_contact(c.c[kMuS], c.c[kMuD], c.spring,
                            normal_contact<Law>(c, s.r_star, s.m_star, s.overlap, s.normal_rate, s.inv_reach), s.spring,
                            s.normal, s.increment, s.vt, s.decide);
}

}  // namespace mpdem
