#pragma once
/// Output files are replaced atomically: the content goes to a temporary file beside
/// the target, which is renamed over the target only once complete. A run that fails
/// or is killed part-way leaves either the previous file or the new one, never a
/// truncated mix, and no temporary behind (on failure it is removed).
#include <filesystem>
#include <functional>
#include <ostream>

namespace lunaster::engine {

/// Writes `path` with `write`; throws DeckError naming the file if it cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

}  // namespace lunaster::engine
