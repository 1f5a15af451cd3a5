// The command line's OpenMP waiting policy (cli/openmp_environment.hpp): without a user choice
// mpdem runs with GOMP_SPINCOUNT=1000 (threads spin briefly, then sleep: on a shared machine 2
// threads stay within 1.3x of 1, docs/benchmark.md "Shared machines"); a
// user's OMP_WAIT_POLICY or GOMP_SPINCOUNT is kept. Observed through GNU OpenMP's own report of
// its settings (OMP_DISPLAY_ENV=verbose, printed when the runtime loads: once per execution).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

// The GOMP_SPINCOUNT values GNU OpenMP reported, one per load of the program, for `mpdem
// --version` run with the environment changes `env` (arguments of env(1)).
std::vector<std::string> spin_counts(const std::string& env) {
  const std::string cmd = "env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u MPDEM_OPENMP_DEFAULTS OMP_DISPLAY_ENV=verbose " +
                          env + " '" + MPDEM_BINARY + "' --version 2>&1";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  for (std::size_t n; pipe && (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  if (pipe) ::pclose(pipe);
  std::vector<std::string> counts;
  const std::string key = "GOMP_SPINCOUNT = '";
  for (auto at = out.find(key); at != std::string::npos; at = out.find(key, at + 1))
    counts.push_back(out.substr(at + key.size(), out.find('\'', at + key.size()) - at - key.size()));
  return counts;
}

}  // namespace

TEST(OpenMPEnvironment, ShortSpinUnlessTheUserChooses) {
  const std::vector<std::string> plain = spin_counts("");
  if (plain.empty()) GTEST_SKIP() << "not GNU OpenMP: no GOMP_SPINCOUNT in its OMP_DISPLAY_ENV report";
  // Loaded with the inherited environment, then re-executed with the short spin.
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain.back(), "1000");
  // A user's choice is left alone: no re-execution.
  EXPECT_EQ(spin_counts("GOMP_SPINCOUNT=5000"), std::vector<std::string>{"5000"});
  const std::vector<std::string> active = spin_counts("OMP_WAIT_POLICY=active");
  ASSERT_EQ(active.size(), 1u);
  EXPECT_NE(active.front(), "0");
  // A binding: GNU OpenMP bound the process at load and exec would keep its one-core mask, so
  // no re-execution (the user sets GOMP_SPINCOUNT beside the binding).
  EXPECT_EQ(spin_counts("OMP_PROC_BIND=close").size(), 1u);
  EXPECT_EQ(spin_counts("OMP_PLACES=cores").size(), 1u);
}
