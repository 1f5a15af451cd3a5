#pragma once
// ParaView collection (.pvd) listing a time series of .vtu snapshots. Every add() rewrites the
// whole file atomically, so at any moment (also after a kill) the .pvd is valid XML listing
// every snapshot written so far with its time; ParaView's time slider then shows the series.
#include <filesystem>
#include <string>
#include <vector>

namespace mpdem {

class PvdIndex {
 public:
  struct Entry {
    double time;       // s, simulated time of the snapshot
    std::string file;  // path of the .vtu relative to the .pvd's folder
  };

  // Starts a new, empty series and writes it (replacing any .pvd left by an earlier run).
  explicit PvdIndex(std::filesystem::path pvd_file);
  // Continues the series of an existing .pvd written by this class (resume from a checkpoint):
  // keeps its entries with time <= keep_until (s), drops later ones. A missing file starts empty.
  // Throws std::runtime_error if the file exists but cannot be read.
  PvdIndex(std::filesystem::path pvd_file, double keep_until);

  // Appends one snapshot and rewrites the .pvd. Throws std::runtime_error on a write failure.
  void add(double time, const std::string& relative_vtu_name);

  const std::vector<Entry>& entries() const { return entries_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  void write() const;
  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

}  // namespace mpdem
