#include "cli/run_paths.hpp"

#include <charconv>
#include <string>

#include "io/input_error.hpp"

namespace mpdem::cli {

namespace fs = std::filesystem;

void require_not_a_folder(const fs::path& file, std::string_view what, std::string_view inner) {
  std::error_code ec;
  if (!fs::is_directory(file, ec)) return;
  std::string msg = "is a directory, not a " + std::string(what);
  if (!inner.empty() && fs::is_regular_file(file / inner, ec)) msg += "; did you mean " + (file / inner).string() + "?";
  throw InputError(file.string(), 0, "", msg);
}

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
