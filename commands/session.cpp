#include "commands/session.hpp"

#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

std::filesystem::path Session::resolve_input(const std::string& relative) const {
  std::filesystem::path p(relative);
  if (p.is_absolute()) return p;
  return deck_path.parent_path() / p;
}

std::filesystem::path Session::output_file(const std::string& name) const {
  // Under mpirun rank 0 writes the files (engine/io/atomic_file.hpp) and makes their folder.
  if (engine::parallel::writes_output()) std::filesystem::create_directories(output_dir);
  return output_dir / name;
}

std::filesystem::path Session::unit_output_file(int unit, const std::string& ext) const {
  if (const auto found = result_units.find(unit); found != result_units.end())
    return output_file(found->second.path.filename().string());
  return output_file(deck_path.stem().string() + "_" + std::to_string(unit) + "." + ext);
}

void Session::warn(const std::string& message) {
  std::string where;
  if (!current.file.empty()) where = current.file + ":" + std::to_string(current.line) + ": ";
  if (!current.command.empty()) where += current.command + ": ";
  log_.warning(where + message);
}

int Session::n_ok() const {
  int n = 0;
  for (const auto& t : tests) n += t.ok ? 1 : 0;
  return n;
}

int Session::n_nook() const { return static_cast<int>(tests.size()) - n_ok(); }

}  // namespace lunaster::cmd
