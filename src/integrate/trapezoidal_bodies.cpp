#include "integrate/trapezoidal_bodies.hpp"

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "model/body_members.hpp"
#include "physics/rigid_rotation.hpp"

namespace mpdem {

namespace {

// m^2, the body's reach squared: the rotational norms' unit (a sphere's is its radius).
double reach2(const Model& model, const Bodies& B, std::size_t b) {
  const double r = model.clumps[static_cast<std::size_t>(B.clump[b])].reach();
  return r * r;
}

}  // namespace

void TrapezoidalBodies::save_start(const Particles& p, const Model& model) {
  const Bodies& B = p.bodies;
  const std::size_t nb = B.size();
  x0_ = B.x;
  v0_ = B.v;
  w0_ = B.w;
  q0_ = B.q;
  T0_ = B.T;
  f0_ = B.force;
  tau0_ = B.torque;
  heat0_ = B.heat;
  L0_.resize(nb);
  a0_.resize(nb);
  h0_.resize(nb);
  r0_.resize(nb);
  free_ = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    L0_[b] = angular_momentum(B.q[b], B.inertia[b], B.w[b]);
    a0_[b] = B.fixed[b] ? Vec3{} : B.force[b] / B.mass[b];
    r0_[b] = spherical_body(B.inertia[b]) ? B.torque[b] / B.inertia[b].x : B.torque[b];
    free_ += B.fixed[b] ? 0 : 1;
    h0_[b] = B.heat[b] / (B.mass[b] * model.materials[static_cast<std::size_t>(B.material[b])].heat_capacity);
  }
  for (auto* a : {&xp_, &vp_, &wp_, &alphap_, &xpp_, &vpp_, &wpp_, &alphapp_, &alpha_}) a->assign(nb, Vec3{});
  Tp_.assign(nb, 0.0);
  Tpp_.assign(nb, 0.0);
}

void TrapezoidalBodies::update(Particles& p, const Model& model, double dt, bool predictor, Sums& sums) {
  Bodies& B = p.bodies;
  const double phi = model.params.time.phi, keep = 1.0 - phi;
  const bool rotation = model.params.analysis.rotation, thermal = model.params.analysis.thermal;
  // The previous iterates move back one place: y_(K-1) -> y_(K-2), the state's -> y_(K-1).
  xpp_.swap(xp_);
  vpp_.swap(vp_);
  wpp_.swap(wp_);
  alphapp_.swap(alphap_);
  Tpp_.swap(Tp_);
  xp_ = B.x;
  vp_ = B.v;
  wp_ = B.w;
  alphap_ = alpha_;
  Tp_ = B.T;
  // The predictor's extrapolation (with a history of as many bodies), as the spheres'.
  const bool history = predictor && dt_prev_ > 0.0 && a_prev_.size() == B.size();
  const double stretch = history ? dt / dt_prev_ : 0.0;
  for (std::size_t b = 0; b < B.size(); ++b) {
    const bool held = B.fixed[b] != 0;
    const Vec3 a0 = a0_[b], r0 = r0_[b];
    const Vec3 a1 = held ? a0 : !predictor ? B.force[b] / B.mass[b] : history ? a0 + stretch * (a0 - a_prev_[b]) : a0;
    const Vec3 r1 = !predictor ? B.torque[b] : history ? r0 + stretch * (r0 - r_prev_[b]) : r0;
    const Vec3 v = held ? v0_[b] : v0_[b] + dt * (keep * a0 + phi * a1);
    const Vec3 x = held ? x0_[b] + dt * v0_[b] : x0_[b] + dt * (keep * v0_[b] + phi * v);
    Vec3 w = w0_[b], alpha = dt * w0_[b];
    if (rotation && !held) {
      const Vec3 I = B.inertia[b];
      if (spherical_body(I)) {  // a sphere's update, operation for operation
        const Vec3 b1 = predictor ? r1 : r1 / I.x;
        w = w0_[b] + dt * (keep * r0 + phi * b1);
      } else {
        const Vec3 L = L0_[b] + dt * (keep * r0 + phi * r1);
        w = angular_velocity(predictor ? q0_[b] : B.q[b], I, L);
      }
      alpha = dt * (keep * w0_[b] + phi * w);
    }
    double T = T0_[b];
    if (thermal) {
      const double h1 = predictor
                            ? h0_[b]
                            : B.heat[b] /
                                  (B.mass[b] * model.materials[static_cast<std::size_t>(B.material[b])].heat_capacity);
      T = T0_[b] + dt * (keep * h0_[b] + phi * h1);
    }
    if (!predictor) {
      const auto add = [&](int field, const auto& y, const auto& yp, const auto& y0, const auto& ypp, double mag2,
                           bool counted) {
        if (!counted) return;
        const auto d2 = [](const auto& a, const auto& c) {
          if constexpr (std::is_same_v<std::decay_t<decltype(a)>, double>) return (a - c) * (a - c);
          else return norm2(a - c);
        };
        sums[4 * field] += d2(y, yp);
        sums[4 * field + 1] += d2(y, y0);
        sums[4 * field + 2] += d2(y, ypp);
        sums[4 * field + 3] += mag2;
      };
      add(kPosition, x, xp_[b], x0_[b], xpp_[b], norm2(x), !held);
      add(kVelocity, v, vp_[b], v0_[b], vpp_[b], norm2(v), !held);
      if (rotation) {
        const double inv_r2 = 1.0 / reach2(model, B, b);
        add(kRotation, alpha, alphap_[b], Vec3{}, alphapp_[b], norm2(alpha) + norm2(x - x0_[b]) * inv_r2, !held);
        add(kAngularVelocity, w, wp_[b], w0_[b], wpp_[b], norm2(w) + norm2(v) * inv_r2, !held);
      }
      if (thermal) add(kTemperature, T, Tp_[b], T0_[b], Tpp_[b], T * T, true);
    }
    B.x[b] = x;
    B.v[b] = v;
    B.w[b] = w;
    B.q[b] = rotation ? rotate_by_increment(q0_[b], alpha) : q0_[b];
    B.T[b] = T;
    alpha_[b] = alpha;
  }
  place_members(model.clumps, p);
}

void TrapezoidalBodies::compact(const std::vector<char>& keep) {
  for (std::vector<Vec3>* a : {&a_prev_, &r_prev_}) {
    if (a->size() != keep.size()) continue;  // no history of these bodies
    std::size_t k = 0;
    for (std::size_t b = 0; b < a->size(); ++b)
      if (keep[b]) (*a)[k++] = (*a)[b];
    a->resize(k);
  }
}

void TrapezoidalBodies::save(BinaryWriter& w) const {
  w.value(dt_prev_);
  w.vector(a_prev_);
  w.vector(r_prev_);
}

void TrapezoidalBodies::save(BinaryWriter& w, double dt_prev, const std::vector<RateRecord>& records) {
  std::vector<Vec3> a, r;
  for (const RateRecord& k : records) {
    a.push_back(k.a);
    r.push_back(k.b);
  }
  w.value(dt_prev);
  w.vector(a);
  w.vector(r);
}

void TrapezoidalBodies::restore(BinaryReader& r, std::span<const std::int64_t> ids, const Bodies& B) {
  const auto dt = r.value<double>();
  const auto a = r.vector<Vec3>();
  const auto rr = r.vector<Vec3>();
  if (!std::isfinite(dt) || dt < 0.0 || (dt > 0.0 && (a.size() > ids.size() || rr.size() != a.size())))
    throw std::runtime_error("the bodies' rate history does not match the scene's bodies");
  // A history of fewer bodies than there are (an inlet added some since) is not used (update()),
  // as in the run that wrote it.
  std::vector<RateRecord> records;
  if (dt > 0.0 && a.size() == ids.size())
    for (std::size_t k = 0; k < ids.size(); ++k) records.push_back({ids[k], a[k], rr[k]});
  set_records(records, B, dt);
}

std::vector<RateRecord> TrapezoidalBodies::records(const Bodies& B) const {
  std::vector<RateRecord> out;
  if (dt_prev_ > 0.0 && a_prev_.size() == B.size())
    for (std::size_t b = 0; b < B.size(); ++b) out.push_back({B.id[b], a_prev_[b], r_prev_[b]});
  return out;
}

void TrapezoidalBodies::set_records(std::span<const RateRecord> records, const Bodies& B, double dt) {
  dt_prev_ = dt;
  a_prev_.clear();
  r_prev_.clear();
  if (!(dt > 0.0)) return;
  std::unordered_map<std::int64_t, const RateRecord*> by_id;
  for (const RateRecord& k : records) by_id.emplace(k.id, &k);
  a_prev_.resize(B.size());
  r_prev_.resize(B.size());
  for (std::size_t b = 0; b < B.size(); ++b) {
    const auto it = by_id.find(B.id[b]);
    if (it == by_id.end()) {  // no history: the predictor then uses the start rates of all bodies
      a_prev_.clear();
      r_prev_.clear();
      return;
    }
    a_prev_[b] = it->second->a;
    r_prev_[b] = it->second->b;
  }
}

void TrapezoidalBodies::accept_midpoint(Particles& p, const Model& model) {
  Bodies& B = p.bodies;
  for (std::size_t b = 0; b < B.size(); ++b) {
    B.x[b] = 0.5 * (B.x[b] + xp_[b]);
    B.v[b] = 0.5 * (B.v[b] + vp_[b]);
    B.w[b] = 0.5 * (B.w[b] + wp_[b]);
    B.T[b] = 0.5 * (B.T[b] + Tp_[b]);
    alpha_[b] = 0.5 * (alpha_[b] + alphap_[b]);
    if (model.params.analysis.rotation) B.q[b] = rotate_by_increment(q0_[b], alpha_[b]);
  }
  place_members(model.clumps, p);
}

void TrapezoidalBodies::restore_start(Particles& p, const Model& model) const {
  Bodies& B = p.bodies;
  B.x = x0_;
  B.v = v0_;
  B.w = w0_;
  B.q = q0_;
  B.T = T0_;
  B.force = f0_;
  B.torque = tau0_;
  B.heat = heat0_;
  place_members(model.clumps, p);
}

}  // namespace mpdem
