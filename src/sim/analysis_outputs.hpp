#pragma once
// The analysis outputs of a run (docs/output.md "Contact snapshots", "Coarse-grained fields"):
// contact snapshots every [output] contacts_every and the [[coarse_grain]] fields, each sampled
// (and averaged over its window) at step ends and written at its output times. Both need the
// contact list of the step's last evaluation: needs_contacts() says before a step whether it
// must be recorded.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/coarse_grain.hpp"
#include "io/binary_stream.hpp"
#include "model/scene.hpp"
#include "sim/interactions.hpp"

namespace mpdem {

class CsvLog;
class PvdIndex;

class AnalysisOutputs {
 public:
  // Whether the scene asks for any of them.
  static bool wanted(const Params& p) { return p.output.contacts_every > 0.0 || !p.coarse_grain.empty(); }

  // resume_time: continue the series of a run resumed at that time (later rows and snapshots of
  // the interrupted run are dropped); none for a fresh run.
  AnalysisOutputs(const Model& model, std::filesystem::path dir, std::optional<double> resume_time);
  ~AnalysisOutputs();

  // Whether a step of dt that ends at t_end may take a sample or write a contact snapshot (end:
  // the run's end time, where a contact snapshot is always written).
  bool needs_contacts(double t_end, double dt, double end) const;
  // After a step of h ending at t (end: the run's end time). The contact list must be the step's.
  void after_step(double t, double h, double end, const Particles& p, const Barriers& b, const Interactions& in);
  void flush();

  void save(BinaryWriter& w) const;
  void restore(BinaryReader& r);

 private:
  struct Field {                // one [[coarse_grain]] entry's progress
    std::uint64_t outputs = 0;  // written so far
    std::uint64_t sample = 0;   // samples taken in the current window
    double next_sample = 0.0;   // s
    CgAverage average;
  };
  double sample_time(const CoarseGrainSpec& c, std::uint64_t window, std::uint64_t sample) const;
  void write_field(std::size_t k, double t, const CgFields& f);

  const Model& model_;
  std::filesystem::path dir_;
  std::optional<double> resume_time_;
  double contacts_next_ = 0.0;           // s
  std::uint64_t contact_snapshots_ = 0;  // written so far
  std::vector<Field> fields_;            // [coarse_grain]
  std::unique_ptr<PvdIndex> contacts_pvd_;
  std::vector<std::unique_ptr<PvdIndex>> grid_pvd_;   // [coarse_grain] grids' .pvd (null for profiles)
  std::vector<std::unique_ptr<CsvLog>> profile_csv_;  // [coarse_grain] profiles' CSV (null for grids)
};

}  // namespace mpdem
