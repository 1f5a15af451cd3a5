#pragma once
// OpenMP's waiting policy for the command line (README "Threads and shared machines"). Threads
// that spin while they wait take the core from a partner that another process has already
// delayed; on a shared machine that made 2 threads slower than 1 (docs/benchmark.md "Shared
// machines"). GNU OpenMP reads its environment once, when the program is loaded, before main; so
// when the user has set neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT, mpdem sets
// OMP_WAIT_POLICY=passive and re-executes itself once (/proc/self/exe, same arguments, same
// process id) before anything else runs.
namespace mpdem::cli {

// Re-executes the program with the default set, unless the user chose a policy or it is set
// already. Returns only if no re-execution happened (or it failed: the run goes on as it is).
void apply_openmp_defaults(char** argv);

}  // namespace mpdem::cli
