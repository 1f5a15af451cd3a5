// The motion of a [[barriers]] entry (docs/scene.md "[[barriers]]"): the translation law, the
// rotation, the activity window and the law's time origin.
#include "scene/barrier_motion_reader.hpp"

#include <cmath>
#include <string>

namespace mpdem {

namespace {

// [[barriers]] motion.rotation: a unit axis, its point, and a constant or tabulated rate.
RotationLaw read_rotation(const TomlSection& r) {
  RotationLaw law;
  const Vec3 axis = r.require(r.vec3("axis"), "axis");
  const double len = norm(axis);
  if (!(len > 0.0) || !std::isfinite(len))
    r.fail("axis", "expected a non-zero axis direction [x, y, z] of finite length, got " + number_text(axis.x) + ", " +
                       number_text(axis.y) + ", " + number_text(axis.z));
  law.axis = axis / len;
  r.get("origin", law.origin);
  if (r.has("omega") && r.has("omega_table")) r.fail("omega_table", "give either omega or omega_table, not both");
  if (!r.has("omega") && !r.has("omega_table")) r.fail("omega", "missing required key (give omega or omega_table)");
  r.get("omega", law.omega);
  if (const auto tab = r.number_pairs("omega_table")) {
    for (std::size_t j = 1; j < tab->size(); ++j)
      if (!((*tab)[j][0] > (*tab)[j - 1][0]))
        r.fail("omega_table",
               "expected rows [t, omega] with strictly ascending times t, got t = " + number_text((*tab)[j][0]) +
                   " s in row " + std::to_string(j + 1) + " after t = " + number_text((*tab)[j - 1][0]) + " s");
    law.omega_table = *tab;
  }
  return law;
}

// [[barriers]] active = [t_start] or [t_start, t_end] and motion_from, into the source's law.
void read_activity(const TomlSection& s, MotionLaw& law) {
  if (const auto w = s.numbers("active", 1, 2)) {
    const double from = (*w)[0];
    if (!(from >= 0.0))
      s.fail("active",
             "expected [t_start] or [t_start, t_end] with t_start >= 0 (s), got t_start = " + number_text(from));
    law.active_from = from;
    if (w->size() == 2) {
      const double until = (*w)[1];
      if (!(until > from))
        s.fail("active", "expected [t_start, t_end] with t_start < t_end (s), got t_start = " + number_text(from) +
                             ", t_end = " + number_text(until));
      law.active_until = until;
    }
  }
  if (const auto f = s.string("motion_from")) {
    if (*f == "start") {
      law.since = law.active_from;  // 0 without `active`: the same as "zero"
      if (law.rotation) law.rotation->since = law.since;
    } else if (*f != "zero") {
      const std::string want = "expected \"zero\" (the motion law runs on t) or \"start\" (on t - t_start)";
      s.fail("motion_from", want + ", got \"" + *f + "\"");
    }
  }
}

}  // namespace

MotionLaw read_barrier_motion(const TomlSection& s, double duration) {
  MotionLaw law;
  if (const auto m = s.table("motion", {"a", "A", "w1", "B", "w2", "rotation"})) {
    m->get("a", law.a);
    m->get("A", law.A);
    m->get("w1", law.w1);
    m->get("B", law.B);
    m->get("w2", law.w2);
    const auto r = m->table("rotation", {"axis", "origin", "omega", "omega_table"});
    if (r) law.rotation = read_rotation(*r);
    std::string key;
    if (const std::string why = law.limit_problem(duration, key); !why.empty()) {
      if (key == "omega") r->fail(r->has("omega") ? "omega" : "omega_table", why);
      m->fail(key, why);
    }
  }
  read_activity(s, law);
  return law;
}

}  // namespace mpdem
