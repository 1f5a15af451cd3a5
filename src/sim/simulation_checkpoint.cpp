// Checkpoints of a Simulation (issue: restart): everything the next step depends on, so a
// resumed run is bitwise identical to an uninterrupted one with the same thread count - the
// particle arrays in their current order (with the rates of the accepted state), the
// neighbour lists' build positions (rebuilds then happen at the same steps), contact history,
// statistics, the adaptive step, the output series and the run record of the end-of-run summary
// (drift, deepest contact) - and the fingerprint of the scene the run started from, so that a
// resume with another scene is refused (io/scene_fingerprint.hpp). The file is a sequence of
// named, checksummed sections (io/checkpoint_format.hpp).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <type_traits>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/input_file.hpp"
#include "io/checkpoint_format.hpp"
#include "core/input_error.hpp"
#include "output/output_manager.hpp"
#include "io/scene_fingerprint.hpp"
#include "parallel/gather.hpp"
#include "output/analysis_outputs.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"
#include "sim/sinks.hpp"

namespace mpdem {

namespace {
// The run's own counters, field by field (one list for writing and reading).
template <class F>
void for_each_counter(double& time, std::uint64_t& steps, std::uint64_t& evaluations, std::size_t& removed,
                      std::uint64_t& redone, double& dt, double& last_balance, double& last_active,
                      bool& energy_checked, F&& f) {
  f(time);
  f(steps);
  f(evaluations);
  f(removed);
  f(redone);
  f(dt);
  f(last_balance);
  f(last_active);
  f(energy_checked);
}

// The restored particles hold what the engine assumes of every particle (the readers check the
// same of a scene's): a checkpoint whose checksums are intact may still have been written by
// another program or patched. Throws std::runtime_error naming the array and the particle id.
void check_restored(const Particles& p, std::size_t materials) {
  const auto fail = [&](std::size_t i, const char* array, const char* what) {
    throw std::runtime_error(fmt::format("particle id {} (index {}): 'particles/{}' {}", p.id[i], i, array, what));
  };
  std::vector<std::int64_t> ids(p.id.begin(), p.id.end());
  std::sort(ids.begin(), ids.end());
  if (const auto d = std::adjacent_find(ids.begin(), ids.end()); d != ids.end())
    throw std::runtime_error(fmt::format("particle id {} appears twice in 'particles/id'", *d));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] < 0 || static_cast<std::size_t>(p.material[i]) >= materials)
      fail(i, "material", "is not an index of the scene's materials");
    if (!(std::isfinite(p.radius[i]) && p.radius[i] > 0.0)) fail(i, "radius", "is not finite and > 0");
    if (!(std::isfinite(p.mass[i]) && p.mass[i] > 0.0)) fail(i, "mass", "is not finite and > 0");
    if (!(std::isfinite(p.inertia[i]) && p.inertia[i] > 0.0)) fail(i, "inertia", "is not finite and > 0");
    if (!std::isfinite(p.charge[i])) fail(i, "charge", "is not finite");
    if (p.fixed[i] > 1) fail(i, "fixed", "is not 0 or 1");
    if (!isfinite(p.x[i])) fail(i, "x", "is not finite");
    if (!isfinite(p.v[i])) fail(i, "v", "is not finite");
    if (!isfinite(p.w[i])) fail(i, "w", "is not finite");
    const Quat& q = p.q[i];
    if (!(std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)))
      fail(i, "q", "is not finite");
    if (!std::isfinite(p.T[i])) fail(i, "T", "is not finite");
    if (!isfinite(p.force[i])) fail(i, "force", "is not finite");
    if (!isfinite(p.torque[i])) fail(i, "torque", "is not finite");
    if (!std::isfinite(p.heat[i])) fail(i, "heat", "is not finite");
  }
}
}  // namespace

void Simulation::write_checkpoint(const std::filesystem::path& file) {
  // Several ranks (collective): rank 0 writes every particle, in id order, with the history keyed
  // by ids, in the one-rank layout: any rank count resumes the file.
  Particles all = comm_ ? gathered() : Particles{};
  Particles& p = comm_ ? all : scene_.particles;
  CheckpointWriter w;
  w.section("scene_fingerprint", [&](BinaryWriter& o) { save_fingerprint(o, fingerprint_); });
  w.section("run", [&](BinaryWriter& o) {
    for_each_counter(time_, steps_, evaluations_, removed_, redone_, dt_, last_balance_, last_active_, energy_checked_,
                     [&](auto& v) { o.value(v); });
  });
  w.section("run_record", [&](BinaryWriter& o) { RunRecord::for_each_field(record_, [&](auto& v) { o.value(v); }); });
  // One section per particle array, by name: an array added to Particles adds a section, and a
  // checkpoint without it is refused naming it.
  // The owned particles only: ghosts are rebuilt from them at the restore.
  const std::size_t owned = p.size();
  p.for_each_array([&](const char* name, auto& a) {
    w.section(std::string("particles/") + name, [&](BinaryWriter& o) {
      o.vector(std::decay_t<decltype(a)>(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(owned)));
    });
  });
  // The clumps' bodies, one section per array (several ranks: gathered, in id order); in every
  // scene with templates, so that a run whose sinks removed its bodies, or whose inlets have not
  // yet added any, resumes as well.
  const bool clumps = !scene_.model.clumps.empty();
  if (clumps)
    p.bodies.for_each_array([&](const char* name, auto& a) {
      w.section(std::string("bodies/") + name, [&](BinaryWriter& o) { o.vector(a); });
    });
  // The bodies' rate history by body id, in the bodies' order (collective).
  const std::vector<RateRecord> body_records =
      comm_ && clumps ? gather_values<RateRecord>(*comm_, trapezoidal_.bodies().records(scene_.particles.bodies), 0)
                      : std::vector<RateRecord>{};
  if (comm_) interactions_->save_gathered(w, scene_.particles, all);
  else interactions_->save(w, p);
  // The trapezoidal predictor's previous rates, by id (any rank count resumes them).
  const RateHistory& rates = trapezoidal_.rate_history();
  const std::vector<RateRecord> rate_records = comm_ ? gather_values<RateRecord>(*comm_, rates.records(), 0)
                                                     : rates.records();
  if (!root()) return;
  w.section("rate_history", [&](BinaryWriter& o) {
    std::vector<RateRecord> sorted = rate_records;
    std::sort(sorted.begin(), sorted.end(), [](const RateRecord& a, const RateRecord& b) { return a.id < b.id; });
    // Right after a resume on several ranks every rank holds every record: keep one of each.
    sorted.erase(std::unique(sorted.begin(), sorted.end(),
                             [](const RateRecord& a, const RateRecord& b) { return a.id == b.id; }),
                 sorted.end());
    o.value(rates.dt());
    o.vector(sorted);
  });
  if (clumps)
    w.section("body_rate_history", [&](BinaryWriter& o) {
      if (!comm_) return trapezoidal_.bodies().save(o);
      std::vector<RateRecord> sorted = body_records;
      std::sort(sorted.begin(), sorted.end(), [](const RateRecord& a, const RateRecord& b) { return a.id < b.id; });
      // The particles' step length: rank 0 may hold no body (and so no length of its own); a
      // history that lacks a body is none.
      const bool whole = sorted.size() == p.bodies.size();
      TrapezoidalBodies::save(o, whole ? rates.dt() : 0.0, whole ? sorted : std::vector<RateRecord>{});
    });
  // What decides the next insertions and the sinks' totals ([[inlet]], [[sink]]).
  if (inlets_) w.section("inlets", [&](BinaryWriter& o) { inlets_->save(o); });
  if (sinks_) w.section("sinks", [&](BinaryWriter& o) { sinks_->save(o); });
  if (output_) w.section("output", [&](BinaryWriter& o) { output_->save(o); });
  if (analysis_) w.section("analysis", [&](BinaryWriter& o) { analysis_->save(o); });
  write_file_atomically(
      file, [&](std::ostream& os) { os.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size())); });
}

void Simulation::resume_from(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (std::string why = input_file_problem(file); !why.empty()) {
    std::error_code ec;  // a run's output folder given instead of its checkpoint
    if (std::filesystem::is_regular_file(file / "checkpoint.bin", ec))
      why += "; did you mean " + (file / "checkpoint.bin").string() + "?";
    throw InputError(name, 0, "", "checkpoint file " + why);
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name, 0, "", "cannot open the checkpoint file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  try {
    CheckpointReader r(bytes.data(), bytes.size());
    const auto read = [&](const std::string& section, auto&& f) {
      BinaryReader s = r.open(section);
      f(s);
      r.done(section, s);
    };
    // The scene first: a checkpoint of another scene is refused saying what differs, before its
    // arrays are compared with this scene's (which would only say that counts differ).
    read("scene_fingerprint", [&](BinaryReader& s) {
      const std::string differs = fingerprint_difference(load_fingerprint(s), fingerprint_);
      if (!differs.empty()) {
        // A scene that ran the trapezoidal rule by default (before velocity Verlet became it).
        const std::string hint =
            differs.find("time.integrator") != std::string::npos
                ? " A scene without [time] integrator runs velocity Verlet; one written for the trapezoidal rule "
                  "by default needs integrator = \"trapezoidal\"."
                : "";
        throw InputError(scene_.file.empty() ? name : scene_.file.string(), 0, "",
                         fmt::format("cannot resume from the checkpoint '{}': it was written for another scene - this "
                                     "scene differs from that one in its {}.{} Resume with the scene the checkpoint "
                                     "was written for, or start a new run; editable on resume: {} (docs/output.md)",
                                     name, differs, hint, kEditableOnResume));
      }
    });
    read("run", [&](BinaryReader& s) {
      for_each_counter(time_, steps_, evaluations_, removed_, redone_, dt_, last_balance_, last_active_,
                       energy_checked_, [&](auto& v) { v = s.value<std::decay_t<decltype(v)>>(); });
    });
    read("run_record", [&](BinaryReader& s) {
      RunRecord::for_each_field(record_, [&](auto& v) { v = s.value<std::decay_t<decltype(v)>>(); });
    });
    Particles& p = scene_.particles;
    p.drop_ghosts();
    p.for_each_array([&](const char* array, auto& a) {
      read(std::string("particles/") + array,
           [&](BinaryReader& s) { a = s.template vector<typename std::decay_t<decltype(a)>::value_type>(); });
    });
    const std::size_t n = p.id.size();
    bool sizes_ok = true;
    p.for_each_array([&](const char*, auto& a) { sizes_ok = sizes_ok && a.size() == n; });
    if (!sizes_ok) throw std::runtime_error("particle arrays of different lengths");
    check_restored(p, scene_.model.materials.size());
    const bool clumps = !scene_.model.clumps.empty();
    if (clumps) {
      // As many bodies as the checkpoint holds (sinks remove bodies, inlets add them), each with its members.
      std::size_t nb = 0;
      p.bodies.for_each_array([&](const char* array, auto& a) {
        read(std::string("bodies/") + array,
             [&](BinaryReader& s) { a = s.template vector<typename std::decay_t<decltype(a)>::value_type>(); });
        if (std::string_view(array) == "id") nb = a.size();
        if (a.size() != nb) throw std::runtime_error("the checkpoint's body arrays differ in length");
      });
      for (std::size_t b = 0; b < nb; ++b)
        if (p.bodies.clump[b] < 0 || static_cast<std::size_t>(p.bodies.clump[b]) >= scene_.model.clumps.size() ||
            p.bodies.material[b] < 0 || static_cast<std::size_t>(p.bodies.material[b]) >= scene_.model.materials.size())
          throw std::runtime_error("a body's template or material index is out of range");
      p.bodies.resize(nb);  // marks the member index and the id lookup stale
      try {
        p.bodies.index_members(p);
      } catch (const std::logic_error& e) {
        throw std::runtime_error(std::string("the checkpoint's bodies and member spheres do not match: ") + e.what());
      }
    }
    const std::vector<std::int64_t> body_ids = p.bodies.id;  // the checkpoint's (a rank keeps its own)
    if (!(std::isfinite(time_) && time_ >= 0.0 && std::isfinite(dt_) && dt_ > 0.0))
      throw std::runtime_error(
          fmt::format("the run section's time {} s or step {} s is not finite and >= 0", time_, dt_));
    scene_.barriers.move_to(time_);
    interactions_->restore(r, p, scene_.barriers);
    read("rate_history", [&](BinaryReader& s) {
      const auto dt = s.value<double>();
      trapezoidal_.rate_history().set_records(s.vector<RateRecord>(), dt);
    });
    if (clumps)
      read("body_rate_history", [&](BinaryReader& s) { trapezoidal_.bodies().restore(s, body_ids, p.bodies); });
    if (inlets_) read("inlets", [&](BinaryReader& s) { inlets_->restore(s); });
    if (sinks_) read("sinks", [&](BinaryReader& s) { sinks_->restore(s); });
    // The output series are restored once run() has opened the outputs.
    if (r.has("output")) {
      read("output", [&](BinaryReader& s) { resume_output_state_ = s.rest(); });
    }
    if (r.has("analysis")) read("analysis", [&](BinaryReader& s) { resume_analysis_state_ = s.rest(); });
    r.finish();
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(name, 0, "", std::string("cannot resume from this checkpoint: ") + e.what());
  }
  // Nothing would be left to run: say so rather than exit 0 having done nothing.
  const double duration = scene_.model.params.time.duration;
  if (!(time_ < duration))
    throw InputError(scene_.file.empty() ? name : scene_.file.string(), 0, "time.duration",
                     fmt::format("the checkpoint '{}' is at t = {:.9g} s, not before the scene's time.duration = "
                                 "{:.9g} s: nothing is left to run; raise time.duration to continue the run",
                                 name, time_, duration));
  // The time goes on as the checkpoint's run counted it: from t = 0 while each of its steps had
  // the scene's dt (a resume with a longer duration is then the uninterrupted run), else from the
  // checkpoint (an edited step, or a step cut to land on an end).
  const Params& prm = scene_.model.params;
  const bool adaptive = prm.time.adaptive && prm.time.integrator == Integrator::Trapezoidal;
  const bool from_zero = static_cast<double>(steps_) * prm.time.dt == time_;
  clock_time_ = from_zero ? 0.0 : time_;
  clock_step_ = from_zero ? 0 : steps_;
  clock_dt_ = adaptive ? std::numeric_limits<double>::quiet_NaN() : prm.time.dt;
  initialized_ = true;
  resumed_ = true;
}

}  // namespace mpdem
