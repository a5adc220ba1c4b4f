#pragma once
/// code_aster's `.export` study description, as its batch runner reads it: `P` lines
/// (parameters: time_limit, memory_limit ...), `A` lines (old-style arguments), and `F`
/// lines that bind a file to a logical unit (`F mmed mesh.med D 20`: data file, unit 20;
/// `F rmed out.rmed R 80`: result file, unit 80). lunaster honours the command file, the
/// mesh and result units and the two limits; a file the study never reads (`F datg`: the
/// script that made the mesh) is skipped; a file type it cannot read or write is an error
/// naming the line (docs/code_aster-files.md has the table).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "lua/budget.hpp"

namespace lunaster::lua {

/// One `F` line that lunaster honours.
struct ExportUnit {
  std::string type;             ///< mmed, msh, rmed, resu, mess
  std::filesystem::path path;   ///< as resolved: data files relative to the .export's folder
  int line = 0;                 ///< line in the .export
};

struct ExportFile {
  std::filesystem::path file;       ///< the .export itself
  std::filesystem::path comm;       ///< the command file (`F comm NAME D 1`)
  std::map<int, ExportUnit> data;   ///< D units: meshes read by LIRE_MAILLAGE(UNITE=...)
  std::map<int, ExportUnit> results;  ///< R units: files written by IMPR_RESU(UNITE=...); `mess` is the log
  Budget budget;                    ///< `P time_limit` (s), `P memory_limit` (MB)
  std::vector<std::string> ignored; ///< parameters read and not used ("P testlist", "A memjeveux" ...)
  std::vector<ExportUnit> skipped;  ///< files the study never reads (`F datg`), in the order of their lines
};

/// Reads an .export file. Throws DeckError naming `file:line` for a malformed line, a file
/// type lunaster does not handle (with the list of those it does, and what to do for the
/// types code_aster's tests use: mail, mgib, msup, libr, nom, base, com1...), a unit given twice, a
/// missing or second command file, a data file that does not exist, or a limit that is
/// not a positive number.
ExportFile read_export(const std::filesystem::path& file);

/// The types of `F` lines read or skipped, with what each is for (for messages and docs).
const std::vector<std::pair<std::string, std::string>>& export_file_types();

}  // namespace lunaster::lua
