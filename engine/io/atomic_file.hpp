#pragma once
/// Output files are replaced atomically: the content goes to a temporary file beside
/// the target, which is renamed over the target only once complete. A run that fails
/// or is killed part-way leaves either the previous file or the new one, never a
/// truncated mix, and no temporary behind (on failure it is removed).
/// In a run of several MPI ranks only rank 0 writes: on the others both functions return
/// without calling the writer.
#include <filesystem>
#include <functional>
#include <ostream>

namespace lunaster::engine {

/// Calls `create(temp)` to write the whole file at `temp`, a path beside `path`, then
/// renames it over `path`. For writers that open files themselves (MED). Throws
/// DeckError naming `path` if its folder does not exist or the rename fails.
void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path& temp)>& create);

/// Writes `path` with `write` through a stream; throws DeckError naming the file if it
/// cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

}  // namespace lunaster::engine
