#pragma once
// A file a scene key names, resolved against the scene file's folder and checked to be a readable
// regular file before any reader opens it (the message names the key, not a library's error).
#include <filesystem>
#include <string_view>

#include "io/toml_section.hpp"

namespace mpdem {

// The file named by string key k of s, relative to `dir` (absolute, normalised); fails at k for a
// missing key, an empty name, or a path that is not a readable file.
std::filesystem::path existing_file(const TomlSection& s, std::string_view k, const std::filesystem::path& dir);

}  // namespace mpdem
