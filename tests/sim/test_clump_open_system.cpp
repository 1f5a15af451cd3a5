// Clumps in an open periodic system: an [[inlet]] of tetrahedra and dumbbells feeds a box periodic
// along x and y, the bodies drift across the faces, land on a floor, and a [[sink]] over half the
// floor takes those whose centre enters it. Inlets add bodies, sinks remove them and the wrap moves
// them, all in the same run (sim/inlets.cpp, sim/sinks.cpp, parallel/periodic_images.cpp). Checked:
// the mass inserted is the mass present plus the mass removed (1e-12 relative), every member sits
// on its body's rigid placement (1e-12 m), bodies crossed the faces and were removed, and a
// checkpoint cut mid-run resumes bitwise under both integrators.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/rotation.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"
#include "sim/sinks.hpp"
#include "support/clump_scenes.hpp"
#include "support/open_system_scenes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kR = 1e-3;   // m, member radius
constexpr double kL = 0.02;   // m, the periods along x and y
constexpr int kSteps = 2500;  // dt = 2e-5 s: 0.05 s

// fed_box_scene's contacts, material and gravity; its walls give way to a floor and the periodic
// faces, its inlet to one of bodies.
Scene open_periodic(Integrator integ) {
  Scene s = fed_box_scene(kSteps * 2e-5, 0.05);
  s.barriers = Barriers{};
  Params& prm = s.model.params;
  prm.time.integrator = integ;
  prm.time.phi = 0.5;
  DomainParams& d = prm.domain;
  d.bounded = true;
  d.min = {0.0, 0.0, -0.01};
  d.max = {kL, kL, 0.03};
  d.periodic = {true, true, false};
  // The floor z = 0 spans the period exactly.
  const int g = s.barriers.group_index("floor");
  const Material& m = s.model.materials.front();
  s.barriers.add(1, {0, 0, 0}, {kL, 0, 0}, {kL, kL, 0}, g, m.young, m.poisson, {}, 0.0, NAN);
  s.barriers.add(2, {0, 0, 0}, {kL, kL, 0}, {0, kL, 0}, g, m.young, m.poisson, {}, 0.0, NAN);
  const double a = 0.7 * kR;
  const int tet = add_template(s, "tetra", {{{a, a, a}, kR}, {{a, -a, -a}, kR}, {{-a, a, -a}, kR}, {{-a, -a, a}, kR}});
  const int db = add_template(s, "dumbbell", {{{0, 0, -kR}, kR}, {{0, 0, kR}, 0.8 * kR}});
  InletSpec& in = prm.inlets.front();
  in.volume.region.min = {0.003, 0.003, 0.008};
  in.volume.region.max = {0.017, 0.017, 0.018};
  in.clump.clumps = {tet, db};
  in.clump.fractions = {0.6, 0.4};
  in.radius.law = RadiusLaw::Discrete;  // the members' radii, as the scene reader sets them
  in.radius.radii = {0.8 * kR, kR};
  in.radius.fractions = {1.0, 1.0};
  in.velocity = {0.4, 0.25, -0.4};  // across the periodic faces while falling
  in.seed = 5;
  SinkSpec sink;
  sink.name = "half";
  sink.region.min = {0.0, 0.0, -0.01};  // the floor's lower half in x, up to where a landed centre sits
  sink.region.max = {0.5 * kL, kL, 0.004};
  prm.sinks.push_back(sink);
  return s;
}

void run_steps(Simulation& sim, std::uint64_t steps) {
  while (sim.steps() < steps) sim.advance(sim.model().params.time.dt);
}

double present_mass(const Bodies& B) {
  double m = 0.0;  // kg
  for (std::size_t b = 0; b < B.size(); ++b) m += B.mass[b];
  return m;
}

}  // namespace

TEST(ClumpOpenSystem, InletSinkAndPeriodicFacesKeepMassAndShape) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    Simulation sim(open_periodic(integ), RunOptions{{}, false, false});
    int crossed = 0;  // body-steps with a nonzero image count
    for (int k = 0; k < kSteps; ++k) {
      sim.advance(sim.model().params.time.dt);
      const Bodies& B = sim.particles().bodies;
      for (std::size_t b = 0; b < B.size(); ++b) crossed += (B.image[b][0] != 0 || B.image[b][1] != 0) ? 1 : 0;
    }
    const Particles& p = sim.particles();
    const Bodies& B = p.bodies;
    const double inserted = sim.inlets()->states()[0].inserted_mass;
    const double removed = sim.sinks()->states()[0].removed_mass;
    std::printf("%zu bodies present, inserted %.6e kg, removed %.6e kg, %d body-steps across a face\n", B.size(),
                inserted, removed, crossed);
    ASSERT_GT(B.size(), 10u);
    EXPECT_GT(removed, 0.0);
    EXPECT_GT(crossed, 0);
    EXPECT_NEAR(present_mass(B) + removed, inserted, 1e-12 * inserted);
    // Every member on its body's rigid placement, and every member's body present.
    const Model& model = sim.model();
    for (std::size_t i = 0; i < p.size(); ++i) {
      ASSERT_GE(p.body[i], 0) << "the scene holds bodies only";
      const std::ptrdiff_t found = B.find(p.body[i]);
      ASSERT_GE(found, 0) << "member " << p.id[i] << " of a removed body";
      const auto b = static_cast<std::size_t>(found);
      const ClumpTemplate& t = model.clumps[static_cast<std::size_t>(B.clump[b])];
      const Vec3 want = B.x[b] + mat_apply(quat_matrix(B.q[b]), t.members()[p.member[i]].x);
      EXPECT_LT(norm(p.x[i] - want), 1e-12) << "member " << p.id[i];
    }
  }
}

TEST(ClumpOpenSystem, ResumeIsBitwise) {
  TempDir dir("mpdem_clump_open_system");
  constexpr std::uint64_t kCut = 1100, kTotal = 1800;
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    Simulation whole(open_periodic(integ), RunOptions{{}, false, false});
    run_steps(whole, kTotal);
    {
      Simulation first(open_periodic(integ), RunOptions{{}, false, false});
      run_steps(first, kCut);
      ASSERT_GT(first.sinks()->states()[0].removed_mass, 0.0) << "a removal before the cut";
      first.write_checkpoint(dir.path / "ck.bin");
    }
    Simulation resumed(open_periodic(integ), RunOptions{{}, false, false});
    resumed.resume_from(dir.path / "ck.bin");
    run_steps(resumed, kTotal);
    expect_same_run(whole.particles(), resumed.particles());
    EXPECT_EQ(whole.sinks()->states()[0].removed_mass, resumed.sinks()->states()[0].removed_mass);
    EXPECT_EQ(whole.inlets()->states()[0].inserted_mass, resumed.inlets()->states()[0].inserted_mass);
  }
}
