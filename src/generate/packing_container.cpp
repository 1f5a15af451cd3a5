// Containers of dense packings (docs/tools.md "mpdem agglomerate").
#include "generate/packing_container.hpp"

#include <cmath>
#include <numbers>

namespace mpdem {

PackingContainer::PackingContainer(const Vec3& centre, double radius)
    : centre_(centre), radius_(radius), volume_(4.0 / 3.0 * std::numbers::pi * radius * radius * radius),
      lo_(centre - Vec3{radius, radius, radius}), hi_(centre + Vec3{radius, radius, radius}) {}

PackingContainer::PackingContainer(std::shared_ptr<const MeshSolid> solid)
    : solid_(std::move(solid)), volume_(solid_->volume()), lo_(solid_->lo()), hi_(solid_->hi()) {}

bool PackingContainer::sample(Rng& rng, double c, Vec3& out) const {
  if (!solid_) {  // uniform in the ball of radius R - c by rejection from its cube (52 % accepted)
    const double rc = radius_ - c;
    if (!(rc > 0.0)) return false;
    Vec3 d;
    do {
      d = {rng.uniform(-rc, rc), rng.uniform(-rc, rc), rng.uniform(-rc, rc)};
    } while (norm2(d) > rc * rc);
    out = centre_ + d;
    return true;
  }
  out = {rng.uniform(lo_.x + c, hi_.x - c), rng.uniform(lo_.y + c, hi_.y - c), rng.uniform(lo_.z + c, hi_.z - c)};
  return solid_->contains(out) && solid_->clear_of_surface(out, c);
}

double PackingContainer::depth(const Vec3& p) const {
  if (!solid_) return radius_ - norm(p - centre_);
  const double d = solid_->distance_to_surface(p);
  return solid_->contains(p) ? d : -d;
}

double PackingContainer::push_inside(Vec3& p, double r) const {
  if (!solid_) {
    const Vec3 d = p - centre_;
    const double l = norm(d);
    if (l + r <= radius_) return 0.0;
    p = centre_ + d * ((radius_ - r) / l);
    return l + r - radius_;
  }
  const Vec3 q = solid_->closest_surface_point(p);
  const double l = norm(p - q);
  const bool inside = solid_->contains(p);
  if (inside && l >= r) return 0.0;
  // Inward normal at q: from q towards p when p is inside, away from p when outside. A centre on
  // the surface itself has no normal: it heads for the middle of the bounding box instead.
  Vec3 n = inside ? p - q : q - p;
  if (l == 0.0) n = (lo_ + hi_) * 0.5 - p;
  const double ln = norm(n);
  if (ln > 0.0) p = q + n * (r / ln);
  return inside ? r - l : r + l;
}

}  // namespace mpdem
