#include "output/output_manager.hpp"

#include "parallel/periodic_images.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "io/body_csv_writer.hpp"
#include "io/bond_vtu_writer.hpp"
#include "output/bond_cells.hpp"
#include "io/csv_log.hpp"
#include "io/particle_csv_writer.hpp"
#include "io/pvd_index.hpp"
#include "io/pvtu_writer.hpp"
#include "io/vtu_writer.hpp"

namespace mpdem {

namespace fs = std::filesystem;

void keep_rows_until(const fs::path& file, double t) {
  if (!fs::exists(file)) return;
  std::ifstream in(file);
  std::string header, line, kept;
  if (!std::getline(in, header)) return;
  std::size_t col = 0;
  {
    std::stringstream hs(header);
    std::string name;
    while (std::getline(hs, name, ',') && name != "time") ++col;
  }
  kept = header + "\n";
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::string field;
    for (std::size_t c = 0; c <= col && std::getline(ls, field, ','); ++c) {}
    char* end = nullptr;
    const double v = std::strtod(field.c_str(), &end);
    if (end != field.c_str() && v <= t) kept += line + "\n";
  }
  write_file_atomically(file, [&](std::ostream& os) { os << kept; });
}

OutputManager::OutputManager(const Model& model, fs::path dir, const Barriers& barriers,
                             const std::vector<std::string>& open_system_columns, std::optional<double> resume_time,
                             int pieces)
    : model_(model), dir_(std::move(dir)), resume_time_(resume_time), pieces_(pieces),
      log_layout_(model, barriers, open_system_columns) {
  const CsvLog::Open mode = resume_time ? CsvLog::Open::append : CsvLog::Open::replace;
  auto pvd = [&](const fs::path& f) {
    return resume_time ? std::make_unique<PvdIndex>(f, *resume_time) : std::make_unique<PvdIndex>(f);
  };
  auto log = [&](const fs::path& f, std::vector<std::string> cols) {
    if (resume_time) keep_rows_until(f, *resume_time);
    return std::make_unique<CsvLog>(f, std::move(cols), mode);
  };
  const OutputParams& o = model.params.output;
  particles_vtu_.every = o.particles_every;
  barriers_vtu_.every = o.barriers_every;
  particles_csv_.every = o.particle_csv_every;
  barrier_log_.every = o.barrier_log_every;
  bodies_csv_.every = model.clumps.empty() ? 0.0 : o.body_csv_every;
  const bool bonds = model.params.bonds.enabled();
  bonds_vtu_.every = bonds ? o.bonds_every : 0.0;
  fs::create_directories(dir_);
  if (particles_vtu_.every > 0.0) {
    fs::create_directories(dir_ / "particles");
    particles_pvd_ = pvd(dir_ / "particles.pvd");
  }
  if (barriers_vtu_.every > 0.0 && barriers.size() > 0) {
    fs::create_directories(dir_ / "barriers");
    barriers_pvd_ = pvd(dir_ / "barriers.pvd");
  }
  if (particles_csv_.every > 0.0) fs::create_directories(dir_ / "particles_csv");
  if (bodies_csv_.every > 0.0) fs::create_directories(dir_ / "bodies_csv");
  if (bonds_vtu_.every > 0.0) {
    fs::create_directories(dir_ / "bonds");
    bonds_pvd_ = pvd(dir_ / "bonds.pvd");
  }
  log_ = log(dir_ / "log.csv", log_layout_.columns());
  if (bonds) bonds_broken_ = log(dir_ / "bonds_broken.csv", {"time", "id_i", "id_j", "mode", "sigma_max", "tau_max"});
  group_count_ = barriers.group_names.size();
  if (barrier_log_.every > 0.0 && group_count_ > 0) {
    std::vector<std::string> cols{"time"};
    group_turns_.assign(group_count_, 0);
    for (std::size_t e = 0; e < barriers.size(); ++e)
      if (barriers.rotation_of[e] >= 0) group_turns_[static_cast<std::size_t>(barriers.group[e])] = 1;
    for (std::size_t g = 0; g < group_count_; ++g) {
      group_column_.push_back(cols.size());
      const std::string& name = barriers.group_names[g];
      for (const char* c : {"fx", "fy", "fz", "mx", "my", "mz", "area"}) cols.push_back(name + "." + c);
      if (group_turns_[g])
        for (const char* c : {"torque", "power"}) cols.push_back(name + "." + c);
    }
    groups_ = log(dir_ / "barrier_groups.csv", cols);
  }
}

OutputManager::~OutputManager() = default;

void OutputManager::save(BinaryWriter& w) const {
  for (const Series* s : {&particles_vtu_, &barriers_vtu_, &particles_csv_, &barrier_log_}) w.value(*s);
  vtu_means_.save(w);
  log_means_.save(w);
  if (bodies_csv_.every > 0.0) w.value(bodies_csv_);
  if (model_.params.bonds.enabled()) {
    w.value(bonds_vtu_);
    w.value(bonds_broken_logged_);
  }
}

void OutputManager::restore(BinaryReader& r) {
  for (Series* s : {&particles_vtu_, &barriers_vtu_, &particles_csv_, &barrier_log_}) {
    const double every = s->every;  // the scene's interval wins over the checkpoint's
    *s = r.value<Series>();
    s->every = every;
  }
  vtu_means_.restore(r);
  log_means_.restore(r);
  const bool bonds = model_.params.bonds.enabled();
  // The body CSV series of a run that wrote one (save): what is left before the bonds' state.
  if (!r.at_end() && (!bonds || bodies_csv_.every > 0.0)) {
    const double every = bodies_csv_.every;
    bodies_csv_ = r.value<Series>();
    bodies_csv_.every = every;
  }
  if (bonds && !r.at_end()) {
    const double every = bonds_vtu_.every;
    bonds_vtu_ = r.value<Series>();
    bonds_vtu_.every = every;
    bonds_broken_logged_ = r.value<std::uint64_t>();
  }
}

void OutputManager::accumulate_barrier_loads(const Barriers& b, double h) {
  if (!model_.params.output.mean_barrier_loads || b.size() == 0) return;
  if (barriers_pvd_) vtu_means_.add(b, h);
  if (groups_) log_means_.add(b, h);
}

bool OutputManager::due(Series& s, double t, double dt, double end, bool force) {
  if (s.every <= 0.0) return false;
  const double slack = 0.5 * dt;                 // round-off in the accumulated time must not skip a snapshot
  if (s.count > 0 && t <= s.last) return false;  // already written at this time
  if (!force) {
    if (s.count > 0 && t <= s.last + slack) return false;
    if (t + slack < s.next) return false;
    // Due within half a step of the end: the end's own snapshot is that one, at the final time.
    if (s.next >= end - slack) return false;
  }
  s.next = (std::floor((t + slack) / s.every) + 1.0) * s.every;
  s.last = t;
  ++s.count;
  return true;
}

ParticleSnapshotsDue OutputManager::particles_due(double t, double dt, bool force) const {
  const double end = model_.params.time.duration;
  Series vtu = particles_vtu_, csv = particles_csv_, bodies = bodies_csv_;
  ParticleSnapshotsDue d;
  d.vtu = particles_pvd_ && due(vtu, t, dt, end, force);
  d.csv = csv.every > 0.0 && due(csv, t, dt, end, force);
  d.body_csv = bodies.every > 0.0 && due(bodies, t, dt, end, force);
  Series bonds = bonds_vtu_;
  d.bonds = bonds_pvd_ && due(bonds, t, dt, end, force);
  if (d.vtu) d.vtu_index = vtu.count - 1;
  return d;
}

void OutputManager::snapshots(double t, double dt, const Particles& p, const Barriers& b, bool force,
                              std::span<const BondRecord> bonds) {
  const double end = model_.params.time.duration;
  if (particles_pvd_ && due(particles_vtu_, t, dt, end, force)) {
    const std::uint64_t index = particles_vtu_.count - 1;
    if (pieces_ > 1) {
      write_particles_pvtu(dir_, index, pieces_);
      particles_pvd_->add(t, particle_pvtu_name(index));
    } else {
      const std::string name = fmt::format("particles/particles_{:06d}.vtu", index);
      write_particles_vtu(dir_ / name, p, t, vtu_options(model_));
      particles_pvd_->add(t, name);
    }
  }
  const bool means = model_.params.output.mean_barrier_loads;
  if (barriers_pvd_ && due(barriers_vtu_, t, dt, end, force)) {
    const std::string name = fmt::format("barriers/barriers_{:06d}.vtu", barriers_vtu_.count - 1);
    if (means && vtu_means_.span() > 0.0) {
      const BarrierLoads l = vtu_means_.mean(b);
      const ElementLoadView view{l.force, l.moment, l.pressure};
      write_barriers_vtu(dir_ / name, b, t, model_.params.output.format, &view);
    } else {
      write_barriers_vtu(dir_ / name, b, t, model_.params.output.format);
    }
    vtu_means_.clear();
    barriers_pvd_->add(t, name);
  }
  if (particles_csv_.every > 0.0 && due(particles_csv_, t, dt, end, force)) {
    write_particles_csv(dir_ / fmt::format("particles_csv/particles_{:06d}.csv", particles_csv_.count - 1), p, t,
                        PeriodicImages(model_.params.domain).period());
  }
  if (bodies_csv_.every > 0.0 && due(bodies_csv_, t, dt, end, force))
    write_bodies_csv(dir_ / fmt::format("bodies_csv/bodies_{:06d}.csv", bodies_csv_.count - 1), p.bodies, model_.clumps,
                     t);
  if (bonds_pvd_ && due(bonds_vtu_, t, dt, end, force)) {
    const std::string name = fmt::format("bonds/bonds_{:06d}.vtu", bonds_vtu_.count - 1);
    write_bonds_vtu(dir_ / name, bond_cells(bonds, p, PeriodicImages(model_.params.domain).period()), t,
                    model_.params.output.format);
    bonds_pvd_->add(t, name);
  }
  if (groups_ && due(barrier_log_, t, dt, end, force)) {
    const BarrierLoads l = means ? log_means_.mean(b) : current_loads(b);
    log_means_.clear();
    std::vector<double> row(groups_->columns().size(), 0.0);
    row[0] = t;
    for (std::size_t e = 0; e < b.size(); ++e) {
      const auto grp = static_cast<std::size_t>(b.group[e]);
      double* g = &row[group_column_[grp]];
      const Vec3 m = l.moment[e] + cross(b.centre(e), l.force[e]);  // moment about the origin
      g[0] += l.force[e].x;
      g[1] += l.force[e].y;
      g[2] += l.force[e].z;
      g[3] += m.x;
      g[4] += m.y;
      g[5] += m.z;
      g[6] += b.area[e];
      if (group_turns_[grp]) {
        g[7] += l.axis_torque[e];
        g[8] += l.drive_power[e];
      }
    }
    groups_->row(row);
  }
}

void OutputManager::global_log(const GlobalLogRow& r, const ParticleTotals& t, const InteractionStats& s) {
  GlobalLogRow row = r;
  row.bonds_broken_before = bonds_broken_logged_;
  log_->row(log_layout_.values(row, t, s));
  bonds_broken_logged_ = s.bonds_broken;
}

std::unique_ptr<CsvLog> OutputManager::open_on_first_row(const char* name, std::vector<std::string> columns) const {
  const fs::path f = dir_ / name;
  const bool resume = resume_time_ && fs::exists(f);
  if (resume) keep_rows_until(f, *resume_time_);
  return std::make_unique<CsvLog>(f, std::move(columns), resume ? CsvLog::Open::append : CsvLog::Open::replace);
}

void OutputManager::removed(std::int64_t id, double t, const Vec3& x) {
  if (!removed_) removed_ = open_on_first_row("removed.csv", {"time", "id", "x", "y", "z"});
  const double row[] = {t, static_cast<double>(id), x.x, x.y, x.z};
  removed_->row(row);
}

void OutputManager::bond_breaks(std::span<const BondBreak> breaks) {
  if (!bonds_broken_) return;
  for (const BondBreak& k : breaks) {
    std::string fields[6];
    append_csv_number(fields[0], k.time);
    append_csv_number(fields[1], static_cast<double>(k.id_i));
    append_csv_number(fields[2], static_cast<double>(k.id_j));
    fields[3] = k.mode == BondBreakMode::tension ? "tension" : "shear";
    append_csv_number(fields[4], k.sigma);
    append_csv_number(fields[5], k.tau);
    bonds_broken_->text_row(fields);
  }
}

void OutputManager::balance(const BalanceRow& r) {
  if (!balance_) balance_ = open_on_first_row("balance.csv", {"time", "step", "ranks", "imbalance", "moved"});
  const double row[] = {r.time, static_cast<double>(r.step), static_cast<double>(r.ranks), r.imbalance,
                        r.moved ? 1.0 : 0.0};
  balance_->row(row);
}

void OutputManager::flush() {
  log_->flush();
  if (groups_) groups_->flush();
  if (removed_) removed_->flush();
  if (balance_) balance_->flush();
  if (bonds_broken_) bonds_broken_->flush();
}

}  // namespace mpdem
