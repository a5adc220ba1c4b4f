#include "lua/export_file.hpp"

#include <fstream>
#include <set>
#include <sstream>

#include "engine/core/error.hpp"

namespace lunaster::lua {

namespace fs = std::filesystem;

namespace {

/// Data (D) or result (R) use of a file type, and what lunaster does with it.
struct FileType {
  const char* name;
  char direction;  ///< 'D' read, 'R' written
  const char* what;
  const char* as = nullptr;  ///< the type lunaster reads it as (a second name of a type), if any
  bool skipped = false;      ///< handed over by code_aster's runner but never read by the study
};

constexpr FileType kFileTypes[] = {
    {"comm", 'D', "the command file (unit 1), converted to Lua and run"},
    {"mmed", 'D', "a MED mesh, read by LIRE_MAILLAGE(UNITE=n, FORMAT='MED')"},
    {"med", 'D', "a MED mesh, as 'mmed'", "mmed"},
    {"msh", 'D', "a Gmsh mesh, read by LIRE_MAILLAGE(UNITE=n, FORMAT='GMSH')"},
    {"mail", 'D', "a mesh in code_aster's text format, read by LIRE_MAILLAGE(UNITE=n, FORMAT='ASTER')"},
    {"datg", 'D', "the script that generated the study's mesh (Gibi, SALOME), kept with the study for the record: "
                  "skipped, with a line in the log", nullptr, true},
    {"rmed", 'R', "a MED result file, written by IMPR_RESU(UNITE=n, FORMAT='MED') in the output folder"},
    {"resu", 'R', "a text result file, written by IMPR_RESU(UNITE=n, FORMAT='RESULTAT') in the output folder"},
    {"mess", 'R', "the message file: a copy of the run's log, in the output folder"},
};

DeckError export_error(const fs::path& file, int line, std::string message, std::vector<std::string> hints = {}) {
  DeckError error(std::move(message), std::move(hints));
  ErrorContext where;
  where.file = file.string();
  where.line = line;
  error.fill_context(where);
  return error;
}

std::string supported_list() {
  std::string out;
  for (const auto& t : kFileTypes)
    if (!t.skipped) out += std::string(out.empty() ? "" : ", ") + t.name + " (" + t.direction + ")";
  return out;
}

/// Why lunaster refuses a file type code_aster knows, where a hint helps.
std::string refusal_hint(const std::string& type) {
  if (type == "mgib" || type == "msup")
    return std::string(type == "mgib" ? "a Gibi" : "an I-DEAS universal") + " mesh, which code_aster reads with " +
           (type == "mgib" ? "PRE_GIBI" : "PRE_IDEAS") + ": convert it to MED (with code_aster: " +
           (type == "mgib" ? "PRE_GIBI" : "PRE_IDEAS") + ", LIRE_MAILLAGE, IMPR_RESU(FORMAT='MED'); or with Gmsh or " +
           "SALOME) and use 'F mmed'";
  if (type == "libr")
    return "a data file the study reads on its unit (LIRE_FONCTION, LIRE_TABLE, INCLUDE, an MFront behaviour ...): "
           "lunaster has no command that reads one";
  if (type == "nom")
    return "a file the study opens by its name (a Python module, a file read through code_aster's Python API): "
           "lunaster's commands read files through their units only";
  if (type == "base" || type == "bhdf") return "lunaster has no code_aster database: POURSUITE is not supported";
  if (type.size() == 4 && type.rfind("com", 0) == 0 && type[3] >= '0' && type[3] <= '9')
    return "continuation command files (POURSUITE) are not supported: put the commands in one .comm";
  return "";
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& export_file_types() {
  static const std::vector<std::pair<std::string, std::string>> types = [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& t : kFileTypes) out.emplace_back(t.name, t.what);
    return out;
  }();
  return types;
}

ExportFile read_export(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw DeckError("cannot open export file '" + file.string() + "'");
  ExportFile out;
  out.file = file;
  const fs::path folder = file.parent_path();
  std::set<std::string> seen_limits;
  int comm_line = 0;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty() || w[0][0] == '#') continue;
    if (w[0] == "P" || w[0] == "A") {
      if (w.size() < 2) throw export_error(file, line, "expected '" + w[0] + " NAME VALUE', got '" + text + "'");
      const std::string& name = w[1];
      if (w[0] == "P" && (name == "time_limit" || name == "memory_limit")) {
        if (w.size() != 3)
          throw export_error(file, line, "expected 'P " + name + " VALUE', got '" + text + "'");
        const auto value = parse_budget_value(w[2]);
        if (!value)
          throw export_error(file, line, "P " + name + ": expected a positive number of " +
                                             (name == "time_limit" ? "seconds" : "MB") + ", got '" + w[2] + "'");
        if (!seen_limits.insert(name).second) throw export_error(file, line, "P " + name + " is given twice");
        (name == "time_limit" ? out.budget.seconds : out.budget.megabytes) = *value;
      } else {
        out.ignored.push_back(w[0] + " " + name);
      }
      continue;
    }
    if (w[0] == "R")
      throw export_error(file, line, "directory units ('R' lines) are not supported, got '" + text + "'",
                         {"give each file on its own 'F TYPE PATH D|R UNIT' line"});
    if (w[0] != "F")
      throw export_error(file, line, "expected a 'P', 'A' or 'F' line, got '" + text + "'");
    if (w.size() != 5)
      throw export_error(file, line, "expected 'F TYPE PATH D|R UNIT', got '" + text + "'",
                         {"paths with blanks are not supported"});
    const std::string& type = w[1];
    const std::string& direction = w[3];
    int unit = -1;
    try {
      std::size_t used = 0;
      unit = std::stoi(w[4], &used);
      if (used != w[4].size()) unit = -1;
    } catch (const std::exception&) {
      unit = -1;
    }
    if (unit < 0 || unit > 99) throw export_error(file, line, "expected a unit number 0..99, got '" + w[4] + "'");
    const fs::path path = fs::path(w[2]).is_absolute() ? fs::path(w[2]) : folder / w[2];
    const FileType* known = nullptr;
    for (const auto& t : kFileTypes)
      if (type == t.name) known = &t;
    if (known && known->skipped) {  // bound to no unit, and never opened
      out.skipped.push_back({type, path, line});
      continue;
    }
    if (!known) {
      std::vector<std::string> hints = {"lunaster reads the file types " + supported_list()};
      if (auto hint = refusal_hint(type); !hint.empty()) hints.insert(hints.begin(), hint);
      throw export_error(file, line, "file type '" + type + "' (unit " + w[4] + ") is not supported", hints);
    }
    if (direction != std::string(1, known->direction))
      throw export_error(file, line,
                         "file type '" + type + "': expected direction " + known->direction + ", got '" + direction + "'",
                         {std::string(known->direction == 'D' ? "a " + type + " file is read (D)"
                                                              : "a " + type + " file is written (R)")});
    ExportUnit entry{known->as ? known->as : type, path, line};
    if (type == "comm") {
      if (comm_line)
        throw export_error(file, line, "a second command file; the first is on line " + std::to_string(comm_line),
                           {"lunaster runs one .comm per study (no POURSUITE)"});
      if (unit != 1) throw export_error(file, line, "the command file is unit 1, got unit " + w[4]);
      comm_line = line;
      out.comm = path;
    } else {
      for (const auto* units : {&out.data, &out.results})
        if (auto clash = units->find(unit); clash != units->end())
          throw export_error(file, line,
                             "unit " + w[4] + " is given twice; first on line " + std::to_string(clash->second.line));
      (known->direction == 'D' ? out.data : out.results)[unit] = entry;
    }
    if (known->direction == 'D' && !fs::is_regular_file(path))
      throw export_error(file, line, "data file '" + path.string() + "' does not exist",
                         {"paths are relative to the .export's folder"});
  }
  if (!comm_line) throw export_error(file, 0, "no command file: expected a line 'F comm NAME.comm D 1'");
  return out;
}

}  // namespace lunaster::lua
