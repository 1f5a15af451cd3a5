#include "cli/openmp_environment.hpp"

#include <unistd.h>

#include <cstdlib>

namespace mpdem::cli {

void apply_openmp_defaults(char** argv) {
  constexpr const char* kMarker = "MPDEM_OPENMP_DEFAULTS";  // set once applied: never loops
  if (std::getenv(kMarker) || std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  // With a binding asked for, GNU OpenMP has already bound this thread to the first place when
  // it loaded, and exec keeps that mask: the re-executed run would have one core for all threads.
  if (std::getenv("OMP_PROC_BIND") || std::getenv("OMP_PLACES") || std::getenv("GOMP_CPU_AFFINITY")) return;
  // Spin about a microsecond, then sleep (header).
  if (::setenv("GOMP_SPINCOUNT", "1000", 0) != 0 || ::setenv(kMarker, "1", 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // Not re-executed (no /proc): the variables stay set for child processes, this one goes on as it is.
}

}  // namespace mpdem::cli
