// Inlets (src/sim/inlets.cpp) in runs: the inserted mass follows the rate, no inserted particle
// overlaps a particle or a barrier element, a full region reports its shortfall (also in
// log.csv), and adding particles keeps the existing contacts' history
// (Interactions::add_particles).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/triangle_closest_point.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"
#include "support/open_system_scenes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

void run_steps(Simulation& sim, std::uint64_t steps) {
  while (sim.steps() < steps) sim.advance(sim.model().params.time.dt);
}

// -, the deepest overlap / radius of particle i with any other particle or active element
// (negative: the smallest gap).
double deepest_overlap(const Particles& p, const Barriers& b, std::size_t i) {
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < p.size(); ++j)
    if (j != i) worst = std::max(worst, (p.radius[i] + p.radius[j] - norm(p.x[i] - p.x[j])) / p.radius[i]);
  for (std::size_t e = 0; e < b.size(); ++e) {
    if (!b.active[e]) continue;
    const Vec3 c = closest_point_on_triangle(p.x[i], b.vertex(e, 0), b.vertex(e, 1), b.vertex(e, 2)).point;
    worst = std::max(worst, (p.radius[i] + 0.5 * b.thickness[e] - norm(p.x[i] - c)) / p.radius[i]);
  }
  return worst;
}

// The last row of a CSV file as column name -> value.
std::vector<std::pair<std::string, double>> last_row(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::vector<std::pair<std::string, double>> out;
  std::stringstream hs(header), ls(last);
  std::string name, value;
  while (std::getline(hs, name, ',') && std::getline(ls, value, ',')) out.emplace_back(name, std::stod(value));
  return out;
}

double column(const std::vector<std::pair<std::string, double>>& row, const std::string& name) {
  for (const auto& [n, v] : row)
    if (n == name) return v;
  ADD_FAILURE() << "no column " << name;
  return 0.0;
}

}  // namespace

// 0.02 kg/s of 1 mm glass spheres at -0.5 m/s for 0.1 s (about 190 particles, 2 per insertion
// time): the inserted mass equals the rate x the time up to the next insertion time within half
// a particle at every time (the rounding to whole particles), so within 1 % at the end (0.3 %
// bound), without shortfall.
TEST(Inlets, InsertedMassFollowsTheRate) {
  Scene s = test::fed_box_scene(0.1, 0.02);
  s.model.params.inlets[0].velocity = {0.0, 0.0, -0.5};
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const double m_p = sphere_mass(0.001, 2500.0);  // kg
  for (const std::uint64_t steps : {1000u, 3000u, 5000u}) {
    run_steps(sim, steps);
    const Inlets::State& st = sim.inlets()->states().at(0);
    const double horizon = std::min(static_cast<double>(st.next_k) * 1e-3, 0.1);  // s
    const double due = 0.02 * horizon;                                            // kg
    EXPECT_LE(std::abs(st.inserted_mass - due), 0.5 * m_p + 1e-15) << "at step " << steps;
    EXPECT_EQ(st.shortfall, 0.0);
    EXPECT_EQ(sim.particles().size(), st.inserted);
    std::printf("t = %.4f s: %llu particles, %.6g kg inserted, %.6g kg due (%+.3g %%)\n", sim.time(),
                static_cast<unsigned long long>(st.inserted), st.inserted_mass, due,
                100.0 * (st.inserted_mass - due) / due);
    if (steps == 5000u) {
      EXPECT_LT(std::abs(st.inserted_mass - due) / due, 0.01);
    }
  }
  // Ids continue from 0 (no particles at the start), one per particle.
  std::vector<std::int64_t> ids(sim.particles().id.begin(), sim.particles().id.end());
  std::sort(ids.begin(), ids.end());
  for (std::size_t k = 0; k < ids.size(); ++k) ASSERT_EQ(ids[k], static_cast<std::int64_t>(k));
}

// A count-driven inlet inserts round(rate x time) particles.
TEST(Inlets, CountRateInsertsWholeParticles) {
  Scene s = test::fed_box_scene(0.02, 0.0);
  InletSpec& in = s.model.params.inlets[0];
  in.mass_rate = 0.0;
  in.count_rate = 1500.0;  // 1.5 per insertion time
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  run_steps(sim, 1000);
  const Inlets::State& st = sim.inlets()->states().at(0);
  const double due = 1500.0 * static_cast<double>(st.next_k) * 1e-3;
  EXPECT_LE(std::abs(static_cast<double>(st.inserted) - due), 0.5);
}

// Inserted into a region already holding a bed of particles and crossed by the box's wall and
// floor, at a rate that fills it: every particle is checked against every other particle and
// every element right after the step that inserted it. Tolerance 1e-6 of its radius.
TEST(Inlets, NoInsertedParticleOverlapsAnything) {
  Scene s = test::fed_box_scene(0.01, 0.2);
  Params& prm = s.model.params;
  prm.fields.gravity = {};
  InletSpec& in = prm.inlets[0];
  in.volume.region.min = {-0.004, 0.002, -0.002};  // through the wall x = 0 and the floor z = 0
  in.volume.region.max = {0.010, 0.012, 0.008};
  in.radius.law = RadiusLaw::Uniform;
  in.radius.min = 0.0008;
  in.radius.max = 0.0012;
  std::int64_t id = 1000000;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) test::add_particle(s, id++, 0.001, {0.0015 + 0.0025 * i, 0.003 + 0.0025 * j, 0.002});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  std::int64_t next = id;  // ids continue after the largest existing one
  std::size_t checked = 0;
  double worst = -std::numeric_limits<double>::infinity();
  for (std::uint64_t step = 1; step <= 500; ++step) {
    sim.advance(sim.model().params.time.dt);
    const Particles& p = sim.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.id[i] < next) continue;
      const double o = deepest_overlap(p, sim.barriers(), i);
      worst = std::max(worst, o);
      EXPECT_LE(o, 1e-6) << "particle id " << p.id[i] << " at step " << step;
      ++checked;
    }
    for (std::size_t i = 0; i < p.size(); ++i) next = std::max(next, p.id[i] + 1);
  }
  const Inlets::State& st = sim.inlets()->states().at(0);
  EXPECT_EQ(checked, st.inserted);
  EXPECT_GT(checked, 50u);
  EXPECT_GT(st.shortfall, 0.0);  // the rate is more than the region holds
  std::printf("%zu inserted particles checked, deepest overlap %.3g of the radius (negative: a gap)\n", checked, worst);
}

// A 3 mm cube holds very few 1 mm spheres (at rest, no gravity): the due mass beyond them is the
// shortfall, in the inlet's state, its summary line and log.csv; inserted + shortfall = due.
TEST(Inlets, FullRegionReportsShortfall) {
  test::TempDir dir("mpdem_inlets");
  Scene s = test::fed_box_scene(0.01, 0.05);
  s.model.params.fields.gravity = {};
  s.model.params.output.log_every = 50;
  InletSpec& in = s.model.params.inlets[0];
  in.volume.region.min = {0.008, 0.008, 0.008};
  in.volume.region.max = {0.011, 0.011, 0.011};
  Simulation sim(std::move(s), RunOptions{dir.path, false, true});
  sim.run();
  const Inlets::State& st = sim.inlets()->states().at(0);
  const double due = 0.05 * 0.01;  // kg, all of it due by the last insertion time
  EXPECT_GE(st.inserted, 1u);
  EXPECT_LE(st.inserted, 2u);
  EXPECT_NEAR(st.inserted_mass + st.shortfall, due, 1e-12 * due);
  EXPECT_NE(sim.inlets()->summary().find("shortfall"), std::string::npos) << sim.inlets()->summary();
  const auto row = last_row(dir.path / "log.csv");
  EXPECT_EQ(column(row, "feed.inserted"), static_cast<double>(st.inserted));
  EXPECT_EQ(column(row, "feed.inserted_mass"), st.inserted_mass);
  EXPECT_EQ(column(row, "feed.shortfall"), st.shortfall);
  std::printf("%llu inserted (%.6g kg), shortfall %.6g kg of %.6g kg due\n",
              static_cast<unsigned long long>(st.inserted), st.inserted_mass, st.shortfall, due);
}

// Two frictional spheres, one on the other on the floor, sliding: appending a far particle
// keeps their pair spring and their barrier springs, so the run goes on as one without it:
// velocities within 1e-9 of the 0.05 m/s start speed (the runs differ in the particle order and
// so in round-off; a lost spring would change the velocity by about mu g dt = 1e-4 m/s at once),
// positions within 1e-12 relative.
TEST(Inlets, AddingParticlesKeepsContactHistory) {
  const auto scene = [] {
    Scene s = test::fed_box_scene(1.0, 0.0);
    s.model.params.inlets.clear();
    s.model.params.time.integrator = Integrator::Trapezoidal;
    s.model.params.checks.energy_jump = 0.0;  // the appended particle's energy is not booked here (no inlet)
    test::add_particle(s, 1, 0.001, {0.01, 0.01, 0.000996}, {0.05, 0.0, 0.0});
    test::add_particle(s, 2, 0.001, {0.01, 0.01, 0.002993}, {-0.05, 0.01, 0.0});
    return s;
  };
  Simulation a(scene(), RunOptions{{}, false, false}), b(scene(), RunOptions{{}, false, false});
  run_steps(a, 200);
  run_steps(b, 200);
  const auto springs = b.interactions().particle_contacts().export_history(b.particles(), b.interactions().search());
  ASSERT_EQ(springs.size(), 1u);
  ASSERT_GT(norm(springs[0].spring), 0.0);
  ASSERT_EQ(b.interactions().stats().contacts_pb, 1u);  // the lower one on the floor
  Particles fresh;
  fresh.add(3, 0, 0.001, 2500.0, {0.015, 0.015, 0.015}, {});
  b.interactions().add_particles(b.particles(), b.barriers(), std::move(fresh));
  const auto kept = b.interactions().particle_contacts().export_history(b.particles(), b.interactions().search());
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].spring, springs[0].spring);
  run_steps(a, 400);
  run_steps(b, 400);
  for (const std::int64_t id : {1, 2}) {
    const std::size_t i = test::index_of(a.particles(), id), j = test::index_of(b.particles(), id);
    const Vec3 va = a.particles().v[i], vb = b.particles().v[j];
    EXPECT_LE(norm(va - vb), 1e-9 * 0.05) << "id " << id;
    EXPECT_LE(norm(a.particles().x[i] - b.particles().x[j]), 1e-12 * norm(a.particles().x[i])) << "id " << id;
  }
}

// A scene filled from empty by an inlet gets its default skin from the inlet's particles (0.2 x
// the smallest radius), not the 1 mm fallback of a scene without any particle.
TEST(Inlets, DefaultSkinFollowsTheInletRadii) {
  Scene s = test::fed_box_scene(0.01, 0.01);
  s.model.params.neighbor.skin = 0.0;  // derived
  EXPECT_DOUBLE_EQ(default_skin(s.model, s.particles), 0.2 * 0.001);
  RadiusDistribution& r = s.model.params.inlets[0].radius;
  r.law = RadiusLaw::Uniform;
  r.min = 0.0004;
  r.max = 0.0008;
  EXPECT_DOUBLE_EQ(default_skin(s.model, s.particles), 0.2 * 0.0004);
  s.model.params.inlets.clear();
  EXPECT_DOUBLE_EQ(default_skin(s.model, s.particles), 1e-3);
}
