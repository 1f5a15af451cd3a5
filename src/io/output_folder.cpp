#include "io/output_folder.hpp"

#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

#include "core/input_error.hpp"

namespace mpdem {

namespace fs = std::filesystem;

namespace {
// The reason of a failed file system call, with what it means for a folder path.
std::string reason(const std::error_code& ec) {
  if (ec == std::errc::not_a_directory) return "a part of the path is a file, not a folder";
  if (ec == std::errc::read_only_file_system) return "the file system is read-only";
  return ec.message();
}
}  // namespace

void ensure_output_folder(const fs::path& dir, std::string_view advice) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(dir.string(), 0, "", why + "; " + std::string(advice));
  };
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st)) refuse("the output folder is a file");
  if (!fs::exists(st)) {
    fs::create_directories(dir, ec);
    if (ec) refuse("cannot create the output folder (" + reason(ec) + ")");
  }
  // Writing and creating files needs both; access() also reports a read-only file system.
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    refuse("cannot write into the output folder (" + reason(std::error_code(errno, std::generic_category())) + ")");
}

}  // namespace mpdem
