#include "scene/input_paths.hpp"

#include <string>

#include "core/input_file.hpp"

namespace mpdem {

std::filesystem::path existing_file(const TomlSection& s, std::string_view k, const std::filesystem::path& dir) {
  const std::string name = s.require(s.string(k), k);
  if (name.empty()) s.fail(k, "expected a file name, got an empty string");
  std::filesystem::path p = (dir / std::filesystem::path(name)).lexically_normal();
  if (const std::string why = input_file_problem(p); !why.empty()) s.fail(k, "file '" + p.string() + "' " + why);
  return p;
}

}  // namespace mpdem
