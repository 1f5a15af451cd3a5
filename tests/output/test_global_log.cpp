// The global log's columns (output/global_log.hpp): a scene without cohesion (no law with
// hysteresis, no liquid bridge; DMT's adhesion keeps no state) logs none of the cohesion columns
// (bridges, breaks, ruptures, cohesion_dissipated), so its log.csv keeps its layout.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "contact/cohesion_reach.hpp"
#include "output/global_log.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;

TEST(GlobalLog, ScenesWithoutCohesionKeepTheirColumns) {
  const std::vector<std::string> plain{"step",
                                       "time",
                                       "dt",
                                       "iterations",
                                       "evaluations",
                                       "evaluations_total",
                                       "redone_steps",
                                       "particles",
                                       "removed",
                                       "contacts_pp",
                                       "contacts_pb",
                                       "kinetic",
                                       "rotational",
                                       "potential",
                                       "elastic",
                                       "damping_dissipated",
                                       "friction_dissipated",
                                       "total_energy"};  // docs/output.md "log.csv"
  for (const char* cohesion : {"none", "dmt"}) {
    Scene s = make_scene(1e-6, 1e-3);
    add_particle(s, 1, 1e-3, {});
    s.model.params.contact.particle_particle.cohesion = cohesion;
    s.model.params.contact.particle_barrier.cohesion = cohesion;
    EXPECT_FALSE(has_cohesion(s.model)) << cohesion;
    EXPECT_EQ(GlobalLogLayout(s.model, s.barriers, {}).columns(), plain) << cohesion;
  }
}
