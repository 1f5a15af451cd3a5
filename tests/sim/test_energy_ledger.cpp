// [checks] energy_ledger = false (docs/scene.md "[checks]"): the contacts' energy terms only for
// the steps that write a log row. The particles move bit for bit as with the ledger, every log
// column the two runs share (`elastic` among them) holds the same bits, the log drops the
// dissipated columns and total_energy, the reader refuses an energy check the ledger would not
// feed, and the overlap and non-finite checks still stop the run at the step.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/run_error.hpp"
#include "scene/scene_reader.hpp"
#include "sim/simulation.hpp"
#include "support/csv_rows.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"

namespace mpdem {
namespace {

using test::csv_rows;
using test::TempDir;

struct Logged {
  std::vector<Vec3> x, v, w;  // m, m/s, rad/s, by index
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;  // log.csv
};

// 5600 spheres falling into an open box (rebuilds, walls), 230 steps with a log row every 50
// steps and one at the end (230 is not a multiple).
Logged run(bool ledger, int threads, bool one_region, const TempDir& dir, Integrator integ = Integrator::Verlet) {
  omp_set_num_threads(threads);
  const double dt = 4e-6;
  Scene s = test::dense_scene(20, 20, 14, 1e-3, 0.05, 2.12e-3, 0.15, 21, dt);
  s.model.params.time.integrator = integ;
  s.model.params.time.duration = 230 * dt;
  s.model.params.output.log_every = 50;
  s.model.params.checks.energy_ledger = ledger;
  Simulation sim(std::move(s), RunOptions{dir.path, false, true});
  sim.interactions().set_one_region(one_region);
  sim.run();
  const Particles& p = sim.particles();
  Logged out{p.x, p.v, p.w, {}, {}};
  out.x.resize(p.size()), out.v.resize(p.size()), out.w.resize(p.size());
  out.rows = csv_rows(dir.path / "log.csv", out.header);
  omp_set_num_threads(omp_get_num_procs());
  return out;
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z) return false;
  return true;
}

bool has(const std::vector<std::string>& h, const std::string& c) {
  return std::find(h.begin(), h.end(), c) != h.end();
}

// The trapezoidal rule (its commits: its iterations never compute the energies) and velocity
// Verlet at 1 and 2 threads, Verlet also with a parallel region per pass.
TEST(EnergyLedger, OffMovesTheParticlesAndLogsTheSharedColumnsBitForBit) {
  struct Case {
    Integrator integ;
    int threads;
    bool one_region;
  };
  for (const Case run_case :
       {Case{Integrator::Verlet, 1, true}, Case{Integrator::Verlet, 2, true}, Case{Integrator::Verlet, 1, false},
        Case{Integrator::Verlet, 2, false}, Case{Integrator::Trapezoidal, 2, true}}) {
    const auto [integ, threads, one_region] = run_case;
    SCOPED_TRACE(std::string(integ == Integrator::Verlet ? "verlet" : "trapezoidal") + ", threads " +
                 std::to_string(threads) + (one_region ? ", one region" : ", a region per pass"));
    TempDir on_dir("mpdem_ledger_on"), off_dir("mpdem_ledger_off");
    const Logged on = run(true, threads, one_region, on_dir, integ);
    const Logged off = run(false, threads, one_region, off_dir, integ);
    EXPECT_TRUE(same_bits(on.x, off.x));
    EXPECT_TRUE(same_bits(on.v, off.v));
    EXPECT_TRUE(same_bits(on.w, off.w));
    for (const char* column : {"damping_dissipated", "friction_dissipated", "total_energy"}) {
      EXPECT_TRUE(has(on.header, column)) << column;
      EXPECT_FALSE(has(off.header, column)) << column;
    }
    ASSERT_EQ(on.rows.size(), off.rows.size());
    ASSERT_EQ(on.rows.size(), 6u);  // t = 0, steps 50, 100, 150, 200, and the end (230)
    // The ledger's run dissipates (the columns it drops are not zeros), and the bed is in contact.
    EXPECT_GT(on.rows.back()[test::index_of(on.header, "damping_dissipated")], 0.0);
    EXPECT_GT(on.rows.back()[test::index_of(on.header, "elastic")], 0.0);
    for (std::size_t c = 0; c < off.header.size(); ++c) {
      const std::size_t k = test::index_of(on.header, off.header[c]);
      for (std::size_t r = 0; r < off.rows.size(); ++r)
        EXPECT_EQ(off.rows[r][c], on.rows[r][k]) << off.header[c] << ", row " << r;
    }
  }
}

std::string scene_text(const std::string& checks) {
  return "[time]\nduration = 0.001\ndt = 1e-5\n"
         "[[material]]\nname = \"glass\"\n"
         "[[particles]]\nfile = \"p.csv\"\n"
         "[checks]\n" +
         checks + "\n";
}

TEST(EnergyLedger, OffSwitchesTheEnergyChecksOffAndRefusesAnExplicitOne) {
  TempDir d("mpdem_ledger_keys");
  d.write("p.csv", "x,y,z,radius\n0,0,0,0.01\n");
  {
    const Scene s = load_scene(d.write("a.toml", scene_text("energy_ledger = false")));
    EXPECT_FALSE(s.model.params.checks.energy_ledger);
    EXPECT_EQ(s.model.params.checks.energy_jump, 0.0);
    EXPECT_EQ(s.model.params.checks.energy_drift, 0.0);
    EXPECT_EQ(s.model.params.checks.max_overlap, 0.05);  // the other checks stay
  }
  {
    const Scene s = load_scene(d.write("b.toml", scene_text("energy_jump = 0\nenergy_ledger = false")));
    EXPECT_EQ(s.model.params.checks.energy_jump, 0.0);
  }
  EXPECT_TRUE(load_scene(d.write("c.toml", scene_text(""))).model.params.checks.energy_ledger);  // the default
  for (const std::string key : {"energy_jump", "energy_drift"}) {
    const auto file = d.write("d.toml", scene_text("energy_ledger = false\n" + key + " = 0.1"));
    try {
      load_scene(file);
      ADD_FAILURE() << key << " with the ledger off was accepted";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("d.toml:10"), std::string::npos) << msg;  // the key's line
      EXPECT_NE(msg.find("checks." + key), std::string::npos) << msg;
      EXPECT_NE(msg.find("energy_ledger = false"), std::string::npos) << msg;
    }
  }
  const auto bad = d.write("e.toml", scene_text("energy_ledger = 0"));
  EXPECT_THROW(load_scene(bad), InputError);  // a boolean, not a number
}

std::string run_until_error(Scene& s, double dt, int steps) {
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  try {
    for (int k = 0; k < steps; ++k) sim.advance(dt);
  } catch (const RunError& e) {
    return e.what();
  }
  return "";
}

TEST(EnergyLedger, OffStillStopsAnExplodingOverlapAndANonFiniteState) {
  {  // a soft fast impact: the Hertz overlap reaches ~14 % of the radius (test_instability.cpp)
    Scene s = test::make_scene(1e-4, 1.0);
    s.model.params.time.integrator = Integrator::Verlet;
    s.model.params.checks.energy_ledger = false;
    s.model.params.fields.gravity = {};
    test::add_particle(s, 7, 0.001, {0, 0, 0}, {2.0, 0, 0});
    test::add_particle(s, 8, 0.001, {0.00205, 0, 0}, {-2.0, 0, 0});
    s.model.materials[0].young = 1e5;
    const std::string msg = run_until_error(s, 1e-6, 2000);
    EXPECT_NE(msg.find("between particles id 7 and id 8"), std::string::npos) << msg;
  }
  {
    Scene s = test::make_scene(1e-4, 1.0);
    s.model.params.time.integrator = Integrator::Verlet;
    s.model.params.checks.energy_ledger = false;
    test::add_particle(s, 11, 0.001, {0, 0, 0});
    test::add_particle(s, 42, 0.001, {1, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0, 0});
    const std::string msg = run_until_error(s, 1e-4, 10);
    EXPECT_NE(msg.find("non-finite state of particle id 42"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at step 1"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace mpdem
