// HertzLine: RK4 reference for elastic Hertz contacts on a line (see hertz_line.hpp).
#include "validate/hertz_line.hpp"

#include <cmath>
#include <stdexcept>

#include "physics/barrier_moduli.hpp"
#include "physics/hertz.hpp"

namespace mpdem::validate {


HertzLine::HertzLine(std::vector<LineSphere> spheres, std::optional<LineWall> wall, double max_step)
    : s_(std::move(spheres)), wall_(wall), max_step_(max_step) {
  if (s_.empty() || !(max_step_ > 0.0)) throw std::invalid_argument("HertzLine: no spheres or step <= 0");
  for (std::size_t k = 0; k + 1 < s_.size(); ++k) {
    const LineSphere &a = s_[k], &b = s_[k + 1];
    const double r_star = a.radius * b.radius / (a.radius + b.radius);  // (52)
    k_pair_.push_back(4.0 / 3.0 * effective_modulus(a.young, a.poisson, b.young, b.poisson) * std::sqrt(r_star));
  }
  if (wall_)
    k_wall_ = 4.0 / 3.0 * barrier_effective_modulus(s_[0].young, s_[0].poisson, wall_->young, wall_->poisson) *
              std::sqrt(s_[0].radius);
}

double HertzLine::overlap(std::size_t k) const { return s_[k].radius + s_[k + 1].radius - (s_[k + 1].x - s_[k].x); }

void HertzLine::accelerations(const std::vector<double>& x, std::vector<double>& a) const {
  const std::size_t n = s_.size();
  std::vector<double> f(n, 0.0);  // N
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double d = s_[k].radius + s_[k + 1].radius - (x[k + 1] - x[k]);
    if (d <= 0.0) continue;
    const double F = k_pair_[k] * d * std::sqrt(d);
    f[k] -= F;
    f[k + 1] += F;
  }
  if (wall_) {
    const double d = s_[0].radius - (x[0] - wall_->x);
    if (d > 0.0) f[0] += k_wall_ * d * std::sqrt(d);
  }
  for (std::size_t i = 0; i < n; ++i) a[i] = f[i] / s_[i].mass;
}

void HertzLine::rk4(double h) {
  const std::size_t n = s_.size();
  std::vector<double> x0(n), v0(n), x(n), a1(n), a2(n), a3(n), a4(n), v1(n), v2(n), v3(n), v4(n);
  for (std::size_t i = 0; i < n; ++i) {
    x0[i] = s_[i].x;
    v0[i] = s_[i].v;
  }
  v1 = v0;
  accelerations(x0, a1);
  for (std::size_t i = 0; i < n; ++i) {
    v2[i] = v0[i] + 0.5 * h * a1[i];
    x[i] = x0[i] + 0.5 * h * v1[i];
  }
  accelerations(x, a2);
  for (std::size_t i = 0; i < n; ++i) {
    v3[i] = v0[i] + 0.5 * h * a2[i];
    x[i] = x0[i] + 0.5 * h * v2[i];
  }
  accelerations(x, a3);
  for (std::size_t i = 0; i < n; ++i) {
    v4[i] = v0[i] + h * a3[i];
    x[i] = x0[i] + h * v3[i];
  }
  accelerations(x, a4);
  for (std::size_t i = 0; i < n; ++i) {
    s_[i].x = x0[i] + h / 6.0 * (v1[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
    s_[i].v = v0[i] + h / 6.0 * (a1[i] + 2.0 * a2[i] + 2.0 * a3[i] + a4[i]);
  }
  t_ += h;
}

void HertzLine::advance_to(double t) {
  if (t <= t_) return;
  const auto steps = static_cast<long>(std::ceil((t - t_) / max_step_ - 1e-9));
  const double h = (t - t_) / static_cast<double>(steps);
  for (long k = 0; k < steps; ++k) rk4(h);
  t_ = t;
}

}  // namespace mpdem::validate
