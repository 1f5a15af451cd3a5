#include "cli/output_folder.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/input_error.hpp"
#include "io/output_folder.hpp"

namespace mpdem::cli {

namespace fs = std::filesystem;

namespace {
// Everything a run writes into its output folder (docs/output.md).
constexpr std::array<std::string_view, 19> kOutputs{
    "particles",       "particles.pvd", "barriers",           "barriers.pvd",    "particles_csv",
    "bodies_csv",      "log.csv",       "barrier_groups.csv", "removed.csv",     "checkpoint.bin",
    "thermal_log.csv", "warnings.txt",  "balance.csv",        "contacts",        "contacts.pvd",
    "contacts_csv",    "bonds",         "bonds.pvd",          "bonds_broken.csv"};
// The coarse-grained fields' files: cg_<name>.csv, cg_<name>.pvd and the folder cg_<name>.
bool coarse_grain_output(const fs::path& p) { return p.filename().string().rfind("cg_", 0) == 0; }

}  // namespace

void prepare_output_folder(const fs::path& dir, bool overwrite) {
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::is_directory(st) && !fs::is_empty(dir, ec) && !ec) {
    if (!overwrite)
      throw InputError(dir.string(), 0, "",
                       "the output folder is not empty; pass --overwrite to replace the previous run's outputs, "
                       "--resume CHECKPOINT to continue it, or choose another folder with --output");
    ensure_output_folder(dir);  // a read-only folder refuses here, before anything is removed
    for (std::string_view name : kOutputs) fs::remove_all(dir / name);
    std::vector<fs::path> cg;
    for (const auto& e : fs::directory_iterator(dir))
      if (coarse_grain_output(e.path())) cg.push_back(e.path());
    for (const fs::path& p : cg) fs::remove_all(p);
  }
  ensure_output_folder(dir);
}

}  // namespace mpdem::cli
