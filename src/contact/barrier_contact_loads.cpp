// What BarrierContacts report of their last evaluation: each element's load (force, moment about
// its centre, pressure) from the loads its contacts hold, and the deepest contact.
#include "contact/barrier_contacts.hpp"

namespace mpdem {

double element_pressure(const Barriers& b, std::size_t e) { return -dot(b.force[e], b.current_normal(e)) / b.area[e]; }

void BarrierContacts::element_loads(Barriers& b, std::size_t e) {
  std::size_t users = 0;
  const std::uint32_t* user = store_.element_users(e, users);
  if (users > 0) {
    const auto el = static_cast<std::int32_t>(e);
    const Vec3& centre = centres_[e];
    Vec3 force = b.force[e], moment = b.moment[e];
    for (std::size_t u = 0; u < users; ++u) {
      const BarrierLoad* l = store_.loads(user[u]);
      const std::size_t used = store_.load_used(user[u]);
      for (std::size_t c = 0; c < used; ++c)
        if (l[c].element == el) {
          force += l[c].force;
          moment += cross(l[c].point - centre, l[c].force);
          break;
        }
    }
    b.force[e] = force;
    b.moment[e] = moment;
  }
  b.pressure[e] = element_pressure(b, e);
}

OverlapReport BarrierContacts::max_overlap(const Particles& p, const Barriers& b) const {
  OverlapReport r;
  for (std::size_t k = 0; k < store_.size(); ++k) {
    const std::size_t i = store_.particle(k);
    if (i >= p.size()) continue;
    const BarrierLoad* l = store_.loads(k);
    for (std::size_t c = 0; c < store_.load_used(k); ++c) {
      const double ratio = l[c].overlap / p.radius[i];
      if (ratio > r.ratio) r = {ratio, p.id[i], -1, b.id[static_cast<std::size_t>(l[c].element)]};
    }
  }
  return r;
}

}  // namespace mpdem
