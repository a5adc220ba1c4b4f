#include "engine/io/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <string>
#include <system_error>

#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

namespace fs = std::filesystem;

void replace_file_atomically(const fs::path& path, const std::function<void(const fs::path& temp)>& create) {
  // Every output file goes through here: under mpirun, rank 0 writes it and the other ranks,
  // which computed the same content, write nothing. A failure on rank 0 is its own error;
  // the end of the run gives every rank the worst exit status (lua/main.cpp).
  if (!parallel::writes_output()) return;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw DeckError("cannot write '" + path.string() + "': cannot create a file in '" + folder.string() +
                    "' (no such folder)");
  const fs::path temp = folder / ("." + path.filename().string() + ".tmp" + std::to_string(::getpid()));
  fs::remove(temp, ec);
  try {
    create(temp);
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  fs::rename(temp, path, ec);
  if (ec) {
    const std::string reason = ec.message();
    fs::remove(temp, ec);
    throw DeckError("cannot write '" + path.string() + "': cannot replace the file (" + reason + ")");
  }
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  replace_file_atomically(path, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw DeckError("cannot write '" + path.string() + "': cannot create a file in '" + temp.parent_path().string() + "'");
    write(out);
    out.flush();
    if (!out) throw DeckError("cannot write '" + path.string() + "' (disk full or file system error)");
  });
}

}  // namespace lunaster::engine
