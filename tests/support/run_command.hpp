#pragma once
// Runs the mpdem executable (MPDEM_BINARY) with arguments and captures exit status and output.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mpdem::test {

struct CommandResult {
  int status = -1;  // exit status
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline CommandResult run_mpdem(const std::string& args, const std::filesystem::path& workdir) {
  const auto out = workdir / "cmd_stdout.txt", err = workdir / "cmd_stderr.txt";
  const std::string cmd = std::string("cd '") + workdir.string() + "' && '" + MPDEM_BINARY + "' " + args + " >'" +
                          out.string() + "' 2>'" + err.string() + "' </dev/null";
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// A fresh, empty temporary folder named after the test.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("mpdem_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

inline void write_text(const std::filesystem::path& f, const std::string& text) { std::ofstream(f) << text; }

}  // namespace mpdem::test
