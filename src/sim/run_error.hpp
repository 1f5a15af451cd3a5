#pragma once
// RunError: a run that cannot continue (non-convergence, instability, a particle leaving the
// domain with on_exit = "stop"). The CLI prints the message and exits with status 1.
#include <stdexcept>
#include <string>

namespace mpdem {

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mpdem
