#pragma once
// The MPI launcher that started the `mpdem` command, as the command printed on SIGINT/SIGTERM
// needs it: pasted, that command must start as many ranks again, through the same launcher
// (docs/parallel.md, "Stopping a run").
#include <string>

namespace mpdem::cli {

// The launcher command that starts `ranks` ranks as this run was started, with a trailing space:
// "mpirun -np 4 " (with "--oversubscribe" when the run was started with it), "srun -n 4 " under
// Slurm's srun; empty for one rank.
std::string launcher_command(int ranks);

}  // namespace mpdem::cli
