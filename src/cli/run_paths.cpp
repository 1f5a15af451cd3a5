#include "cli/run_paths.hpp"

#include <charconv>
#include <string>

namespace mpdem::cli {

namespace fs = std::filesystem;

std::string check_thread_count(const std::string& text) {
  long long n = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, n);
  if (ec == std::errc() && ptr == end && n >= 1 && n <= kMaxThreads) return "";
  return "expected a whole number of threads from 1 to " + std::to_string(kMaxThreads) + ", got '" + text + "'";
}

std::string shell_quote(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                             "0123456789@%+=:,./_-") == std::string::npos;
  if (plain) return text;
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string resume_command(const std::string& program, const RunArgs& args, const fs::path& checkpoint) {
  // The folder the run wrote to, not the scene's default: a run given --output continues there.
  fs::path dir = checkpoint.parent_path();
  if (dir.empty()) dir = ".";
  std::string cmd = shell_quote(program) + " run " + shell_quote(args.scene.string()) + " --output " +
                    shell_quote(dir.string());
  if (args.threads > 0) cmd += " --threads " + std::to_string(args.threads);  // bitwise identical needs the same count
  if (args.quiet) cmd += " --quiet";
  return cmd + " --resume " + shell_quote(checkpoint.string());
}

}  // namespace mpdem::cli
