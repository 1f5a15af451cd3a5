#pragma once
// Why a path given where an input file is expected cannot be read as one, for the readers'
// messages: a folder named by mistake is told apart from a missing file.
#include <filesystem>
#include <string>
#include <system_error>

namespace mpdem {

// "" for a regular file (or a link to one), else "does not exist", "is a directory, expected a
// file", "is not a regular file" or "cannot be accessed (reason)"; to follow "file 'name' ".
inline std::string input_file_problem(const std::filesystem::path& p) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(p, ec);
  if (std::filesystem::is_regular_file(st)) return "";
  if (std::filesystem::is_directory(st)) return "is a directory, expected a file";
  if (st.type() == std::filesystem::file_type::not_found) return "does not exist";
  if (ec) return "cannot be accessed (" + ec.message() + ")";
  return "is not a regular file";
}

}  // namespace mpdem
