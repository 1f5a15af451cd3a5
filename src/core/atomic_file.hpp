#pragma once
// Crash-safe file output. A snapshot is written to a temporary file beside its final name and
// renamed over it only when complete, so a killed run never leaves a truncated file under the
// final name (rename within one folder is atomic on POSIX). Logs that grow by rows use
// append_complete_lines instead: each call adds whole lines with one O_APPEND write, so a kill
// can at worst cut the last line of one flush, never interleave or lose earlier rows.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace mpdem {

// Name of the temporary file used while writing `path`: "<path>.tmp-<pid>" in the same folder.
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

// What a written file must survive. Both survive a killed run (the rename is atomic); only
// `power_loss` forces the data to disk first (fsync, milliseconds per file): checkpoints, which
// a resume depends on. Snapshots and indexes a run rewrites or adds to need only `kill`.
enum class Durability { power_loss, kill };

// Calls body(stream) on "<path>.tmp-<pid>", flushes it (and syncs it to disk for power_loss),
// checks the stream state, then renames it onto `path`. Throws std::runtime_error naming `path`
// if the file cannot be written; if body throws, its exception propagates. In both cases the
// temporary file is removed and any previous file at `path` is left untouched.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body,
                           Durability durability = Durability::power_loss);

// Appends `text` (expected to end in '\n') to `path`, creating the file if needed. The text is
// written with a single O_APPEND write loop and the descriptor closed before returning.
// Throws std::runtime_error naming `path` on failure.
void append_complete_lines(const std::filesystem::path& path, std::string_view text);

}  // namespace mpdem
