#pragma once
// Clumps in test scenes: templates from member lists, bodies added as the scene reader adds them,
// and a floor.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "model/body_members.hpp"
#include "physics/clump_mass.hpp"
#include "scene/clump_reader.hpp"
#include "support/scene_builder.hpp"

namespace mpdem::test {

// Adds template `name` of `members` (template frame, m) to the scene; returns its index.
inline int add_template(Scene& s, const std::string& name, const std::vector<ClumpMember>& members) {
  ClumpTemplate t;
  t.name = name;
  t.shape = clump_mass_properties(members);
  s.model.clumps.push_back(t);
  return static_cast<int>(s.model.clumps.size()) - 1;
}

// Adds a body of template `clump` in the scene's first material.
inline void add_clump(Scene& s, std::int64_t id, int clump, const Vec3& x, const Vec3& v = {}, const Vec3& w = {},
                      const Quat& q = {}) {
  BodyInit init;
  init.id = id;
  init.x = x;
  init.v = v;
  init.w = w;
  init.q = q;
  init.T = s.model.materials.front().temperature;
  add_body(s.model, 0, clump, init, s.particles);
}

// Index of the member k of the body with id `body` in p.
inline std::size_t member_of(const Particles& p, std::int64_t body, std::uint32_t k) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == body && p.member[i] == k) return i;
  ADD_FAILURE() << "no member " << k << " of body " << body;
  return 0;
}

// Gives the members their ids (after the free spheres'), as a loaded scene has them.
inline void finish_clumps(Scene& s) { assign_member_ids(s.particles, "test"); }

// A square floor z = z0, half-width h (m), two triangles of the first material's E and nu.
inline void add_floor(Scene& s, double z0, double h) {
  const int g = s.barriers.group_index("floor");
  const Material& m = s.model.materials.front();
  s.barriers.add(1, {-h, -h, z0}, {h, -h, z0}, {h, h, z0}, g, m.young, m.poisson, {}, 0.0, NAN);
  s.barriers.add(2, {-h, -h, z0}, {h, h, z0}, {-h, h, z0}, g, m.young, m.poisson, {}, 0.0, NAN);
}

}  // namespace mpdem::test
