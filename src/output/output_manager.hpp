#pragma once
// OutputManager: decides when each output is due and writes it - particle and barrier VTU
// series with their .pvd indexes, particle CSV snapshots, body CSV snapshots of the clumps, the
// global log and the barrier-group log, and with [bonds] the bond VTU series and bonds_broken.csv. Intervals are in
// simulated seconds (the global log: in steps). docs/output.md lists every file and column. On several ranks rank 0
// alone has one; the ranks write the pieces of each particle VTU snapshot themselves (io/pvtu_writer.hpp) and this
// writes their .pvtu index.
#include <type_traits>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "integrate/step_report.hpp"
#include "output/barrier_load_means.hpp"
#include "core/binary_stream.hpp"
#include "output/global_log.hpp"
#include "model/scene.hpp"
#include "integrate/energy_balance.hpp"
#include "interact/interactions.hpp"
#include "contact/bonds.hpp"

namespace mpdem {

class CsvLog;
class PvdIndex;

// Keeps the header and the rows whose `time` column is <= t: a resumed run continues a log from
// its checkpoint without the rows the interrupted run wrote after it.
void keep_rows_until(const std::filesystem::path& file, double t);

// The particle snapshots due now (OutputManager::particles_due).
struct ParticleSnapshotsDue {
  bool vtu = false;             // a particle VTU snapshot (on several ranks: its pieces and .pvtu)
  bool csv = false;             // a particle CSV snapshot
  std::uint64_t vtu_index = 0;  // -, its counter NNNNNN in the file names, when vtu
  // A body CSV snapshot (the clumps' bodies; on several ranks gathered with the particles).
  bool body_csv = false;
  // A bond VTU snapshot (on several ranks: the bonds and the particles gathered).
  bool bonds = false;
  // Whether the particles are needed whole on rank 0 (gathered on several ranks).
  bool gather() const { return csv || body_csv || bonds; }
};

class OutputManager {
 public:
  // resume_time: continue the series of a run resumed from a checkpoint at that time (rows and
  // snapshots written after it by the interrupted run are dropped); none for a fresh run.
  // pieces: the ranks of the run; more than one: each particle VTU snapshot is written as that
  // many pieces (one per rank, written by the ranks) and a .pvtu index listing them, which
  // snapshots() writes and particles.pvd lists.
  // open_system_columns: the log's inlet and sink columns (GlobalLogLayout).
  OutputManager(const Model& model, std::filesystem::path dir, const Barriers& barriers,
                const std::vector<std::string>& open_system_columns, std::optional<double> resume_time = std::nullopt,
                int pieces = 1);
  ~OutputManager();

  // Writes whatever is due at time t (force = write every snapshot output now: the start and the
  // end of the run, which is written at the final time even when a periodic snapshot falls within
  // half a step of it). With pieces > 1 a due particle VTU snapshot is written as its .pvtu index
  // (the ranks have written its pieces), and p is read for the CSV snapshots only (p.bodies: the
  // body CSV's). bonds: every bond (on several ranks gathered; p then holds all their particles),
  // for the bond VTU.
  void snapshots(double t, double dt, const Particles& p, const Barriers& b, bool force,
                 std::span<const BondRecord> bonds = {});
  // After every accepted step of length h (s): its end-of-step barrier loads enter the means
  // that the barrier outputs write ([output] barrier_loads = "mean").
  void accumulate_barrier_loads(const Barriers& b, double h);
  void global_log(const GlobalLogRow& row, const ParticleTotals& totals, const InteractionStats& stats);
  // The particle files snapshots(t, dt, ..., force) would write (changes nothing): a run on
  // several ranks writes the pieces of a VTU snapshot and gathers its particles for a CSV one.
  ParticleSnapshotsDue particles_due(double t, double dt, bool force) const;
  void removed(std::int64_t id, double t, const Vec3& x);
  // Rows of bonds_broken.csv (one per break, as given).
  void bond_breaks(std::span<const BondBreak> breaks);
  // The cumulative bonds_broken at the last log.csv row (its bonds_broken_interval counts from it).
  std::uint64_t bonds_broken_logged() const { return bonds_broken_logged_; }
  // A load-balance measurement of a run on several ranks: a row of balance.csv.
  struct BalanceRow {
    double time = 0.0;  // s
    std::uint64_t step = 0;
    int ranks = 1;
    double imbalance = 1.0;  // -, max / mean cost per rank
    bool moved = false;      // the cut planes moved (imbalance above the threshold)
  };
  void balance(const BalanceRow& r);
  void flush();
  // Checkpoints: when each series is next due.
  void save(BinaryWriter& w) const;
  void restore(BinaryReader& r);
  const std::filesystem::path& dir() const { return dir_; }

 private:
  struct Series {
    double every = 0.0;       // s
    double next = 0.0;        // s, time of the next snapshot
    double last = 0.0;        // s, time of the last snapshot
    std::uint64_t count = 0;  // snapshots written
  };
  // Checkpoints hold Series byte for byte: a layout change is a format change.
  static_assert(sizeof(Series) == 32 && std::is_trivially_copyable_v<Series>,
                "Series changed: bump kCheckpointFormat (io/checkpoint_format.hpp) and this size");
  // Whether series s is due at time t after a step of dt (s) in a run that ends at `end` (s); force:
  // the start or the end of the run, written unless it already was at t.
  static bool due(Series& s, double t, double dt, double end, bool force);

  const Model& model_;
  std::filesystem::path dir_;
  std::optional<double> resume_time_;  // s, set when continuing a resumed run
  int pieces_ = 1;                     // -, pieces per particle VTU snapshot (the ranks)
  Series particles_vtu_, barriers_vtu_, particles_csv_, barrier_log_;
  // The body CSV series: on only in a scene with clump templates; checkpointed after the others
  // only then, so that the output state of a scene of spheres keeps its bytes.
  Series bodies_csv_;
  // The bond VTU series and the bonds broken as of the last log row: with [bonds] only,
  // checkpointed last, then.
  Series bonds_vtu_;
  std::uint64_t bonds_broken_logged_ = 0;
  std::unique_ptr<PvdIndex> particles_pvd_, barriers_pvd_, bonds_pvd_;
  std::unique_ptr<CsvLog> log_, groups_, removed_, balance_, bonds_broken_;
  // dir_/name for the rows of this run: replaced, or after a resume kept up to its time and appended to.
  std::unique_ptr<CsvLog> open_on_first_row(const char* name, std::vector<std::string> columns) const;
  std::size_t group_count_ = 0;
  std::vector<char> group_turns_;          // [groups] 1: a rotating element (torque and power columns)
  std::vector<std::size_t> group_column_;  // [groups] first column of the group in barrier_groups.csv
  GlobalLogLayout log_layout_;
  BarrierLoadMeans vtu_means_, log_means_;  // since the last barrier VTU / barrier_groups.csv row
};

}  // namespace mpdem
