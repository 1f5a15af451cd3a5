// Clump bodies and sinks (sim/sinks.cpp, docs/scene.md "Clumps"): upright dumbbells fall into a
// sink; each is removed whole at the step its centre of mass enters (not when its lower member
// does), the sink counts its members and its mass once, removed.csv names its members, the energy
// it took along (kinetic, rotational and potential, once per body) keeps the balance closed, and a
// run checkpointed after some removals resumes bitwise. With domain.on_exit = "remove" a body
// goes whole at the step its first member leaves the domain.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "physics/rigid_rotation.hpp"
#include "sim/simulation.hpp"
#include "sim/sinks.hpp"
#include "support/clump_scenes.hpp"
#include "support/csv_rows.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kR = 1e-3;   // m, member radius and offset
constexpr double kG = 9.81;   // m/s^2
constexpr double kDt = 1e-4;  // s
constexpr int kSteps = 1000;  // 0.1 s: a body falls g T^2 / 2 = 0.049 m
constexpr int kBodies = 12;

const char* name_of(Integrator integ) { return integ == Integrator::Verlet ? "verlet" : "trapezoidal"; }

// Upright dumbbells (axis along z, turning slowly about y) in a row 8 mm apart (never touching),
// centres from 3 mm to 0.0905 m high, over a sink filling z <= 0; the last one stands beside it.
Scene falling_dumbbells(Integrator integ, bool sink) {
  Scene s = make_scene(kDt, kDt * kSteps);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {0.0, 0.0, -kG};
  s.model.params.output.log_every = 10;
  const int c = add_template(s, "dumbbell", {{{0.0, -kR, 0.0}, kR}, {{0.0, kR, 0.0}, kR}});
  const Quat upright = quat_normalized({1.0, 1.0, 0.0, 0.0});  // template y -> world z
  for (int k = 0; k < kBodies; ++k) {
    const double x = -0.044 + 0.008 * k + (k == kBodies - 1 ? 0.02 : 0.0);
    add_clump(s, 10 + k, c, {x, 0.0, 0.003 + 0.0079 * k}, {0.0, 0.0, 0.0}, {0.0, 2.0 + 0.1 * k, 0.0}, upright);
  }
  finish_clumps(s);
  if (sink) {
    SinkSpec spec;
    spec.name = "outlet";
    spec.region.min = {-0.05, -0.05, -1.0};
    spec.region.max = {0.05, 0.05, 0.0};
    s.model.params.sinks.push_back(spec);
  }
  return s;
}

bool in_sink(const Vec3& x) { return std::abs(x.x) <= 0.05 && std::abs(x.y) <= 0.05 && x.z <= 0.0 && x.z >= -1.0; }

}  // namespace

// Beside the run with the sink goes the same fall without it (the bodies never touch, so the
// two move alike): after every step a body is present exactly when its centre in the free fall is
// outside the sink, with both members; the energy it took along is its 1/2 M v^2 + 1/2 w.(I w) -
// M g.x at that step, summed once per body (1e-12); the sink's mass is M per body (1e-12).
TEST(ClumpSink, BodyIsRemovedWholeWhenItsCentreEnters) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name_of(integ));
    TempDir dir("mpdem_clump_sink");
    Simulation sim(falling_dumbbells(integ, true), RunOptions{dir.path, false, true});
    Simulation free(falling_dumbbells(integ, false), RunOptions{{}, false, false});
    sim.start();
    const double M = sim.particles().bodies.mass[0];
    std::set<std::int64_t> gone;
    double taken = 0.0;                    // J, what the removed bodies took along (from the free fall)
    std::size_t member_first_steps = 0;    // steps where a present body had its lower member in the sink
    std::map<std::int64_t, Vec3> removed;  // body id -> its centre at removal (free fall)
    for (int k = 0; k < kSteps; ++k) {
      sim.step(kDt * kSteps);
      free.advance(kDt);
      const Particles& p = sim.particles();
      const Bodies& B = p.bodies;
      const Bodies& F = free.particles().bodies;
      ASSERT_EQ(p.size(), 2 * B.size());  // never a body without both members
      for (std::size_t f = 0; f < F.size(); ++f) {
        const std::int64_t id = F.id[f];
        const std::ptrdiff_t b = B.find(id);
        if (in_sink(F.x[f])) {
          EXPECT_LT(b, 0) << "body " << id << " with its centre in the sink at step " << k + 1;
          if (b < 0 && !gone.count(id)) {
            gone.insert(id);
            removed[id] = F.x[f];
            taken += 0.5 * M * norm2(F.v[f]) + rotational_energy(F.q[f], F.inertia[f], F.w[f]) + M * kG * F.x[f].z;
          }
          continue;
        }
        ASSERT_GE(b, 0) << "body " << id << " removed at step " << k + 1 << " with its centre at z = " << F.x[f].z;
        EXPECT_EQ(B.x[static_cast<std::size_t>(b)], F.x[f]);
        for (std::size_t i = 0; i < p.size(); ++i)
          if (p.body[i] == id && in_sink(p.x[i])) ++member_first_steps;
      }
    }
    const Sinks::State& st = sim.sinks()->states().at(0);
    const RunRecord& rec = sim.record();
    std::printf("%s: %zu of %d dumbbells removed (%.6g kg, %llu members); %zu steps saw a lower member in the sink "
                "before its body; energy taken along %.9g J (expected %.9g), balance %.12g -> %.12g J\n",
                name_of(integ), gone.size(), kBodies, st.removed_mass, static_cast<unsigned long long>(st.removed),
                member_first_steps, rec.removed_energy, taken, rec.start_balance, rec.balance);
    EXPECT_GE(gone.size(), 5u);
    EXPECT_LT(gone.size(), static_cast<std::size_t>(kBodies - 1));
    EXPECT_GT(member_first_steps, 10u);
    EXPECT_EQ(st.removed, 2 * gone.size());
    EXPECT_NEAR(st.removed_mass, M * static_cast<double>(gone.size()), 1e-12 * st.removed_mass);
    EXPECT_NEAR(rec.removed_energy, taken, 1e-12 * std::abs(taken));
    EXPECT_NEAR(rec.balance, rec.start_balance, 1e-9 * std::abs(rec.start_balance));
    sim.finish();

    // removed.csv: both members of every removed body, nobody else, where their body left them.
    std::vector<std::string> rh;
    std::map<std::int64_t, int> rows_per_body;
    const Particles& p0 = free.particles();
    for (const auto& r : csv_rows(dir.path / "removed.csv", rh)) {
      const auto id = static_cast<std::int64_t>(r[index_of(rh, "id")]);
      std::int64_t body = -1;
      for (std::size_t i = 0; i < p0.size(); ++i)
        if (p0.id[i] == id) body = p0.body[i];
      ++rows_per_body[body];
    }
    EXPECT_EQ(rows_per_body.size(), gone.size());
    for (const std::int64_t id : gone) EXPECT_EQ(rows_per_body[id], 2) << "body " << id;
    // log.csv: the last row's bodies, members and the sink's mass.
    std::vector<std::string> lh;
    const auto rows = csv_rows(dir.path / "log.csv", lh);
    EXPECT_EQ(rows.back()[index_of(lh, "bodies")], static_cast<double>(kBodies - gone.size()));
    EXPECT_EQ(rows.back()[index_of(lh, "members")], static_cast<double>(2 * (kBodies - gone.size())));
    EXPECT_EQ(rows.back()[index_of(lh, "outlet.removed_mass")], st.removed_mass);
  }
}

// A checkpoint written after some bodies were removed (fewer bodies than the scene loads, the
// trapezoidal predictor's body history compacted with them) resumes bitwise.
TEST(ClumpSink, ResumeAfterRemovalsIsBitwise) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name_of(integ));
    TempDir dir("mpdem_clump_sink_resume");
    Simulation full(falling_dumbbells(integ, true), RunOptions{{}, false, false});
    for (int k = 0; k < 700; ++k) full.advance(kDt);
    const std::size_t left = full.particles().bodies.size();
    full.write_checkpoint(dir.path / "ck.bin");
    for (int k = 0; k < 300; ++k) full.advance(kDt);
    Simulation resumed(falling_dumbbells(integ, true), RunOptions{{}, false, false});
    resumed.resume_from(dir.path / "ck.bin");
    EXPECT_EQ(resumed.particles().bodies.size(), left);
    for (int k = 0; k < 300; ++k) resumed.advance(kDt);
    EXPECT_LT(left, static_cast<std::size_t>(kBodies));
    const Bodies &a = full.particles().bodies, &b = resumed.particles().bodies;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_LT(a.size(), left);  // more went after the checkpoint
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a.id[k], b.id[k]);
      EXPECT_EQ(a.x[k], b.x[k]);
      EXPECT_EQ(a.v[k], b.v[k]);
      EXPECT_EQ(a.w[k], b.w[k]);
      EXPECT_EQ(a.q[k].w, b.q[k].w);
    }
    EXPECT_EQ(full.sinks()->states().at(0).removed, resumed.sinks()->states().at(0).removed);
    EXPECT_EQ(full.sinks()->states().at(0).removed_mass, resumed.sinks()->states().at(0).removed_mass);
    EXPECT_EQ(full.record().removed_energy, resumed.record().removed_energy);
  }
}

// domain.on_exit = "remove" with the domain's floor at z = 0: each body goes whole, at the step
// its lower member's centre leaves the domain (long before its centre of mass would), with its
// energy once.
TEST(ClumpSink, BodyLeavingTheDomainGoesWholeWithItsFirstMember) {
  const auto with_domain = [](Scene s) {
    DomainParams& d = s.model.params.domain;
    d.bounded = true;
    d.min = {-0.1, -0.1, 0.0};
    d.max = {0.1, 0.1, 0.2};
    d.on_exit = ExitPolicy::Remove;
    return s;
  };
  Simulation sim(with_domain(falling_dumbbells(Integrator::Verlet, false)), RunOptions{{}, false, false});
  Simulation free(falling_dumbbells(Integrator::Verlet, false), RunOptions{{}, false, false});
  const double M = sim.particles().bodies.mass[0];
  std::set<std::int64_t> gone;
  double taken = 0.0;  // J
  for (int k = 0; k < kSteps; ++k) {
    sim.advance(kDt);
    free.advance(kDt);
    const Particles& p = sim.particles();
    const Particles& q = free.particles();
    ASSERT_EQ(p.size(), 2 * p.bodies.size());
    const Bodies& F = q.bodies;
    for (std::size_t f = 0; f < F.size(); ++f) {
      double lowest = INFINITY;  // m, the lower member's centre in the free fall
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q.body[i] == F.id[f]) lowest = std::min(lowest, q.x[i].z);
      const bool present = p.bodies.find(F.id[f]) >= 0;
      EXPECT_EQ(present, lowest >= 0.0) << "body " << F.id[f] << " at step " << k + 1;
      if (!present && gone.insert(F.id[f]).second) {
        EXPECT_GT(F.x[f].z, 0.5 * kR);  // its centre is still well inside
        taken += 0.5 * M * norm2(F.v[f]) + rotational_energy(F.q[f], F.inertia[f], F.w[f]) + M * kG * F.x[f].z;
      }
    }
  }
  std::printf("on_exit = remove: %zu of %d dumbbells left the domain, energy taken along %.9g J (expected %.9g)\n",
              gone.size(), kBodies, sim.record().removed_energy, taken);
  EXPECT_GE(gone.size(), 5u);
  EXPECT_NEAR(sim.record().removed_energy, taken, 1e-12 * std::abs(taken));
  EXPECT_NEAR(sim.record().balance, sim.record().start_balance, 1e-9 * std::abs(sim.record().start_balance));
}
