#pragma once
// A clump template ([[clump]] in the scene, docs/scene.md "Clumps"): the member spheres of a rigid
// body, re-expressed in the body's principal frame about its centre of mass, and the union's mass
// properties per unit density (physics/clump_mass.hpp). A body of the template made of a material
// of density rho has mass rho V and principal moments rho J, unless the template overrides them.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "physics/clump_mass.hpp"

namespace mpdem {

struct ClumpTemplate {
  std::string name;
  ClumpMassProperties shape;    // per unit density; shape.members_principal: the members as used
  std::optional<double> mass;   // kg, the scene's override of rho V
  std::optional<Vec3> inertia;  // kg m^2, the scene's override of the principal moments (I1, I2, I3)
  std::string origin;           // the file that defines it, and its line, for messages
  std::size_t line = 0;

  const std::vector<ClumpMember>& members() const { return shape.members_principal; }
  // kg, a body's mass for a material of density rho (kg/m^3).
  double body_mass(double rho) const { return mass ? *mass : rho * shape.volume; }
  // kg m^2, its principal moments: the override, or the union's scaled to the body's mass (an
  // overridden mass scales the moments with it: the shape's mass distribution is kept).
  Vec3 body_inertia(double rho) const {
    if (inertia) return *inertia;
    return (body_mass(rho) / shape.volume) * shape.principal;
  }
  // -, member k's share of the body (mass, charge, coarse-grained fields): its volume over the
  // sum of the members' volumes.
  double share(std::size_t k) const {
    double sum = 0.0;
    for (const ClumpMember& m : members()) sum += m.r * m.r * m.r;
    const double r = members()[k].r;
    return r * r * r / sum;
  }
  // m, the largest distance of a member's surface from the centre of mass.
  double reach() const {
    double r = 0.0;
    for (const ClumpMember& m : members()) r = std::max(r, norm(m.x) + m.r);
    return r;
  }
  // m, the largest distance of a member's centre from the centre of mass.
  double member_offset() const {
    double r = 0.0;
    for (const ClumpMember& m : members()) r = std::max(r, norm(m.x));
    return r;
  }
};

// m, the largest member_offset() of the templates (0 without any): how far outside a periodic
// domain's period a member may lie when its body's centre is inside (parallel/periodic_images.hpp).
inline double largest_member_offset(const std::vector<ClumpTemplate>& clumps) {
  double r = 0.0;
  for (const ClumpTemplate& t : clumps) r = std::max(r, t.member_offset());
  return r;
}

}  // namespace mpdem
