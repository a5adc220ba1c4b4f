#include "engine/io/aster_mail_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "engine/core/error.hpp"

namespace lunaster::engine {

namespace {

struct AsterType {
  const char* name;
  CellType type;
  std::vector<int> to_med;  ///< med[to_med[k]] = aster[k]; empty = same order
};

/// code_aster's node orders against MED's (code_aster's MED reader applies the
/// same permutations): the 3D cells list their base the other way round.
const std::vector<AsterType>& aster_types() {
  static const std::vector<AsterType> types{
      {"POI1", CellType::Point1, {}},
      {"SEG2", CellType::Seg2, {}},
      {"SEG3", CellType::Seg3, {}},
      {"TRIA3", CellType::Tria3, {}},
      {"TRIA6", CellType::Tria6, {}},
      {"QUAD4", CellType::Quad4, {}},
      {"QUAD8", CellType::Quad8, {}},
      {"TETRA4", CellType::Tetra4, {0, 2, 1, 3}},
      {"TETRA10", CellType::Tetra10, {0, 2, 1, 3, 6, 5, 4, 7, 9, 8}},
      {"PYRAM5", CellType::Pyram5, {0, 3, 2, 1, 4}},
      {"PENTA6", CellType::Penta6, {0, 2, 1, 3, 5, 4}},
      {"PENTA15", CellType::Penta15, {0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9}},
      {"HEXA8", CellType::Hexa8, {0, 3, 2, 1, 4, 7, 6, 5}},
      {"HEXA20", CellType::Hexa20, {0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 16, 19, 18, 17, 15, 14, 13, 12}},
  };
  return types;
}

/// code_aster cell types lunaster has no element for.
bool unsupported_aster_type(const std::string& k) {
  static const char* const names[] = {"SEG22", "SEG33", "SEG4", "TRIA33", "TRIA4", "TRIA7", "TRIA66", "QUAD44",
                                      "QUAD88", "QUAD9", "QUAD99", "TETRA15", "TETRA9", "PYRAM13", "PYRAM19",
                                      "PENTA18", "PENTA21", "PENTA7", "HEXA27", "HEXA9"};
  return std::find_if(std::begin(names), std::end(names), [&](const char* n) { return k == n; }) != std::end(names);
}

struct Token {
  std::string text;
  int line = 0;
  bool first = false;  ///< first token of its line
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

struct RawCell {
  std::string name;
  const AsterType* type;
  std::vector<const Token*> nodes;
  int line;
};

struct RawGroup {
  std::string name;
  bool cells;  ///< GROUP_MA (else GROUP_NO)
  std::vector<const Token*> members;
  int line;
};

class MailParser {
 public:
  MailParser(const std::string& text, const std::string& source) : source_(source) { tokenize(text); }
  Mesh parse();

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw DeckError("code_aster mesh file '" + source_ + "', line " + std::to_string(line) + ": " + what);
  }
  void tokenize(const std::string& text);
  bool at_end() const { return pos_ >= toks_.size(); }
  bool is_finsf(const Token& t) const { return upper(t.text) == "FINSF"; }
  bool is_block_keyword(const Token& t) const;
  /// Skips the header items KEY=value after a block keyword; returns NOM's value.
  std::string read_header();
  /// Stops the block at FINSF (consumed); true there.
  bool block_end(const std::string& block, int start);
  void read_nodes(int dim, int start);
  void read_cells(const AsterType& type, int start);
  void read_group(bool cells, int start);
  /// Skips the rest of a block keyword's line (its header) and the KEY=value lines after it.
  void skip_header() {
    while (!at_end() && !toks_[pos_].first) ++pos_;
    read_header();
  }

  std::string source_;
  std::vector<Token> toks_;
  size_t pos_ = 0;
  Mesh mesh_;
  std::unordered_map<std::string, int> node_of_name_, node_line_;
  std::vector<RawCell> cells_;
  std::vector<RawGroup> groups_;
};

void MailParser::tokenize(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const auto c = line.find('%'); c != std::string::npos) line.resize(c);
    bool first = true;
    size_t i = 0;
    while (i < line.size()) {
      const unsigned char c = static_cast<unsigned char>(line[i]);
      if (std::isspace(c) || c == ',') {
        ++i;
        continue;
      }
      size_t j = i;
      if (c == '=') {
        j = i + 1;
      } else {
        while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])) && line[j] != '=' && line[j] != ',')
          ++j;
      }
      toks_.push_back({line.substr(i, j - i), number, first});
      first = false;
      i = j;
    }
  }
}

bool MailParser::is_block_keyword(const Token& t) const {
  const std::string k = upper(t.text);
  if (k == "FIN" || k == "TITRE" || k == "COOR_1D" || k == "COOR_2D" || k == "COOR_3D" || k == "GROUP_NO" ||
      k == "GROUP_MA")
    return true;
  for (const auto& a : aster_types())
    if (k == a.name) return true;
  return false;
}

std::string MailParser::read_header() {
  // code_aster's header items (its own files also write `NOM=` with no value).
  static const char* const keys[] = {"NOM", "NBOBJ", "NOBJ", "NBLIGE", "NBLIGT", "NUMIN", "NUMAX", "AUTEUR", "DATE"};
  std::string nom;
  while (pos_ + 1 < toks_.size() && toks_[pos_ + 1].text == "=") {
    const std::string key = upper(toks_[pos_].text);
    if (std::find_if(std::begin(keys), std::end(keys), [&](const char* k) { return key == k; }) == std::end(keys))
      break;
    const int line = toks_[pos_ + 1].line;
    pos_ += 2;
    if (pos_ < toks_.size() && toks_[pos_].line == line && toks_[pos_].text != "=") {
      if (key == "NOM") nom = toks_[pos_].text;
      ++pos_;
    }
  }
  return nom;
}

bool MailParser::block_end(const std::string& block, int start) {
  // `=` and `,` separate items as blanks do (code_aster's files write `M1 = N1 N2`).
  while (!at_end() && toks_[pos_].text == "=") ++pos_;
  if (at_end()) fail(start, block + " block has no FINSF (the file ends inside it)");
  const Token& t = toks_[pos_];
  if (is_finsf(t)) {
    ++pos_;
    return true;
  }
  if (t.first && upper(t.text) == "FIN") return true;  // FIN closes the block and the file, as in code_aster
  if (t.first && is_block_keyword(t))
    fail(t.line, block + " block opened at line " + std::to_string(start) + " has no FINSF before '" + t.text + "'");
  return false;
}

void MailParser::read_nodes(int dim, int start) {
  const std::string block = "COOR_" + std::to_string(dim) + "D";
  while (!block_end(block, start)) {
    const Token& name = toks_[pos_++];
    if (!name.first) fail(name.line, "'" + name.text + "': a node starts a line (a node of " + block + " takes " +
                                         std::to_string(dim) + " coordinates; too many on this line?)");
    double x[3] = {0, 0, 0};
    for (int k = 0; k < dim; ++k) {
      while (!at_end() && toks_[pos_].text == "=") ++pos_;
      if (at_end() || toks_[pos_].first || is_finsf(toks_[pos_]))
        fail(name.line, "node '" + name.text + "': " + block + " takes " + std::to_string(dim) + " coordinates, " +
                            std::to_string(k) + " given");
      std::string v = toks_[pos_].text;
      std::replace(v.begin(), v.end(), 'D', 'E');
      std::replace(v.begin(), v.end(), 'd', 'e');
      char* end = nullptr;
      x[k] = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0')
        fail(name.line, "node '" + name.text + "': coordinate '" + toks_[pos_].text + "' is not a number");
      ++pos_;
    }
    if (const auto [it, fresh] = node_line_.emplace(name.text, name.line); !fresh)
      fail(name.line, "node '" + name.text + "' defined twice (first at line " + std::to_string(it->second) + ")");
    node_of_name_[name.text] = mesh_.add_node(x[0], x[1], x[2], name.text);
  }
}

void MailParser::read_cells(const AsterType& type, int start) {
  const int n = cell_info(type.type).n_nodes;
  const std::string how = std::string(type.name) + " takes " + std::to_string(n) + " nodes";
  while (!block_end(type.name, start)) {
    const Token& name = toks_[pos_++];
    if (!name.first) {
      // The previous cell ended on this line: either this line has too many nodes, or the previous
      // cell's own line had too few and its last nodes were taken from this one.
      const RawCell* prev = cells_.empty() ? nullptr : &cells_.back();
      if (prev && prev->line != name.line && prev->nodes.back()->line == name.line) {
        size_t on_line = 0;
        for (const Token* t : prev->nodes) on_line += t->line == prev->line;
        const Token* first_taken = prev->nodes[on_line];
        fail(prev->line, "cell '" + prev->name + "': " + how + ", line " + std::to_string(prev->line) + " gives " +
                             std::to_string(on_line) + " (then '" + first_taken->text + "' of line " +
                             std::to_string(first_taken->line) + " was read as its node)");
      }
      fail(name.line, "'" + name.text + "' does not start a line: " + how + ", more given?");
    }
    RawCell cell{name.text, &type, {}, name.line};
    for (int k = 0; k < n; ++k) {
      while (!at_end() && toks_[pos_].text == "=") ++pos_;
      if (at_end() || is_finsf(toks_[pos_]))
        fail(name.line, "cell '" + name.text + "': " + how + ", " + std::to_string(k) + " given");
      cell.nodes.push_back(&toks_[pos_++]);
    }
    cells_.push_back(std::move(cell));
  }
}

void MailParser::read_group(bool cells, int start) {
  const std::string block = cells ? "GROUP_MA" : "GROUP_NO";
  RawGroup group{read_header(), cells, {}, start};
  if (group.name.empty()) {
    if (at_end() || is_finsf(toks_[pos_])) fail(start, block + " block without a group name");
    group.name = toks_[pos_++].text;
  }
  while (!block_end(block, start)) group.members.push_back(&toks_[pos_++]);
  groups_.push_back(std::move(group));
}

Mesh MailParser::parse() {
  bool fin = false;
  while (!at_end()) {
    const Token& t = toks_[pos_++];
    const std::string k = upper(t.text);
    if (k == "FIN") {
      fin = true;
      break;
    }
    if (k == "FINSF") continue;  // a block closed twice: code_aster reads on
    if (k == "TITRE") {
      while (!at_end() && !is_finsf(toks_[pos_])) ++pos_;
      if (at_end()) fail(t.line, "TITRE block has no FINSF (the file ends inside it)");
      ++pos_;
      continue;
    }
    if (k == "COOR_1D" || k == "COOR_2D" || k == "COOR_3D") {
      skip_header();
      read_nodes(k[5] - '0', t.line);
      continue;
    }
    if (k == "GROUP_NO" || k == "GROUP_MA") {
      read_group(k == "GROUP_MA", t.line);
      continue;
    }
    const AsterType* type = nullptr;
    for (const auto& a : aster_types())
      if (k == a.name) type = &a;
    if (type) {
      skip_header();
      read_cells(*type, t.line);
      continue;
    }
    if (unsupported_aster_type(k))
      fail(t.line, "cell type " + k + " is not supported (supported: POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, "
                   "TETRA4, TETRA10, PYRAM5, PENTA6, PENTA15, HEXA8, HEXA20)");
    fail(t.line, "unknown block '" + t.text +
                     "' (expected TITRE, COOR_1D, COOR_2D, COOR_3D, a cell type such as QUAD4, GROUP_NO, GROUP_MA or "
                     "FIN)");
  }
  const int last = toks_.empty() ? 1 : toks_.back().line;
  if (!fin) fail(last, "no FIN at the end of the file (truncated file?)");
  if (mesh_.n_nodes() == 0) fail(last, "no node (no COOR_2D or COOR_3D block)");
  if (cells_.empty()) fail(last, "no cell (no block of a cell type such as QUAD4)");

  std::unordered_map<std::string, int> cell_of_name, cell_line;
  for (const auto& c : cells_) {
    std::vector<int> med(c.nodes.size());
    for (size_t k = 0; k < c.nodes.size(); ++k) {
      const Token& node = *c.nodes[k];
      const auto it = node_of_name_.find(node.text);
      if (it == node_of_name_.end())
        fail(node.line, "cell '" + c.name + "' (" + c.type->name + ", line " + std::to_string(c.line) +
                            ") refers to unknown node '" + node.text + "'" +
                            (node.first && node.line != c.line ? std::string(" (a ") + c.type->name + " takes " +
                                                                     std::to_string(c.nodes.size()) +
                                                                     " nodes: too few on its line?)"
                                                               : ""));
      med[c.type->to_med.empty() ? k : static_cast<size_t>(c.type->to_med[k])] = it->second;
    }
    if (const auto [it, fresh] = cell_line.emplace(c.name, c.line); !fresh)
      fail(c.line, "cell '" + c.name + "' defined twice (first at line " + std::to_string(it->second) + ")");
    cell_of_name[c.name] = mesh_.add_cell(c.type->type, med, c.name);
  }
  for (const auto& g : groups_) {
    auto& names = g.cells ? cell_of_name : node_of_name_;
    std::vector<int> members;
    for (const Token* m : g.members) {
      const auto it = names.find(m->text);
      if (it == names.end())
        fail(m->line, std::string(g.cells ? "GROUP_MA" : "GROUP_NO") + " '" + g.name + "' (line " +
                          std::to_string(g.line) + ") names unknown " + (g.cells ? "cell" : "node") + " '" + m->text +
                          "'");
      members.push_back(it->second);
    }
    if (g.cells) {
      mesh_.cell_groups[g.name];
      mesh_.add_to_cell_group(g.name, members);
    } else {
      mesh_.node_groups[g.name];
      mesh_.add_to_node_group(g.name, members);
    }
  }
  mesh_.detect_dimension();
  return std::move(mesh_);
}

}  // namespace

const std::vector<int>& aster_to_med_order(CellType type) {
  for (const auto& t : aster_types())
    if (t.type == type) return t.to_med;
  throw InternalError("no code_aster cell type for " + std::string(cell_info(type).name));
}

Mesh read_aster_mail_text(const std::string& text, const std::string& source) {
  MailParser parser(text, source);
  return parser.parse();
}

Mesh read_aster_mail(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw DeckError("code_aster mesh file '" + path + "': cannot be opened (no such file?)");
  std::ostringstream text;
  text << file.rdbuf();
  return read_aster_mail_text(text.str(), path);
}

}  // namespace lunaster::engine
