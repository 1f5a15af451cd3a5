// Checkpoint and restart: a resumed run is bitwise identical to an uninterrupted one (positions,
// velocities, orientations, temperatures, contact history, adaptive step), in-process and through
// the command line with SIGTERM; a run killed mid-write leaves no truncated file behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <thread>

#include "core/atomic_file.hpp"
#include "core/input_error.hpp"
#include "contact/particle_contacts.hpp"
#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/run_command.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
namespace fs = std::filesystem;

namespace {
// 100 spheres of two sizes and temperatures falling into an open box with a warm floor:
// contacts with friction and rolling resistance, barriers, conduction, neighbour rebuilds.
Scene granular_scene(bool adaptive) {
  Scene s = test::make_scene(2e-5, 1.0);
  Params& prm = s.model.params;
  prm.time.phi = 0.5;
  prm.time.adaptive = adaptive;
  prm.time.dt_min = 1e-7;
  prm.time.dt_max = 4e-5;
  prm.time.desired_iterations = 6;
  prm.analysis.thermal = true;
  prm.thermal.convection = true;
  prm.checks.max_overlap = 0.2;
  ContactLawParams& c = prm.contact.particle_particle;
  c.restitution = 0.5;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.4;
  c.mu_rolling = 0.02;
  prm.contact.particle_barrier = c;
  test::set_material(s, 2500.0, 1e6, 0.3);
  test::add_open_box(s.barriers, 0.02, 0.02, 2, 1e6, 0.3);
  for (std::size_t e = 0; e < s.barriers.size(); ++e) s.barriers.temperature[e] = 350.0;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
  std::int64_t id = 1;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) {
        const double r = (i + j + k) % 2 ? 0.0012 : 0.0009;
        const std::size_t n = test::add_particle(
            s, id++, r, {0.002 + 0.004 * i + jitter(rng), 0.002 + 0.004 * j + jitter(rng), 0.002 + 0.004 * k},
            {jitter(rng) * 100, jitter(rng) * 100, 0});
        s.particles.T[n] = 280.0 + 10.0 * (k % 3);
      }
  return s;
}

void advance(Simulation& sim, bool adaptive, int steps) {
  for (int k = 0; k < steps; ++k) {
    if (adaptive) sim.advance_adaptive(1.0);
    else sim.advance(sim.model().params.time.dt);
  }
}

// The bytes of a checkpoint written after 5 steps of granular_scene, kept as dir/ck.bin.
std::string written_checkpoint(const fs::path& dir) {
  Scene s = granular_scene(false);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  advance(sim, false, 5);
  sim.write_checkpoint(dir / "ck.bin");
  return test::slurp(dir / "ck.bin");
}

std::vector<PairHistory> sorted_history(Simulation& sim) {
  auto h = sim.interactions().particle_contacts().export_history(sim.particles(), sim.interactions().search());
  for (PairHistory& r : h)
    if (r.id_first > r.id_second) {
      std::swap(r.id_first, r.id_second);
      r.spring = -r.spring;
      r.vt0 = -r.vt0;
    }
  std::sort(h.begin(), h.end(), [](const PairHistory& a, const PairHistory& b) {
    return a.id_first != b.id_first ? a.id_first < b.id_first : a.id_second < b.id_second;
  });
  return h;
}

void expect_bitwise_equal(Simulation& a, Simulation& b) {
  const Particles& p = a.particles();
  const Particles& q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.current_dt(), b.current_dt());
  EXPECT_EQ(a.steps(), b.steps());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p.id[i], q.id[i]) << "particle order differs at " << i;
    EXPECT_EQ(p.x[i], q.x[i]) << "id " << p.id[i];
    EXPECT_EQ(p.v[i], q.v[i]) << "id " << p.id[i];
    EXPECT_EQ(p.w[i], q.w[i]) << "id " << p.id[i];
    EXPECT_EQ(p.q[i].w, q.q[i].w);
    EXPECT_EQ(p.q[i].x, q.q[i].x);
    EXPECT_EQ(p.T[i], q.T[i]) << "id " << p.id[i];
  }
  const auto ha = sorted_history(a), hb = sorted_history(b);
  ASSERT_EQ(ha.size(), hb.size());
  ASSERT_GT(ha.size(), 10u);  // the scene does have contact history to carry
  for (std::size_t k = 0; k < ha.size(); ++k) {
    EXPECT_EQ(ha[k].id_first, hb[k].id_first);
    EXPECT_EQ(ha[k].id_second, hb[k].id_second);
    EXPECT_EQ(ha[k].spring, hb[k].spring);
    EXPECT_EQ(ha[k].vt0, hb[k].vt0);
  }
  EXPECT_EQ(a.interactions().stats().friction_dissipated, b.interactions().stats().friction_dissipated);
  EXPECT_EQ(a.interactions().stats().heat_convected, b.interactions().stats().heat_convected);
}
}  // namespace

TEST(Checkpoint, ResumedRunIsBitwiseIdentical) {
  const fs::path dir = test::fresh_dir("checkpoint");
  for (bool adaptive : {false, true}) {
    Scene full_scene = granular_scene(adaptive);
    Simulation full(std::move(full_scene), RunOptions{{}, false, false});
    advance(full, adaptive, 5000);

    Scene first_scene = granular_scene(adaptive);
    Simulation first(std::move(first_scene), RunOptions{{}, false, false});
    advance(first, adaptive, 3000);
    const std::uint64_t rebuilds_at_checkpoint = first.interactions().stats().rebuilds;
    const double dt_at_checkpoint = first.current_dt();
    first.write_checkpoint(dir / "ck.bin");

    Scene resumed_scene = granular_scene(adaptive);  // as loaded again from the scene file
    Simulation resumed(std::move(resumed_scene), RunOptions{{}, false, false});
    resumed.resume_from(dir / "ck.bin");
    advance(resumed, adaptive, 2000);
    EXPECT_GT(resumed.interactions().stats().rebuilds, rebuilds_at_checkpoint);  // lists were rebuilt after it
    expect_bitwise_equal(full, resumed);
    if (adaptive) {
      EXPECT_NE(dt_at_checkpoint, full.model().params.time.dt);  // the adaptive step had moved
    }
  }
  fs::remove_all(dir);
}

TEST(Checkpoint, CorruptOrForeignFileIsAClearError) {
  const fs::path dir = test::fresh_dir("checkpoint_bad");
  const std::string good = written_checkpoint(dir);
  test::write_text(dir / "truncated.bin", good.substr(0, good.size() / 2));
  test::write_text(dir / "text.bin", "hello");
  for (const char* f : {"truncated.bin", "text.bin", "missing.bin"}) {
    Scene s2 = granular_scene(false);
    Simulation sim2(std::move(s2), RunOptions{{}, false, false});
    try {
      sim2.resume_from(dir / f);
      FAIL() << f;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}

// A scene whose duration ends at or before the checkpoint's time leaves nothing to run: refused
// naming the key and both times, instead of a run that exits 0 having done nothing.
TEST(Checkpoint, ResumeWithNothingLeftToRunIsRefused) {
  const fs::path dir = test::fresh_dir("checkpoint_short");
  written_checkpoint(dir);  // 5 steps of 2e-5 s: t = 1e-4 s
  for (const double duration : {5e-5, 1e-4}) {
    Scene s2 = granular_scene(false);
    s2.model.params.time.duration = duration;
    Simulation sim2(std::move(s2), RunOptions{{}, false, false});
    try {
      sim2.resume_from(dir / "ck.bin");
      FAIL() << duration;
    } catch (const InputError& e) {
      test::expect_contains(e.what(), {"'time.duration'", "t = 0.0001 s", "nothing is left to run"});
    }
  }
  Scene s3 = granular_scene(false);  // duration 1 s: resumes
  Simulation sim3(std::move(s3), RunOptions{{}, false, false});
  EXPECT_NO_THROW(sim3.resume_from(dir / "ck.bin"));
  fs::remove_all(dir);
}

TEST(Checkpoint, OtherFormatVersionIsRefusedNamingTheFormat) {
  const fs::path dir = test::fresh_dir("checkpoint_version");
  std::string bytes = written_checkpoint(dir);
  ASSERT_EQ(bytes.substr(0, 7), "MPDEMCK");
  bytes[7] = '1';  // a file of the format before the per-index barrier history
  test::write_text(dir / "old.bin", bytes);
  Scene s2 = granular_scene(false);
  Simulation sim2(std::move(s2), RunOptions{{}, false, false});
  try {
    sim2.resume_from(dir / "old.bin");
    FAIL() << "an old-format checkpoint was accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("old.bin"), std::string::npos) << msg;
    EXPECT_NE(msg.find("checkpoint format 1"), std::string::npos) << msg;
  }
  fs::remove_all(dir);
}

TEST(Checkpoint, KilledBetweenWriteAndRenameLeavesNoTruncatedFile) {
  const fs::path dir = test::fresh_dir("killed_write");
  const fs::path target = dir / "particles_000001.vtu";
  test::write_text(target, "previous complete snapshot\n");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    write_file_atomically(target, [](std::ostream& os) {
      os << "<?xml version=\"1.0\"?><VTKFile";  // half a file ...
      os.flush();
      raise(SIGKILL);  // ... and the process dies before the rename
    });
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(test::slurp(target), "previous complete snapshot\n");  // never truncated
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    EXPECT_TRUE(ext != ".vtu" || e.path() == target) << e.path();  // the partial data is not a .vtu
  }
  fs::remove_all(dir);
}

TEST(Checkpoint, SigtermThenResumeMatchesAnUninterruptedRun) {
  const fs::path dir = test::fresh_dir("sigterm");
  // A scene that runs for many seconds: SIGTERM arrives in the middle.
  std::string csv = "id,x,y,z,vx,vy,radius\n";
  int id = 1;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        csv += std::to_string(id++) + "," + std::to_string(0.002 + 0.0042 * i) + "," +
               std::to_string(0.002 + 0.0042 * j) + "," + std::to_string(0.002 + 0.0042 * k) + "," +
               std::to_string(0.01 * (i - j)) + "," + std::to_string(0.01 * (k - i)) + ",0.0009\n";
  test::write_text(dir / "p.csv", csv);
  test::write_text(dir / "box.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,-0.01,-0.01,0,0.03,-0.01,0,0.03,0.03,0\n"
                                    "2,-0.01,-0.01,0,0.03,0.03,0,-0.01,0.03,0\n");
  const std::string scene =
      "[time]\nduration = 0.4\ndt = 2e-5\nintegrator = \"verlet\"\n"
      "[contact.particle_particle]\nrestitution = 0.5\nmu_static = 0.5\nmu_dynamic = 0.4\n"
      "[contact.particle_barrier]\nrestitution = 0.5\nmu_static = 0.5\nmu_dynamic = 0.4\n"
      "[[material]]\nname = \"m\"\nyoung = 1e6\n[[particles]]\nfile = \"p.csv\"\n[[barriers]]\nfile = \"box.csv\"\n"
      "[checks]\nmax_overlap = 0.2\n"
      "[output]\nparticle_csv_every = 0.1\nlog_every = 500\ncheckpoint_every = 2000\n";
  test::write_text(dir / "scene.toml", scene);
  // Uninterrupted reference.
  ASSERT_EQ(test::run_mpdem("run scene.toml --quiet --threads 1 --output ref", dir).status, 0);
  // Interrupted run: start in the background, SIGTERM after a while.
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string out = (dir / "int_stderr.txt").string();
    if (chdir(dir.c_str()) != 0) _exit(99);
    FILE* f = freopen(out.c_str(), "w", stderr);
    (void)f;
    execl(MPDEM_BINARY, MPDEM_BINARY, "run", "scene.toml", "--threads", "1", "--output", "int", nullptr);
    _exit(98);
  }
  // Wait for the first periodic checkpoint so the run is well under way, then stop it.
  for (int k = 0; k < 600 && !fs::exists(dir / "int" / "checkpoint.bin"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  const std::string err = test::slurp(dir / "int_stderr.txt");
  EXPECT_NE(err.find("stopped by signal 15"), std::string::npos) << err;
  EXPECT_NE(err.find("--resume"), std::string::npos) << err;
  const test::CommandResult res = test::run_mpdem(
      "run scene.toml --quiet --threads 1 --output int --resume int/checkpoint.bin", dir);
  ASSERT_EQ(res.status, 0) << res.err;
  // The final snapshots (t = 0.4 s, 17 significant digits) are identical.
  const std::string a = test::slurp(dir / "ref" / "particles_csv" / "particles_000004.csv");
  const std::string b = test::slurp(dir / "int" / "particles_csv" / "particles_000004.csv");
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, b);
  // The global log has no duplicated or missing rows.
  EXPECT_EQ(test::slurp(dir / "ref" / "log.csv").size(), test::slurp(dir / "int" / "log.csv").size());
  fs::remove_all(dir);
}
