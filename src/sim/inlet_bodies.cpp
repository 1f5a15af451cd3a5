#include "sim/inlet_bodies.hpp"

#include "generate/generated_bodies.hpp"

namespace mpdem {

namespace {
// The rotation of a body's members from its principal frame, as add_body (model/body_members.hpp)
// places them: principal frame -> world is q * to_input.
Mat3 member_rotation(const ClumpTemplate& t, const Quat& q) {
  return quat_matrix(quat_normalized(quat_multiply(q, t.shape.to_input)));
}
}  // namespace

bool place_body(const ClumpTemplate& t, const InsertionVolume& vol, const Region& region, const InsertionSpace& space,
                Rng& rng, std::size_t attempts, BodyPlace& out) {
  for (std::size_t a = 0; a < attempts; ++a) {
    Vec3 local;  // m, the centre in the volume's frame
    if (!region.sample(rng, 0.0, local)) continue;
    const Quat q = uniform_rotation(rng);
    const Mat3 R = member_rotation(t, q);
    const Vec3 x = vol.origin + vol.u * local.x + vol.v * local.y + vol.w * local.z;  // m, world
    bool ok = true;
    for (std::size_t k = 0; k < t.members().size() && ok; ++k) {
      const ClumpMember& m = t.members()[k];
      const Vec3 d = mat_apply(R, m.x);  // m, world offset of the member
      const Vec3 in_frame = local + Vec3{dot(vol.u, d), dot(vol.v, d), dot(vol.w, d)};
      ok = region.holds(in_frame, m.r) && space.free(x + d, m.r);
    }
    if (!ok) continue;
    out = {x, q};
    return true;
  }
  return false;
}

}  // namespace mpdem
