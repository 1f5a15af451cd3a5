#pragma once
// RunError: a run that cannot continue (non-convergence, instability, a particle leaving the
// domain with on_exit = "stop"). The CLI prints the message and exits with status 1.
// On several ranks a RunError is thrown by every rank at the same point, with the same message
// (the decision is taken from values reduced over the ranks), so that rank 0 alone reports it;
// a failure one rank sees alone is another exception (docs/parallel.md, "Errors").
#include <stdexcept>
#include <cstdint>
#include <filesystem>
#include <string>

namespace mpdem {

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run stopped by SIGINT/SIGTERM after writing a checkpoint (empty when it writes no output).
class Interrupted : public RunError {
 public:
  Interrupted(int sig, double t, std::uint64_t n, std::filesystem::path file)
      : RunError("interrupted by signal " + std::to_string(sig)), signal(sig), time(t), step(n),
        checkpoint(std::move(file)) {}
  int signal;
  double time;  // s
  std::uint64_t step;
  std::filesystem::path checkpoint;
};

}  // namespace mpdem
