#pragma once
// External field forces on one particle (physics.md section 3, thesis (39)-(43)).
#include "core/vec3.hpp"

namespace mpdem {

inline Vec3 gravity_force(double mass, const Vec3& g) { return mass * g; }                                // (40)
inline Vec3 electric_force(double charge, const Vec3& E) { return charge * E; }                           // (42)
inline Vec3 magnetic_force(double charge, const Vec3& v, const Vec3& B) { return charge * cross(v, B); }  // (43)
inline Vec3 drag_force(double c, const Vec3& v) { return -c * v; }  // viscous drag, c in N s/m

}  // namespace mpdem
