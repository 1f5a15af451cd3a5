#include "cli/openmp_environment.hpp"

#include <unistd.h>

#include <cstdlib>

namespace mpdem::cli {

void apply_openmp_defaults(char** argv) {
  constexpr const char* kMarker = "MPDEM_OPENMP_DEFAULTS";  // set once applied: never loops
  if (std::getenv(kMarker) || std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (::setenv("OMP_WAIT_POLICY", "passive", 0) != 0 || ::setenv(kMarker, "1", 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // Not re-executed (no /proc): the variables stay set for child processes, this one goes on as it is.
}

}  // namespace mpdem::cli
