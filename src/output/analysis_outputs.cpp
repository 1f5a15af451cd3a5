#include "output/analysis_outputs.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <tuple>
#include <unordered_map>

#include "contact/cohesion_reach.hpp"
#include "model/body_members.hpp"
#include "output/cg_writer.hpp"
#include "output/contact_writer.hpp"
#include "io/csv_log.hpp"
#include "output/output_manager.hpp"
#include "io/pvd_index.hpp"
#include "parallel/periodic_images.hpp"
#include "parallel/gather.hpp"
#include "output/contact_list.hpp"

namespace mpdem {

namespace fs = std::filesystem;

namespace {

// s, the first multiple of `every` after u, computed directly (an interval below the step gives
// one snapshot per step, never a loop over the intervals passed).
double next_multiple(double every, double u) { return (std::floor(u / every) + 1.0) * every; }

// The owned particles as coarse-graining input (contacts not yet counted) and their ids.
// A clump's member stands for its share of the body's mass, moving with the body's velocity
// (model/body_members.hpp).
void cg_particles(const Model& model, const Particles& p, std::vector<CgParticle>& particles,
                  std::vector<std::int64_t>& ids) {
  const std::size_t n = p.size();
  particles.resize(n);
  ids.assign(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double r = p.radius[i];
    particles[i] = {p.x[i], represented_velocity(p, i), represented_mass(model, p, i),
                    4.0 / 3.0 * std::numbers::pi * r * r * r, 0};
  }
}

// Contact snapshot rows that do not depend on the rank count or the particle order: each pair
// seen from its member of lower id, the rows by first id, then second id (pairs) or element id
// (barrier contacts).
void orient_and_sort(std::vector<ContactEntry>& list) {
  for (ContactEntry& c : list)
    if (c.second >= 0 && c.second < c.first) {
      std::swap(c.first, c.second);
      std::swap(c.first_body, c.second_body);
      c.normal = -c.normal;
      c.normal_force = -c.normal_force;
      c.tangential_force = -c.tangential_force;
      c.centre = c.centre - c.branch;  // the other's centre (its image across a periodic boundary)
      c.branch = -c.branch;
    }
  std::stable_sort(list.begin(), list.end(), [](const ContactEntry& a, const ContactEntry& b) {
    return std::tie(a.first, a.second, a.element) < std::tie(b.first, b.second, b.element);
  });
}

}  // namespace

void cg_contacts(std::span<const std::int64_t> ids, std::span<const ContactEntry> list,
                 std::vector<CgParticle>& particles, std::vector<CgContact>& contacts) {
  std::unordered_map<std::int64_t, std::size_t> index;  // id -> index
  index.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) index.emplace(ids[i], i);
  contacts.clear();
  contacts.reserve(list.size());
  for (const ContactEntry& c : list) {
    const auto first = index.find(c.first);
    if (first == index.end()) continue;  // not a listed particle's contact
    if (c.touching) {                    // a bridge alone carries a force but is not a contact
      ++particles[first->second].contacts;
      if (c.second >= 0)
        if (const auto it = index.find(c.second); it != index.end()) ++particles[it->second].contacts;
    }
    contacts.push_back({first->second, c.normal_force + c.tangential_force, c.branch, c.element >= 0});
  }
}

AnalysisOutputs::AnalysisOutputs(const Model& model, fs::path dir, std::optional<double> resume_time,
                                 const Communicator* comm)
    : model_(model), comm_(comm), dir_(std::move(dir)), resume_time_(resume_time),
      period_(PeriodicImages(model.params.domain).period()) {
  const Params& prm = model.params;
  const bool files = writes();
  auto pvd = [&](const fs::path& f) {
    if (!files) return std::unique_ptr<PvdIndex>();
    return resume_time ? std::make_unique<PvdIndex>(f, *resume_time) : std::make_unique<PvdIndex>(f);
  };
  if (files) fs::create_directories(dir_);
  if (contacts_on()) {
    if (files) {
      fs::create_directories(dir_ / "contacts");
      fs::create_directories(dir_ / "contacts_csv");
    }
    contacts_pvd_ = pvd(dir_ / "contacts.pvd");
    contacts_next_ = prm.output.contacts_every;
  }
  for (std::size_t k = 0; k < prm.coarse_grain.size(); ++k) {
    const CoarseGrainSpec& c = prm.coarse_grain[k];
    const std::string stem = "cg_" + c.name;
    Field f;
    f.next_sample = sample_time(c, 0, 0);
    fields_.push_back(std::move(f));
    if (!files) {
      profile_csv_.emplace_back();
      grid_pvd_.emplace_back();
    } else if (c.profile) {
      const fs::path file = dir_ / (stem + ".csv");
      if (resume_time) keep_rows_until(file, *resume_time);
      profile_csv_.push_back(
          std::make_unique<CsvLog>(file, cg_profile_columns(c.axis),
                                   resume_time && fs::exists(file) ? CsvLog::Open::append : CsvLog::Open::replace));
      grid_pvd_.emplace_back();
    } else {
      fs::create_directories(dir_ / stem);
      grid_pvd_.push_back(pvd(dir_ / (stem + ".pvd")));
      profile_csv_.emplace_back();
    }
  }
}

AnalysisOutputs::~AnalysisOutputs() = default;

bool AnalysisOutputs::writes() const { return !comm_ || comm_->rank() == 0; }

// s, sample `sample` of window `window`: the window ends at output (window + 1) * every and its
// samples are spaced evenly, the last one at its end.
double AnalysisOutputs::sample_time(const CoarseGrainSpec& c, std::uint64_t window, std::uint64_t sample) const {
  const double end = static_cast<double>(window + 1) * c.every;
  if (c.average <= 0.0) return end;
  const auto n = static_cast<double>(c.samples);
  return end - c.average + static_cast<double>(sample + 1) * c.average / n;
}

bool AnalysisOutputs::needs_contacts(double t_end, double dt, double end) const {
  const double slack = 0.5 * dt;
  if (contacts_on() && (t_end >= contacts_next_ - slack || t_end >= end - slack)) return true;
  for (const Field& f : fields_)
    if (t_end >= f.next_sample - slack) return true;
  return false;
}

void AnalysisOutputs::after_step(double t, double h, double end, bool last, const Particles& p, const Barriers& b,
                                 const Interactions& in) {
  const double slack = 0.5 * h;
  // The run's last step writes a contact snapshot; a periodic one due within half a step before
  // it is left to it, so the end state is written once.
  const bool contacts_due = contacts_on() && (last || (t >= contacts_next_ - slack && t < end - slack));
  bool fields_due = false;
  for (const Field& f : fields_) fields_due = fields_due || t >= f.next_sample - slack;
  if (!contacts_due && !fields_due) return;
  // This rank's contacts and particles; on several ranks, every rank's on rank 0 (in rank order).
  std::vector<ContactEntry> list = contact_list(p, b, in);
  std::vector<CgParticle> particles;
  std::vector<std::int64_t> ids;
  if (fields_due) cg_particles(model_, p, particles, ids);
  if (comm_ && comm_->size() > 1) {
    list = gather_values<ContactEntry>(*comm_, list, 0);
    if (fields_due) {
      particles = gather_values<CgParticle>(*comm_, particles, 0);
      ids = gather_values<std::int64_t>(*comm_, ids, 0);
    }
  }
  const bool files = writes();
  const Params& prm = model_.params;
  if (contacts_due) {
    const std::string name = fmt::format("contacts/contacts_{:06d}.vtu", contact_snapshots_);
    if (files) {
      std::vector<ContactEntry> rows = list;
      orient_and_sort(rows);
      const bool bodies = !model_.clumps.empty();  // the members' body ids
      const bool cohesion = has_cohesion(model_);  // touching and bridge flags (the materials as now)
      write_contacts_vtu(dir_ / name, rows, t, prm.output.format, bodies, cohesion);
      write_contacts_csv(dir_ / fmt::format("contacts_csv/contacts_{:06d}.csv", contact_snapshots_), rows, t, bodies,
                         cohesion);
      contacts_pvd_->add(t, name);
    }
    ++contact_snapshots_;
    contacts_next_ = next_multiple(prm.output.contacts_every, t + slack);
  }
  std::vector<CgContact> contacts;
  if (files && fields_due) cg_contacts(ids, list, particles, contacts);
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    Field& f = fields_[k];
    const CoarseGrainSpec& c = prm.coarse_grain[k];
    if (t < f.next_sample - slack) continue;
    if (files) f.average.add(coarse_grain(c.grid, c.kernel, c.width, particles, contacts, period_));
    // The window is done once its last sample is passed (a step longer than the spacing skips
    // samples); the next sample is the first one after this step, found directly.
    const std::uint64_t n = c.average > 0.0 ? static_cast<std::uint64_t>(c.samples) : 1;
    const double u = t + slack;
    if (f.sample + 1 < n && sample_time(c, f.outputs, n - 1) > u) {
      f.sample = first_sample_after(c, f.outputs, f.sample + 1, u);
      f.next_sample = sample_time(c, f.outputs, f.sample);
      continue;
    }
    if (files) write_field(k, t, f.average.mean());
    f.average.clear();
    f.outputs = first_window_after(c, f.outputs + 1, u);
    f.sample = n > 1 ? first_sample_after(c, f.outputs, 0, u) : 0;
    f.next_sample = sample_time(c, f.outputs, f.sample);
  }
}

// The smallest sample index s >= s0 of `window` whose time is after u (s, the window's last
// sample is), from its estimate corrected for round-off.
std::uint64_t AnalysisOutputs::first_sample_after(const CoarseGrainSpec& c, std::uint64_t window, std::uint64_t s0,
                                                  double u) const {
  const auto n = static_cast<std::uint64_t>(c.samples);
  const double start = static_cast<double>(window + 1) * c.every - c.average;  // s, the window's start
  const double x = std::floor((u - start) * static_cast<double>(n) / c.average);
  std::uint64_t s = x <= static_cast<double>(s0) ? s0 : std::min(n - 1, static_cast<std::uint64_t>(x));
  for (int k = 0; k < 2 && s > s0 && sample_time(c, window, s - 1) > u; ++k) --s;
  for (int k = 0; k < 2 && s + 1 < n && sample_time(c, window, s) <= u; ++k) ++s;
  return s;
}

// The smallest window index w >= w0 whose last sample (at its end) is after u, from its estimate
// corrected for round-off: a window whose first samples a long step passed still gets an output,
// from the samples left. An interval below the resolution of the time gives a window that is not
// after u: it is then due at the next step (one output per step, never a loop over windows).
std::uint64_t AnalysisOutputs::first_window_after(const CoarseGrainSpec& c, std::uint64_t w0, double u) const {
  const std::uint64_t last = c.average > 0.0 ? static_cast<std::uint64_t>(c.samples) - 1 : 0;
  constexpr double kLargest = 0x1p62;  // -, a window index that stays exact in a double and an uint64
  const double x = std::min(kLargest, std::floor(u / c.every));
  std::uint64_t w = x <= static_cast<double>(w0) ? w0 : static_cast<std::uint64_t>(x);
  for (int k = 0; k < 2 && w > w0 && sample_time(c, w - 1, last) > u; ++k) --w;
  for (int k = 0; k < 2 && sample_time(c, w, last) <= u; ++k) ++w;
  return w;
}

void AnalysisOutputs::write_field(std::size_t k, double t, const CgFields& f) {
  const CoarseGrainSpec& c = model_.params.coarse_grain[k];
  if (c.profile) {
    for (const std::vector<double>& row : cg_profile_rows(c.grid, f, c.axis, t)) profile_csv_[k]->row(row);
    profile_csv_[k]->flush();
    return;
  }
  const std::string stem = "cg_" + c.name;
  // Named by the count of files written (the .pvd lists each), whether or not windows were skipped.
  const std::string name = fmt::format("{}/{}_{:06d}.vti", stem, stem, grid_pvd_[k]->entries().size());
  write_cg_vti(dir_ / name, c.grid, f, t, model_.params.output.format);
  grid_pvd_[k]->add(t, name);
}

void AnalysisOutputs::flush() {
  for (auto& csv : profile_csv_)
    if (csv) csv->flush();
}

void AnalysisOutputs::save(BinaryWriter& w) const {
  w.value(contacts_next_);
  w.value(contact_snapshots_);
  w.value(static_cast<std::uint64_t>(fields_.size()));
  for (const Field& f : fields_) {
    w.value(f.outputs);
    w.value(f.sample);
    w.value(f.next_sample);
    f.average.visit_state([&](const auto& v) {
      if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::size_t>) w.value(static_cast<std::uint64_t>(v));
      else w.vector(v);
    });
  }
}

void AnalysisOutputs::restore(BinaryReader& r) {
  contacts_next_ = r.value<double>();
  contact_snapshots_ = r.value<std::uint64_t>();
  if (r.value<std::uint64_t>() != fields_.size())
    throw std::runtime_error("the checkpoint's [[coarse_grain]] entries differ from the scene's");
  for (Field& f : fields_) {
    f.outputs = r.value<std::uint64_t>();
    f.sample = r.value<std::uint64_t>();
    f.next_sample = r.value<double>();
    f.average.visit_state([&](auto& v) {
      using T = std::decay_t<decltype(v)>;
      if constexpr (std::is_same_v<T, std::size_t>) v = static_cast<std::size_t>(r.value<std::uint64_t>());
      else v = r.template vector<typename T::value_type>();
    });
  }
}

}  // namespace mpdem
