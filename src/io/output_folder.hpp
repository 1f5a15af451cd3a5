#pragma once
// An output folder that can be written: created when missing, refused with one clean message when
// it cannot be (used by the command line and the Python module before anything is written).
#include <filesystem>
#include <string_view>

namespace mpdem {

// Creates `dir` if needed; throws InputError (one clean message: exit 2 on the command line, a
// ValueError in Python) when it is a file, cannot be created (a part of the path is a file, a
// read-only file system, no permission, a name too long) or cannot be written into. `advice`
// ends the message (how the caller chooses another folder).
void ensure_output_folder(const std::filesystem::path& dir, std::string_view advice = "choose another with --output");

}  // namespace mpdem
