// The rebuild rule with rotating barriers (Interactions::barrier_reach, BarrierBroadphase): it
// must follow the fastest point of every element, so that an impeller tip moving a large part of
// the skin per step never misses a contact: the run gives bitwise the trajectory of a run that
// rebuilds the lists before every step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/rotating_meshes.hpp"
#include "support/run_command.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kPi, base_scene

namespace {

constexpr double kSkin = 1e-4;   // m
constexpr double kTip = 0.1;     // m, blade tip radius
constexpr double kDt = 1e-5;     // s
const double kTurn = 0.5 * kPi;  // rad, a quarter turn: every blade sweeps its sector

// Four blades about z, turning so that the tip moves `per_step` skins per step, and eight spheres
// at rest between them (none touching another).
Scene impeller(double per_step) {
  Scene s = base_scene(Integrator::Verlet, kDt, {0.0, 0.0, 0.0});
  s.model.params.neighbor.skin = kSkin;
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.5;
  c.mu_static = 0.4;
  c.mu_dynamic = 0.3;
  const MotionLaw law = spin_about_z(per_step * kSkin / (kTip * kDt));
  for (int k = 0; k < 4; ++k) add_paddle(s.barriers, "impeller", 0.5 * kPi * k, 0.005, kTip, -0.01, 0.01, kE, kNu, law);
  for (int k = 0; k < 8; ++k) {
    const double phi = 0.25 * kPi * k + 0.3, r = 0.03 + 0.008 * k;  // rad, m
    add_particle(s, k + 1, kR, {r * std::cos(phi), r * std::sin(phi), 0.002 * (k % 3 - 1)});
  }
  return s;
}

struct Run {
  std::map<std::int64_t, std::pair<Vec3, Vec3>> state;  // id -> (x m, v m/s)
  std::uint64_t rebuilds = 0;
  std::size_t steps = 0;
  double fastest = 0.0;  // m/s, fastest sphere at the end
};

Run run(double per_step, bool rebuild_every_step) {
  Simulation sim(impeller(per_step), RunOptions{{}, false, false});
  const double omega = sim.barriers().rotations[0].omega;
  Run out;
  while (omega * sim.time() < kTurn) {
    if (rebuild_every_step) sim.interactions().force_rebuild(sim.particles(), sim.barriers(), true);
    sim.advance(kDt);
    ++out.steps;
  }
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    out.state[p.id[i]] = {p.x[i], p.v[i]};
    out.fastest = std::max(out.fastest, norm(p.v[i]));
  }
  out.rebuilds = sim.interactions().stats().rebuilds;
  return out;
}

void expect_same_trajectory(double per_step) {
  const Run ruled = run(per_step, false), every = run(per_step, true);
  std::printf("tip %.2f skin/step: %zu steps, rebuilds %llu (every step: %llu), fastest sphere %.3f m/s\n", per_step,
              ruled.steps, static_cast<unsigned long long>(ruled.rebuilds),
              static_cast<unsigned long long>(every.rebuilds), ruled.fastest);
  ASSERT_GT(every.fastest, 0.1 * per_step * kSkin / kDt) << "the blades must hit the spheres";
  for (const auto& [id, xv] : every.state) {
    const auto& [x, v] = ruled.state.at(id);
    EXPECT_EQ(x, xv.first) << "id " << id;
    EXPECT_EQ(v, xv.second) << "id " << id;
  }
}

}  // namespace

// Tip at 0.5 skin per step: the allowance alone exceeds skin/2, every step rebuilds.
TEST(RotatingBarrierRebuilds, FastImpellerMissesNoContact) { expect_same_trajectory(0.5); }

// Tip at 0.05 skin per step: the lists last a few steps, the vertices' displacement since the
// build decides when they no longer do.
TEST(RotatingBarrierRebuilds, SlowImpellerRebuildsWhenItsTipHasMoved) { expect_same_trajectory(0.05); }

// A resumed run rebuilds at the same steps as an uninterrupted one: the checkpoint places the
// turning blades where they were at the last build (Barriers::time at the build). Checkpoints on
// eight consecutive steps before the first hit, while only the blades' motion sets the rebuilds
// (every 8 steps), so that most fall several steps after a build; the run goes on through the
// hits.
TEST(RotatingBarrierRebuilds, ResumeKeepsTheRebuildSteps) {
  const std::filesystem::path dir = fresh_dir("rotating_resume");
  const auto steps = [](Simulation& sim, int n) {
    for (int k = 0; k < n; ++k) sim.advance(kDt);
  };
  constexpr int kEnd = 8000;  // steps
  Simulation full(impeller(0.05), RunOptions{{}, false, false});
  steps(full, kEnd);
  for (int at = 200; at < 208; ++at) {
    SCOPED_TRACE(at);
    Simulation first(impeller(0.05), RunOptions{{}, false, false});
    steps(first, at);
    first.write_checkpoint(dir / "ck.bin");
    Simulation resumed(impeller(0.05), RunOptions{{}, false, false});
    resumed.resume_from(dir / "ck.bin");
    steps(resumed, kEnd - at);
    EXPECT_GT(full.interactions().stats().rebuilds, first.interactions().stats().rebuilds);
    EXPECT_EQ(resumed.interactions().stats().rebuilds, full.interactions().stats().rebuilds);
    const Particles &a = full.particles(), &b = resumed.particles();
    ASSERT_EQ(a.id, b.id);  // the same reordering at the same steps
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a.x[i], b.x[i]) << "id " << a.id[i];
      EXPECT_EQ(a.v[i], b.v[i]) << "id " << a.id[i];
    }
  }
  std::filesystem::remove_all(dir);
}
