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

// The bodies of two runs bitwise alike: ids, templates and state (image counts included).
inline void expect_same_bodies(const Bodies& a, const Bodies& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a.id[k], b.id[k]);
    EXPECT_EQ(a.clump[k], b.clump[k]);
    EXPECT_EQ(a.x[k], b.x[k]);
    EXPECT_EQ(a.image[k], b.image[k]);
    EXPECT_EQ(a.v[k], b.v[k]);
    EXPECT_EQ(a.w[k], b.w[k]);
    EXPECT_TRUE(a.q[k].w == b.q[k].w && a.q[k].x == b.q[k].x && a.q[k].y == b.q[k].y && a.q[k].z == b.q[k].z);
  }
}

// The particles (ids, centres, velocities, spins) and bodies of two runs bitwise alike: a resumed
// run against the uninterrupted one.
inline void expect_same_run(const Particles& p, const Particles& q) {
  ASSERT_EQ(p.size(), q.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p.id[i], q.id[i]);
    EXPECT_EQ(p.x[i], q.x[i]);
    EXPECT_EQ(p.v[i], q.v[i]);
    EXPECT_EQ(p.w[i], q.w[i]);
  }
  expect_same_bodies(p.bodies, q.bodies);
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
