#pragma once
// The analysis outputs of a run (docs/output.md "Contact snapshots", "Coarse-grained fields"):
// contact snapshots every [output] contacts_every and the [[coarse_grain]] fields, each sampled
// (and averaged over its window) at step ends and written at its output times. Both need the
// contact list of the step's last evaluation: needs_contacts() says before a step whether it
// must be recorded. On several ranks every rank keeps the schedule and takes part in each sample
// (its owned particles and contacts are gathered on rank 0, each cross-rank pair listed once, by
// the rank of its lower id); rank 0 computes the fields and writes every file.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "analysis/coarse_grain.hpp"
#include "core/binary_stream.hpp"
#include "model/scene.hpp"
#include "interact/interactions.hpp"
#include "output/contact_list.hpp"

namespace mpdem {

class Communicator;
class CsvLog;
class PvdIndex;

// The listed contacts as coarse-graining input (forces and branch vectors, bridges' included) and
// each particle's contact count (touching entries only: a bridge alone is not a contact); members
// found by id (ids [N] of particles [N]; a periodic image or another rank's particle carries its
// source's id); entries whose `first` is not listed are left out.
void cg_contacts(std::span<const std::int64_t> ids, std::span<const ContactEntry> list,
                 std::vector<CgParticle>& particles, std::vector<CgContact>& contacts);

class AnalysisOutputs {
 public:
  // Whether the scene asks for any of them.
  static bool wanted(const Params& p) { return p.output.contacts_every > 0.0 || !p.coarse_grain.empty(); }

  // resume_time: continue the series of a run resumed at that time (later rows and snapshots of
  // the interrupted run are dropped); none for a fresh run. comm: the run's ranks (null: one).
  AnalysisOutputs(const Model& model, std::filesystem::path dir, std::optional<double> resume_time,
                  const Communicator* comm = nullptr);
  ~AnalysisOutputs();

  // Whether a step of dt that ends at t_end may take a sample or write a contact snapshot (end:
  // the run's end time, where a contact snapshot is always written).
  bool needs_contacts(double t_end, double dt, double end) const;
  // After a step of h ending at t (end: the run's end time; last: t has reached it, within the
  // round-off of Simulation::reached). The contact list must be the step's. Collective on several
  // ranks.
  void after_step(double t, double h, double end, bool last, const Particles& p, const Barriers& b,
                  const Interactions& in);
  void flush();

  void save(BinaryWriter& w) const;  // rank 0's state (the schedule is every rank's)
  void restore(BinaryReader& r);

 private:
  struct Field {                // one [[coarse_grain]] entry's progress
    std::uint64_t outputs = 0;  // -, the window of the next sample (window k ends at (k + 1) every)
    std::uint64_t sample = 0;   // -, the next sample's index in its window
    double next_sample = 0.0;   // s
    CgAverage average;
  };
  double sample_time(const CoarseGrainSpec& c, std::uint64_t window, std::uint64_t sample) const;
  std::uint64_t first_sample_after(const CoarseGrainSpec& c, std::uint64_t window, std::uint64_t s0, double u) const;
  std::uint64_t first_window_after(const CoarseGrainSpec& c, std::uint64_t w0, double u) const;
  void write_field(std::size_t k, double t, const CgFields& f);

  bool writes() const;  // this rank computes the fields and writes the files (rank 0)
  bool contacts_on() const { return model_.params.output.contacts_every > 0.0; }

  const Model& model_;
  const Communicator* comm_;  // null: one rank
  std::filesystem::path dir_;
  std::optional<double> resume_time_;
  Vec3 period_;                          // m, the periodic cell's length along periodic axes (0 elsewhere)
  double contacts_next_ = 0.0;           // s
  std::uint64_t contact_snapshots_ = 0;  // written so far
  std::vector<Field> fields_;            // [coarse_grain]
  std::unique_ptr<PvdIndex> contacts_pvd_;
  std::vector<std::unique_ptr<PvdIndex>> grid_pvd_;   // [coarse_grain] grids' .pvd (null for profiles)
  std::vector<std::unique_ptr<CsvLog>> profile_csv_;  // [coarse_grain] profiles' CSV (null for grids)
};

}  // namespace mpdem
