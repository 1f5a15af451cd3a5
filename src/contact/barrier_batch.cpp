#include "contact/barrier_batch.hpp"

#include "physics/contact_coefficients.hpp"
#include "physics/contact_geometry.hpp"
#include "physics/hertz.hpp"

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
    b.E[t] = b.E[l], b.G[t] = b.G[l], b.r[t] = b.r[l], b.m[t] = b.m[l];
  }
}

}  // namespace

// The very expressions of the one-contact form, lane by lane (vectorised; the laws are
// branch-free).
void barrier_contact_law(const ContactModel& law, const EvalRequest& req, BarrierBatch& b) {
  pad(b);
  const double dt = req.dt, phi = req.phi;
  const double xi_n = law.xi_n, xi_t = law.xi_t, mu_s = law.mu_s, mu_d = law.mu_d;
  for (std::size_t t = 0; t < b.lanes(); ++t) {
    const Vec3 nrm{b.nx[t], b.ny[t], b.nz[t]};
    const double r = b.r[t];
    const Vec3 rP = -r * nrm;
    const Vec3 vrel = contact_relative_velocity_barrier({b.vx[t], b.vy[t], b.vz[t]}, {b.wx[t], b.wy[t], b.wz[t]}, rP,
                                                        {b.ux[t], b.uy[t], b.uz[t]});
    const double vn = normal_rate(vrel, nrm);
    const Vec3 vt = tangential_part(vrel, nrm);
    // (49)-(50), (65), (67) sharing one sqrt(r* delta).
    const ContactCoefficients cc = contact_coefficients(b.E[t], b.G[t], r, b.m[t], xi_n, xi_t, b.overlap[t]);
    const NormalForce fn = damped_normal_force(cc.f_el, cc.d_n, vn);
    const Vec3 s0 = project_spring({b.s0x[t], b.s0y[t], b.s0z[t]}, nrm);
    const Vec3 vt0{b.vt0x[t], b.vt0y[t], b.vt0z[t]};
    const TangentialResult ft = tangential_force(s0, dt * ((1.0 - phi) * vt0 + phi * vt), vt, cc.k_t, cc.d_t, mu_s,
                                                 mu_d, fn.magnitude, b.decide[t]);
    const Vec3 f = fn.magnitude * nrm + ft.force;
    const Vec3 arm = cross(rP, ft.force);
    b.fx[t] = f.x, b.fy[t] = f.y, b.fz[t] = f.z;
    b.tx[t] = arm.x, b.ty[t] = arm.y, b.tz[t] = arm.z;
    b.sx[t] = ft.spring.x, b.sy[t] = ft.spring.y, b.sz[t] = ft.spring.z;
    b.vtx[t] = vt.x, b.vty[t] = vt.y, b.vtz[t] = vt.z;
    b.fn[t] = fn.magnitude;
    b.energy[t] = hertz_energy_from_force(cc.f_el, b.overlap[t]) + 0.5 * cc.k_t * norm2(ft.spring);
    b.damping[t] = fn.dissipated_power + (ft.slipped ? 0.0 : ft.dissipated_power);
    b.friction[t] = ft.slipped ? ft.dissipated_power : 0.0;
    b.slip[t] = ft.slipped ? 1 : 0;
  }
}


}  // namespace mpdem
