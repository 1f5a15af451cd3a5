#include "cli/mpi_launcher.hpp"

#include <cstdlib>
#include <string_view>

#include "cli/run_paths.hpp"

namespace mpdem::cli {

namespace {
bool env_is(const char* name, std::string_view value) {
  const char* v = std::getenv(name);
  return v != nullptr && value == v;
}
}  // namespace

std::string launcher_command(int ranks) {
  if (ranks <= 1) return "";
  const std::string n = std::to_string(ranks);
  // Open MPI's mpirun (or mpiexec, the same program) leaves its contact address to the ranks; a
  // rank started by Slurm's srun has a step id and no such address.
  if (std::getenv("OMPI_MCA_orte_hnp_uri") == nullptr && std::getenv("SLURM_STEP_ID") != nullptr) {
    const char* mpi = std::getenv("SLURM_MPI_TYPE");
    return std::string("srun") + (mpi != nullptr && *mpi != '\0' ? " --mpi=" + shell_quote(mpi) : "") + " -n " + n +
           " ";
  }
  // More ranks than slots needs the flag again (mpirun passes it to the ranks as this variable).
  const bool oversubscribed = env_is("OMPI_MCA_rmaps_base_oversubscribe", "1") ||
                              env_is("OMPI_MCA_rmaps_base_oversubscribe", "true");
  return "mpirun -np " + n + (oversubscribed ? " --oversubscribe " : " ");
}

}  // namespace mpdem::cli
