#include "contact/barrier_batch.hpp"

#include "contact/cohesive_contact.hpp"
#include "contact/contact_law.hpp"
#include "physics/contact_geometry.hpp"

namespace mpdem {

namespace {

// The lanes past count repeat the last contact (count >= 1), so the law computes finite values
// nobody reads.
void pad(BarrierBatch& b) {
  const std::size_t l = b.count - 1;
  for (std::size_t t = b.count; t < b.lanes(); ++t) {
    b.decide[t] = b.decide[l];
    b.overlap[t] = b.overlap[l];
    b.nx[t] = b.nx[l], b.ny[t] = b.ny[l], b.nz[t] = b.nz[l];
    b.vx[t] = b.vx[l], b.vy[t] = b.vy[l], b.vz[t] = b.vz[l];
    b.wx[t] = b.wx[l], b.wy[t] = b.wy[l], b.wz[t] = b.wz[l];
    b.ux[t] = b.ux[l], b.uy[t] = b.uy[l], b.uz[t] = b.uz[l];
    b.s0x[t] = b.s0x[l], b.s0y[t] = b.s0y[l], b.s0z[t] = b.s0z[l];
    b.vt0x[t] = b.vt0x[l], b.vt0y[t] = b.vt0y[l], b.vt0z[t] = b.vt0z[l];
    b.set_law(t, b.law_of(l));
    b.r_star[t] = b.r_star[l], b.m_star[t] = b.m_star[l];
    b.state0[t] = b.state0[l], b.bridge[t] = b.bridge[l];
  }
}

template <class Law, bool kCohesive>
void contact_law_lanes(const EvalRequest& req, BarrierBatch& b) {
  const double dt = req.dt, phi = req.phi;
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    ContactState c;
    c.normal = {b.nx[t], b.ny[t], b.nz[t]};
    c.overlap = b.overlap[t];
    c.r_star = b.r_star[t];
    c.m_star = b.m_star[t];
    const Vec3 rP = -c.r_star * c.normal;
    const Vec3 vrel = contact_relative_velocity_barrier({b.vx[t], b.vy[t], b.vz[t]}, {b.wx[t], b.wy[t], b.wz[t]}, rP,
                                                        {b.ux[t], b.uy[t], b.uz[t]});
    c.normal_rate = normal_rate(vrel, c.normal);
    c.vt = tangential_part(vrel, c.normal);
    c.spring = {b.s0x[t], b.s0y[t], b.s0z[t]};
    c.increment = dt * ((1.0 - phi) * Vec3{b.vt0x[t], b.vt0y[t], b.vt0z[t]} + phi * c.vt);  // (64)
    c.decide = b.decide[t];
    ContactResult r;
    if constexpr (kCohesive) {
      const PairLaw law = b.law_of(t);
      const CohesiveNormal cn = cohesive_normal<Law>(law, b.bridge[t], b.state0[t], c.r_star, c.m_star, c.overlap,
                                                     c.normal_rate, 0.0);
      r = tangential_contact(law.c[kMuS], law.c[kMuD], law.spring, cn.n, c.spring, c.normal, c.increment, c.vt,
                             c.decide);
      if ((cn.live & kLawFormed) == 0) without_contact(r, cn.n);
      b.live[t] = cn.live, b.next[t] = cn.next, b.broke[t] = cn.broke;
      b.loss[t] = cn.loss;
    } else {
      r = evaluate_contact<Law>(b.law_of(t), c);
    }
    const Vec3 f = r.fn * c.normal + r.ft;
    const Vec3 arm = cross(rP, r.ft);
    b.fx[t] = f.x, b.fy[t] = f.y, b.fz[t] = f.z;
    b.tx[t] = arm.x, b.ty[t] = arm.y, b.tz[t] = arm.z;
    b.sx[t] = r.spring.x, b.sy[t] = r.spring.y, b.sz[t] = r.spring.z;
    b.vtx[t] = c.vt.x, b.vty[t] = c.vt.y, b.vtz[t] = c.vt.z;
    b.fn_load[t] = r.fn_limit;
    b.energy[t] = r.energy;
    b.damping[t] = r.damping;
    b.spring_energy_before[t] = r.spring_energy_before;
    b.spring_energy_after[t] = r.spring_energy;
    b.tangential_loss[t] = r.tangential_loss;
    b.slip[t] = r.slipped ? 1 : 0;
  }
}

}  // namespace

// Lane by lane (vectorised; the laws are branch-free).
void barrier_contact_law(LawSet laws, const EvalRequest& req, BarrierBatch& b, bool cohesive) {
  pad(b);
  with_laws(laws, [&]<class Law>(std::type_identity<Law>) {
    if (cohesive) contact_law_lanes<Law, true>(req, b);
    else contact_law_lanes<Law, false>(req, b);
  });
}

}  // namespace mpdem
