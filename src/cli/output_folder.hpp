#pragma once
// The rule that two runs never mix their outputs silently: a run writes into a fresh or empty
// folder, or, with --overwrite, first removes the previous run's outputs (only the files and
// folders mpdem writes; anything else in the folder is left alone).
#include <filesystem>

namespace mpdem::cli {

// Throws InputError when `dir` holds files and overwrite is false. With overwrite, removes the
// outputs of an earlier run. Then ensure_output_folder (io/output_folder.hpp).
void prepare_output_folder(const std::filesystem::path& dir, bool overwrite);

}  // namespace mpdem::cli
