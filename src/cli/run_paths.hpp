#pragma once
// The command line's numbers and paths: the --threads range, and the command that resumes an
// interrupted run (printed on SIGINT/SIGTERM, to be pasted into a shell as it is). A folder given
// as the scene or checkpoint is reported by their readers (core/input_file.hpp).
#include <filesystem>
#include <string>
#include <string_view>

#include "cli/commands.hpp"

namespace mpdem::cli {

inline constexpr int kMaxThreads = 1024;  // --threads upper bound (OpenMP threads)

// Empty when `text` is a whole number from 1 to kMaxThreads; else the message (CLI11 validator).
std::string check_thread_count(const std::string& text);
// `text` as one shell word: as it is when it holds only characters no shell treats specially,
// else in single quotes.
std::string shell_quote(const std::string& text);
// The command that resumes the run `args` (started as `program`) from `checkpoint`, in the folder
// the run wrote to and with its thread count; relative paths are relative to the same working folder.
std::string resume_command(const std::string& program, const RunArgs& args, const std::filesystem::path& checkpoint);

}  // namespace mpdem::cli
