#include "output/barrier_load_means.hpp"

#include <stdexcept>

namespace mpdem {

BarrierLoads current_loads(const Barriers& b) {
  const std::size_t m = b.size();
  BarrierLoads l{b.force, b.moment, b.pressure, std::vector<double>(m, 0.0), std::vector<double>(m, 0.0)};
  if (b.rotating())
    for (std::size_t e = 0; e < m; ++e) {
      l.axis_torque[e] = b.axis_torque(e);
      l.drive_power[e] = b.drive_power(e);
    }
  return l;
}

void BarrierLoadMeans::add(const Barriers& b, double h) {
  const std::size_t m = b.size();
  if (sum_.force.size() != m) {
    if (span_ > 0.0) throw std::logic_error("barrier load means: the number of elements changed");
    sum_ = {std::vector<Vec3>(m), std::vector<Vec3>(m), std::vector<double>(m, 0.0), std::vector<double>(m, 0.0),
            std::vector<double>(m, 0.0)};
  }
  const bool turns = b.rotating();
  for (std::size_t e = 0; e < m; ++e) {
    sum_.force[e] += b.force[e] * h;
    sum_.moment[e] += b.moment[e] * h;
    sum_.pressure[e] += b.pressure[e] * h;
    if (turns) {
      sum_.axis_torque[e] += b.axis_torque(e) * h;
      sum_.drive_power[e] += b.drive_power(e) * h;
    }
  }
  span_ += h;
}

BarrierLoads BarrierLoadMeans::mean(const Barriers& b) const {
  if (!(span_ > 0.0)) return current_loads(b);
  BarrierLoads l = sum_;
  const double inv = 1.0 / span_;
  for (std::size_t e = 0; e < l.force.size(); ++e) {
    l.force[e] *= inv;
    l.moment[e] *= inv;
    l.pressure[e] *= inv;
    l.axis_torque[e] *= inv;
    l.drive_power[e] *= inv;
  }
  return l;
}

void BarrierLoadMeans::clear() {
  span_ = 0.0;
  sum_ = {};
}

void BarrierLoadMeans::save(BinaryWriter& w) const {
  w.value(span_);
  w.vector(sum_.force);
  w.vector(sum_.moment);
  w.vector(sum_.pressure);
  w.vector(sum_.axis_torque);
  w.vector(sum_.drive_power);
}

void BarrierLoadMeans::restore(BinaryReader& r) {
  span_ = r.value<double>();
  sum_.force = r.vector<Vec3>();
  sum_.moment = r.vector<Vec3>();
  sum_.pressure = r.vector<double>();
  sum_.axis_torque = r.vector<double>();
  sum_.drive_power = r.vector<double>();
}

}  // namespace mpdem
