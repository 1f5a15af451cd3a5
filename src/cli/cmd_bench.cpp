// `mpdem bench`: the settled-bed benchmark driver (docs/benchmark.md). The scene is the one of the
// shared bench README, identical to the LIGGGHTS input liggghts_bench.in. Under mpirun the bed is
// decomposed over the ranks like any run (docs/parallel.md); rank 0 reports the job's totals.
// With --output the steps are whole run steps writing their files (output cost, docs/benchmark.md).
#include <fmt/core.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "cli/bench_beds.hpp"
#include "cli/bench_command.hpp"
#include "cli/output_folder.hpp"
#include "io/output_folder.hpp"
#include "core/input_error.hpp"
#include "io/lammps_data.hpp"
#include "io/vtk_xml.hpp"
#include "neighbor/neighbor_search.hpp"
#include "parallel/gather.hpp"
#include "sim/simulation.hpp"

namespace mpdem::cli {

namespace {

constexpr double kYoung = 1e7;        // Pa, particles and walls
constexpr double kPoisson = 0.3;      // -
constexpr double kRestitution = 0.5;  // -, particle-particle and particle-wall
constexpr double kFriction = 0.5;     // -, static = dynamic sliding friction
constexpr double kGravity = 9.81;     // m/s^2, along -z

ContactLawParams bench_law() {
  ContactLawParams c;
  c.restitution = kRestitution;
  c.mu_static = kFriction;
  c.mu_dynamic = kFriction;
  c.mu_rolling = 0.0;
  c.tangential_damping = 0.0;
  return c;
}

// Adds the rectangle a-b-c-d (counter-clockwise seen from inside the box) as two triangles.
void add_wall(Barriers& b, std::int64_t& next_id, int group, const Vec3& a, const Vec3& bb, const Vec3& c,
              const Vec3& d) {
  const double insulated = std::numeric_limits<double>::quiet_NaN();
  b.add(next_id++, a, bb, c, group, kYoung, kPoisson, MotionLaw{}, 0.0, insulated);
  b.add(next_id++, a, c, d, group, kYoung, kPoisson, MotionLaw{}, 0.0, insulated);
}

void add_walls(const LammpsData& d, Barriers& b);

// The reference scene: particles of the data file, five walls x = lo, hi; y = lo, hi; z = lo
// (no lid) up to the box top, gravity, Hertz-Mindlin, e = 0.5, mu = 0.5, no rolling friction.
void build_scene(const LammpsData& d, const BenchArgs& a, Scene& s) {
  Params& prm = s.model.params;
  prm.time.integrator = a.integrator == "verlet" ? Integrator::Verlet : Integrator::Trapezoidal;
  prm.time.phi = a.phi;
  prm.time.dt = prm.time.dt_min = prm.time.dt_max = a.dt;
  prm.time.duration = a.dt * static_cast<double>(a.relax + a.steps);
  prm.fields.gravity = {0.0, 0.0, -kGravity};
  prm.contact.particle_particle = bench_law();
  prm.contact.particle_barrier = bench_law();
  prm.analysis.rotation = true;
  prm.analysis.thermal = false;
  prm.neighbor.skin = a.skin;
  add_bed_physics(a, prm);                     // --cohesion, --bonds
  prm.checks.energy_ledger = a.energy_ledger;  // without it Simulation checks no energy
  if (!a.output.empty()) {
    prm.output.particles_every = a.dt * static_cast<double>(a.snapshot_every);
    prm.output.format = vtk_format_from_name(a.format).value();  // the command line checked the name
    prm.output.progress_every = 0.0;
  }
  Material m;
  m.name = "bed";
  m.young = kYoung;
  m.poisson = kPoisson;
  m.density = d.atoms.empty() ? 2500.0 : d.atoms.front().density;
  s.model.materials.push_back(m);

  Particles& p = s.particles;
  if (a.clumps) {
    add_clump_bed(d, s);
    return add_walls(d, s.barriers);
  }
  p.reserve(d.atoms.size());
  for (const LammpsAtom& at : d.atoms) {
    p.add(at.id, 0, 0.5 * at.diameter, at.density, at.x, Vec3{});
    const std::size_t i = p.size() - 1;
    p.charge[i] = 0.0;
    p.T[i] = m.temperature;
  }
  add_walls(d, s.barriers);
}

void add_walls(const LammpsData& d, Barriers& b) {
  const int g = b.group_index("walls");
  const Vec3 lo = d.lo, hi = d.hi;
  const double h = hi.z;
  std::int64_t next = 1;
  add_wall(b, next, g, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, h}, {lo.x, lo.y, h});        // x = lo
  add_wall(b, next, g, {hi.x, lo.y, lo.z}, {hi.x, lo.y, h}, {hi.x, hi.y, h}, {hi.x, hi.y, lo.z});        // x = hi
  add_wall(b, next, g, {lo.x, lo.y, lo.z}, {lo.x, lo.y, h}, {hi.x, lo.y, h}, {hi.x, lo.y, lo.z});        // y = lo
  add_wall(b, next, g, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, h}, {lo.x, hi.y, h});        // y = hi
  add_wall(b, next, g, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z});  // floor
}

double kinetic_energy(const Particles& p) {
  double e = 0.0;
  for (std::size_t b = 0; b < p.bodies.size(); ++b) e += 0.5 * p.bodies.mass[b] * norm2(p.bodies.v[b]);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == kNoBody) e += 0.5 * p.mass[i] * norm2(p.v[i]);
  return e;
}

double top(const Particles& p) {
  double z = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) z = std::max(z, p.x[i].z);
  return z;
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;  // KiB on Linux
}

}  // namespace

int bench_command(const BenchArgs& args) {
  if (args.integrator != "verlet" && args.integrator != "trapezoidal")
    throw InputError("", 0, "--integrator", "expected \"verlet\" or \"trapezoidal\"");
  if (std::find(kBenchCohesions.begin(), kBenchCohesions.end(), args.cohesion) == kBenchCohesions.end())
    throw InputError("", 0, "--cohesion", "expected \"none\", \"jkr\", \"sjkr\" or \"bridges\"");
  if (args.threads < 1) throw InputError("", 0, "--threads", "expected >= 1");
  if (!(args.dt > 0.0) || !(args.skin >= 0.0) || args.relax < 0 || args.steps < 0)
    throw InputError("", 0, "--dt/--skin/--relax/--steps", "expected dt > 0, skin >= 0, relax >= 0, steps >= 0");
  if (args.snapshot_every > 0 && args.output.empty())
    throw InputError("", 0, "--snapshot-every", "snapshots need --output FOLDER");
  if (std::error_code ec;
      !args.output.empty() && std::filesystem::exists(args.output, ec) && !std::filesystem::is_empty(args.output, ec))
    throw InputError(args.output.string(), 0, "--output", "the bench writes only into a fresh or empty folder");
  if (!args.output.empty()) ensure_output_folder(args.output);
  omp_set_num_threads(args.threads);

  BenchArgs a = args;
  Scene scene;
  {  // the parsed file is not needed once the scene holds the particles (peak memory counts)
    const LammpsData d = read_lammps_data(args.data);
    if (a.steps == 0) a.steps = d.atoms.size() <= 50000 ? 5000 : 2000;
    build_scene(d, a, scene);
  }
  const std::size_t n = scene.particles.size();

  const Communicator& comm = Communicator::world();
  const bool files = !a.output.empty();
  Simulation sim(std::move(scene), RunOptions{a.output, false, files, &comm});
  const double end = a.dt * static_cast<double>(a.relax + a.steps);  // s
  // One step: with files the whole step of a run (outputs included), else the evaluation and
  // integration alone. Returns its force evaluations.
  const auto step = [&] {
    if (!files) return static_cast<std::uint64_t>(sim.advance(a.dt).evaluations);
    const std::uint64_t before = sim.evaluations();
    sim.step(end);
    return sim.evaluations() - before;
  };
  for (long k = 0; k < a.relax; ++k) step();

  const std::uint64_t rebuilds0 = sim.interactions().stats().rebuilds;
  const PhaseTimes times0 = sim.interactions().times();
  std::uint64_t evaluations = 0;
  comm.barrier();  // every rank starts the timed steps together; the slowest one's time counts
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < a.steps; ++k) evaluations += step();
  const auto t1 = std::chrono::steady_clock::now();
  const PhaseTimes& times1 = sim.interactions().times();

  const double seconds = comm.max(std::chrono::duration<double>(t1 - t0).count());
  const double psteps = static_cast<double>(n) * static_cast<double>(a.steps);
  const InteractionStats st = sim.interactions().global_stats();
  const std::uint64_t rebuilds = st.rebuilds - rebuilds0;
  const double pp_per_particle = n ? static_cast<double>(st.contacts_pp) / static_cast<double>(n) : 0.0;
  const double coordination = 2.0 * pp_per_particle;  // each contact counted at both particles
  const double pb_per_particle = n ? static_cast<double>(st.contacts_pb) / static_cast<double>(n) : 0.0;
  const double evals_per_step = a.steps ? static_cast<double>(evaluations) / static_cast<double>(a.steps) : 0.0;
  const double ke = comm.sum(kinetic_energy(sim.particles()));
  const double zmax = comm.max(top(sim.particles()));
  const long rss = static_cast<long>(comm.sum(static_cast<std::uint64_t>(peak_rss_kib())));  // the job's
  const double bodies = comm.sum(static_cast<double>(sim.particles().bodies.size()));
  const double pairs = comm.sum(static_cast<double>(sim.interactions().search().pairs().num_pairs()));
  const double cross = comm.sum(static_cast<double>(sim.interactions().search().blocks().num_cross()));
  // Where the time goes (s in the timed steps): the slowest rank's parts.
  double part[] = {times1.search - times0.search,     times1.fields - times0.fields, times1.pairs - times0.pairs,
                   times1.barriers - times0.barriers, times1.other - times0.other,   times1.exchange - times0.exchange};
  comm.max(part);
  // Several ranks: each rank's share, to see an imbalance (owned particles, ghosts, listed pairs,
  // and its time in pairs and in the exchange, which holds its waits for the others).
  struct RankShare {
    double owned, ghosts, listed, pairs_s, exchange_s;
  };
  const RankShare mine{static_cast<double>(sim.particles().size()), static_cast<double>(sim.particles().n_ghost),
                       static_cast<double>(sim.interactions().search().pairs().num_pairs()),
                       times1.pairs - times0.pairs, times1.exchange - times0.exchange};
  const std::vector<RankShare> shares = gather_values<RankShare>(comm, std::span(&mine, 1), 0);
  if (comm.rank() != 0) return 0;
  const std::string integ = a.integrator == "verlet" ? "verlet" : fmt::format("trapezoidal(phi={})", a.phi);

  fmt::print("mpdem bench: {} particles, {} walls (triangles {}), {} ranks x {} threads, {}\n", n, 5,
             sim.barriers().size(), comm.size(), a.threads, integ);
  if (a.clumps) fmt::print("  clumps: {:.0f} tetrahedral bodies of 4 members (a particle is a member)\n", bodies);
  if (const std::string physics = bed_physics_summary(a); !physics.empty()) fmt::print("  {}\n", physics);
  fmt::print("  steps: {} untimed + {} timed, dt = {:g} s, skin = {:g} m\n", a.relax, a.steps, a.dt, a.skin);
  if (!a.energy_ledger) fmt::print("  energy ledger off (--no-energy-ledger): no energy checks\n");
  fmt::print("  wall time of timed steps   {:.3f} s\n", seconds);
  fmt::print("  throughput                 {:.4g} particle-steps/s\n", seconds > 0 ? psteps / seconds : 0.0);
  fmt::print("  cost                       {:.1f} ns/particle-step\n", psteps > 0 ? 1e9 * seconds / psteps : 0.0);
  fmt::print("  force evaluations / step   {:.2f}\n", evals_per_step);
  fmt::print("  neighbour rebuilds (timed) {}\n", rebuilds);
  fmt::print("  listed pairs per particle  {:.3f}\n", n ? pairs / static_cast<double>(n) : 0.0);
  fmt::print("  listed pairs across blocks {:.1f}% (their second member's share goes through a buffer)\n",
             100.0 * cross / std::max(1.0, pairs));
  fmt::print("  contacts per particle      {:.3f} (coordination 2 pp/N; pp/N = {:.3f}, walls/N = {:.3f})\n",
             coordination, pp_per_particle, pb_per_particle);
  if (a.bonds)
    fmt::print("  bonds                      {} intact, {} broken; {:.3f} per particle\n", st.bonds_intact,
               st.bonds_broken, n ? 2.0 * static_cast<double>(st.bonds_intact) / static_cast<double>(n) : 0.0);
  if (a.cohesion != "none")
    fmt::print("  cohesion                   {} liquid bridges; broken so far: {} necks, {} bridges\n", st.bridges,
               st.cohesion_breaks, st.ruptures);
  fmt::print("  final kinetic energy       {:.4g} J, top of bed z = {:.6g} m\n", ke, zmax);
  fmt::print("  peak RSS                   {:.1f} MiB{}\n", static_cast<double>(rss) / 1024.0,
             comm.serial() ? "" : " (sum over the ranks)");
  // Where the time goes, ns per particle-step: the evaluation's parts, and the rest of the step
  // (integration, the per-step checks); exchange: ghosts and barrier loads between the ranks,
  // with the waits for the others.
  const auto per = [&](double t) { return psteps > 0 ? 1e9 * t / psteps : 0.0; };
  const double eval = per(part[0] + part[1] + part[2] + part[3] + part[4] + part[5]);
  fmt::print("  ns/particle-step by part   search {:.1f}, fields {:.1f}, pairs {:.1f}, barriers {:.1f}, other {:.1f}, "
             "exchange {:.1f}, integration + checks {:.1f}\n",
             per(part[0]), per(part[1]), per(part[2]), per(part[3]), per(part[4]), per(part[5]),
             psteps > 0 ? 1e9 * seconds / psteps - eval : 0.0);
  if (!comm.serial())
    for (std::size_t r = 0; r < shares.size(); ++r)
      fmt::print("  rank {:<3}                   {:.0f} particles, {:.0f} ghosts, {:.0f} listed pairs; pairs {:.3f} s, "
                 "exchange {:.3f} s\n",
                 r, shares[r].owned, shares[r].ghosts, shares[r].listed, shares[r].pairs_s, shares[r].exchange_s);
  fmt::print(
      "BENCH_RESULT code=mpdem integrator={} ranks={} threads={} particles={} steps={} seconds={:.6f} "
      "psteps_per_s={:.6g} "
      "ns_per_pstep={:.4f} evals_per_step={:.4f} rebuilds={} coordination={:.5f} wall_contacts_per_particle={:.5f} "
      "ke={:.6g} zmax={:.9g} peak_rss_kib={} bed={} bodies={:.0f} bonds={} bonds_broken={} bridges={} "
      "cohesion_breaks={} ruptures={}\n",
      a.integrator == "verlet" ? "verlet" : "trapezoidal", comm.size(), a.threads, n, a.steps, seconds,
      seconds > 0 ? psteps / seconds : 0.0, psteps > 0 ? 1e9 * seconds / psteps : 0.0, evals_per_step, rebuilds,
      coordination, pb_per_particle, ke, zmax, rss, bench_bed_name(a), bodies, st.bonds_intact, st.bonds_broken,
      st.bridges, st.cohesion_breaks, st.ruptures);
  return 0;
}

}  // namespace mpdem::cli
