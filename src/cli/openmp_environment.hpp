#pragma once
// OpenMP's waiting policy for the command line (README "Threads and shared machines"). Threads
// that spin long while they wait take the core from a partner that another process has already
// delayed; on a shared machine that made 2 threads slower than 1 (docs/benchmark.md "Shared
// machines"). Threads that sleep at once pay a wake-up at every parallel region, which on a
// virtual machine is expensive (docs/benchmark.md). A short spin (GOMP_SPINCOUNT=1000, about
// a microsecond) serves both. GNU OpenMP reads its environment once, when the program is loaded,
// before main; so when the user has set neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT, mpdem sets
// GOMP_SPINCOUNT=1000 and re-executes itself once (/proc/self/exe, same arguments, same process
// id) before anything else runs. Not when OMP_PROC_BIND, OMP_PLACES or GOMP_CPU_AFFINITY is set:
// the runtime has bound the process to one core at load, which exec would keep.
namespace mpdem::cli {

// Re-executes the program with the default set, unless the user chose a policy or it is set
// already. Returns only if no re-execution happened (or it failed: the run goes on as it is).
void apply_openmp_defaults(char** argv);

}  // namespace mpdem::cli
