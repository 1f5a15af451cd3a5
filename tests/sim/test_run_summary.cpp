// The run record behind the end-of-run summary: the energy balance's drift from the start (with
// the energy removed particles take along kept in it), the deepest contact seen, both carried
// through a checkpoint; and the drift warning's threshold.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulation.hpp"
#include "support/run_command.hpp"
#include "support/open_system_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
namespace fs = std::filesystem;

namespace {
// Two spheres colliding head-on, resolved (the deepest overlap is about 2% of the radius).
Scene collision() {
  Scene s = test::make_scene(2e-7, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.materials[0].young = 1e9;
  test::add_particle(s, 5, 0.001, {0, 0, 0}, {1.0, 0, 0});
  test::add_particle(s, 6, 0.001, {0.00205, 0, 0}, {-1.0, 0, 0});
  return s;
}

void advance(Simulation& sim, int steps) {
  for (int k = 0; k < steps; ++k) sim.advance(sim.model().params.time.dt);
}
}  // namespace

TEST(RunRecord, RemovedParticlesKeepTheBalance) {
  // Free fall is exact for velocity Verlet; one particle leaves through the floor of the domain.
  Scene s = test::bounded_domain_scene(1e-4);
  test::add_particle(s, 1, 0.001, {0, 0, 0.01});
  test::add_particle(s, 2, 0.001, {0.05, 0, 0.09});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  advance(sim, 1000);  // particle 1 crosses z = -0.02 after 78 ms, particle 2 only after 150 ms
  ASSERT_EQ(sim.particles().size(), 1u);
  EXPECT_GT(sim.record().removed_energy, 0.0);
  EXPECT_LT(std::abs(energy_drift(sim.record())), 1e-9) << "the removed particle's energy left the balance";
}

TEST(RunRecord, DeepestContactIsRecorded) {
  Scene s = collision();
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  advance(sim, 1500);
  const RunRecord& r = sim.record();
  EXPECT_GT(r.deepest.ratio, 0.005);
  EXPECT_LT(r.deepest.ratio, 0.05);
  EXPECT_EQ(std::min(r.deepest.particle, r.deepest.other), 5);
  EXPECT_EQ(std::max(r.deepest.particle, r.deepest.other), 6);
  EXPECT_EQ(r.deepest.element, -1);
  EXPECT_GT(r.deepest_time, 0.0);
  EXPECT_LT(std::abs(energy_drift(r)), 0.01);
  EXPECT_GT(r.peak_active, 0.0);
}

TEST(RunRecord, SurvivesACheckpoint) {
  const fs::path dir = test::fresh_dir("run_record");
  Scene full_scene = collision();
  Simulation full(std::move(full_scene), RunOptions{{}, false, false});
  advance(full, 1500);
  Scene first_scene = collision();
  Simulation first(std::move(first_scene), RunOptions{{}, false, false});
  advance(first, 100);  // before the contact (at 25 us): the deepest comes after the checkpoint
  first.write_checkpoint(dir / "ck.bin");
  Scene resumed_scene = collision();
  Simulation resumed(std::move(resumed_scene), RunOptions{{}, false, false});
  resumed.resume_from(dir / "ck.bin");
  advance(resumed, 1400);
  const RunRecord& a = full.record();
  const RunRecord& b = resumed.record();
  EXPECT_EQ(a.start_balance, b.start_balance);
  EXPECT_EQ(a.start_active, b.start_active);
  EXPECT_EQ(a.balance, b.balance);
  EXPECT_EQ(a.peak_active, b.peak_active);
  EXPECT_EQ(a.deepest.ratio, b.deepest.ratio);
  EXPECT_EQ(a.deepest_time, b.deepest_time);
  fs::remove_all(dir);
}

TEST(RunRecord, DriftWarningAboveTheThresholdOnly) {
  RunSummary s;
  s.time = 0.25;
  s.drift_limit = 0.05;
  s.record.started = true;
  s.record.start_balance = 1.0;
  s.record.balance = 1.98;
  EXPECT_DOUBLE_EQ(energy_drift(s.record), 0.98);
  const std::string w = drift_warning(s);
  EXPECT_NE(w.find("warning: the energy balance rose by 98%"), std::string::npos) << w;
  EXPECT_NE(w.find("more than checks.energy_drift = 5%"), std::string::npos) << w;
  EXPECT_NE(summary_line(s).find("energy balance drift +98% of the start balance"), std::string::npos)
      << summary_line(s);
  s.record.balance = 0.9;  // a loss beyond the booked dissipation warns too
  EXPECT_NE(drift_warning(s).find("fell by 10%"), std::string::npos) << drift_warning(s);
  s.record.balance = 1.04;
  EXPECT_EQ(drift_warning(s), "");
  s.record.balance = 1.98;
  s.drift_limit = 0.0;  // off
  EXPECT_EQ(drift_warning(s), "");
  s.drift_limit = 0.05;
  s.drift_unchecked = "moving barriers do work that is not in the balance";
  EXPECT_EQ(drift_warning(s), "");
  EXPECT_NE(summary_line(s).find("not checked: moving barriers"), std::string::npos) << summary_line(s);
  // Without the contacts' ledger ([checks] energy_ledger = false) the balance is not booked: no
  // drift figure, no warning, whatever the numbers.
  s.drift_unchecked.clear();
  s.booked = false;
  EXPECT_EQ(drift_warning(s), "");
  EXPECT_EQ(summary_line(s).find("drift"), std::string::npos) << summary_line(s);
  EXPECT_EQ(summary_line(s).rfind("energy balance not booked ([checks] energy_ledger = false); ", 0), 0u)
      << summary_line(s);
  s.booked = true;
  // A balance that starts at zero is measured against the kinetic + rotational + elastic energy.
  RunRecord r;
  r.start_active = 2.0;
  r.balance = 0.5;
  EXPECT_DOUBLE_EQ(energy_drift(r), 0.25);
  r.start_active = 0.0;
  r.peak_active = 5.0;
  EXPECT_DOUBLE_EQ(energy_drift(r), 0.1);
}

// Issue 45 item 4: an open system's drift is measured against the energy the run handled (here
// the 5.6 J the contacts dissipated), not a start balance of 0 J; a closed one as before.
TEST(RunRecord, OpenSystemDriftAgainstTheDissipatedEnergy) {
  RunSummary s;
  s.time = 1.0;
  s.drift_limit = 0.05;
  s.record.started = true;
  s.record.balance = 0.12;  // J, from 0 J at the start (filled from empty)
  s.record.peak_active = 0.6;
  s.inserted_energy = 5.7;
  s.dissipated = 5.6;
  // Closed (as before): against the largest kinetic + elastic energy, 20 %.
  EXPECT_DOUBLE_EQ(energy_drift(s), 0.2);
  EXPECT_NE(drift_warning(s).find("rose by 20%"), std::string::npos) << drift_warning(s);
  s.open = true;
  EXPECT_EQ(drift_reference(s).energy, 5.6);
  EXPECT_STREQ(drift_reference(s).what, "the energy dissipated");
  EXPECT_DOUBLE_EQ(energy_drift(s), 0.12 / 5.6);
  EXPECT_EQ(drift_warning(s), "");
  EXPECT_NE(summary_line(s).find("energy balance drift +2.14% of the energy dissipated, 5.6 J (an open system: the "
                                 "balance 0 J at the start, 0.12 J at the end; inlets brought 5.7 J)"),
            std::string::npos)
      << summary_line(s);
  // Little dissipated (particles passing through): the largest kinetic + elastic energy.
  s.dissipated = 0.1;
  EXPECT_DOUBLE_EQ(energy_drift(s), 0.2);
  const std::string w = drift_warning(s);
  EXPECT_NE(w.find("warning: the energy balance rose by 20% of the largest kinetic + rotational + elastic energy, "
                   "0.6 J (an open system"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("not to be trusted"), std::string::npos) << w;
  // A start balance larger than both (a discharge from a full silo) stays the reference.
  s.record.start_balance = 10.0;
  s.record.balance = 10.12;
  EXPECT_NEAR(energy_drift(s), 0.012, 1e-12);  // 0.12 J of the 10 J
  // Sinks' removals beside the domain exits.
  s.steps = 10;
  s.evaluations = 11;
  s.removed = 3;
  s.sinks = true;
  s.sunk = 4;
  EXPECT_EQ(counts_line(s),
            "10 steps, 11 interaction evaluations, 3 particles removed at the domain boundary, 4 in sinks");
  s.sinks = false;  // inlets only
  EXPECT_EQ(counts_line(s), "10 steps, 11 interaction evaluations, 3 particles removed at the domain boundary");
}
