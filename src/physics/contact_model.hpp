#pragma once
// ContactModel: the constant coefficients of one contact kind (particle-particle or
// particle-barrier), resolved once from the scene: the damping ratio xi_n from the restitution
// coefficient (physics.md section 5, Departure) or as given, and the friction and rolling
// coefficients of sections 6.
#include "model/params.hpp"
#include "physics/restitution.hpp"

namespace mpdem {

struct ContactModel {
  double xi_n = 0.0;        // -, normal damping ratio used in (50)
  double xi_t = 0.0;        // -, tangential damping ratio (67)
  double mu_s = 0.0;        // -, static friction (68)
  double mu_d = 0.0;        // -, dynamic friction (69)
  double mu_r = 0.0;        // -, rolling resistance (71)

  static ContactModel from(const ContactLawParams& c) {
    ContactModel m;
    if (c.damping_ratio)
      m.xi_n = *c.damping_ratio;
    else if (c.restitution)
      m.xi_n = damping_ratio_for_restitution(*c.restitution);
    m.xi_t = c.tangential_damping;
    m.mu_s = c.mu_static;
    m.mu_d = c.mu_dynamic;
    m.mu_r = c.mu_rolling;
    return m;
  }
};

}  // namespace mpdem
