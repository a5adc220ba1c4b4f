#include "commands/session.hpp"

namespace lunaster::cmd {

std::filesystem::path Session::resolve_input(const std::string& relative) const {
  std::filesystem::path p(relative);
  if (p.is_absolute()) return p;
  return deck_path.parent_path() / p;
}

std::filesystem::path Session::output_file(const std::string& name) const {
  std::filesystem::create_directories(output_dir);
  return output_dir / name;
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
