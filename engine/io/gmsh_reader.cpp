#include "engine/io/gmsh_reader.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "engine/core/error.hpp"

namespace lunaster::engine {

namespace {

struct GmshType {
  int gmsh;
  CellType type;
  std::vector<int> to_med;  ///< med[to_med[k]] = gmsh[k]; empty = same order
};

/// Gmsh element types and the Gmsh -> MED node permutation (from the node
/// ordering section of the Gmsh manual and the MED reference cells).
const std::vector<GmshType>& gmsh_types() {
  static const std::vector<GmshType> types{
      {15, CellType::Point1, {}},
      {1, CellType::Seg2, {}},
      {8, CellType::Seg3, {}},
      {2, CellType::Tria3, {}},
      {9, CellType::Tria6, {}},
      {3, CellType::Quad4, {}},
      {16, CellType::Quad8, {}},
      {4, CellType::Tetra4, {0, 2, 1, 3}},
      {11, CellType::Tetra10, {0, 2, 1, 3, 6, 5, 4, 7, 8, 9}},
      {7, CellType::Pyram5, {0, 3, 2, 1, 4}},
      {6, CellType::Penta6, {0, 2, 1, 3, 5, 4}},
      {18, CellType::Penta15, {0, 2, 1, 3, 5, 4, 8, 6, 12, 7, 14, 13, 11, 9, 10}},
      {5, CellType::Hexa8, {0, 3, 2, 1, 4, 7, 6, 5}},
      {17, CellType::Hexa20, {0, 3, 2, 1, 4, 7, 6, 5, 11, 8, 16, 10, 19, 9, 18, 17, 15, 12, 14, 13}},
  };
  return types;
}

class GmshParser {
 public:
  GmshParser(const std::string& text, const std::string& source)
      : in_(text), source_(source), text_size_(static_cast<long long>(text.size())) {}
  Mesh parse();

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw DeckError("Gmsh file '" + source_ + "': " + what);
  }
  template <class T>
  T read(const char* what) {
    T value{};
    if (!(in_ >> value)) fail(std::string("truncated or malformed input in ") + section_ + " (expected " + what + ")");
    return value;
  }
  /// A count read from the file: negative or larger than what the rest of the
  /// input could hold is a malformed (or fuzzed) file, not an allocation to try.
  long long read_count(const char* what);
  void expect_end(const std::string& name);
  void skip_section(const std::string& name);
  void read_format();
  void read_physical_names();
  void read_entities();
  void read_nodes_22();
  void read_nodes_41();
  void read_elements_22();
  void read_elements_41();
  void add_element(long long tag, int gmsh_type, const std::vector<long long>& nodes, int dim, int physical);
  void add_element_group(int cell, int dim, int physical, CellType type);

  std::istringstream in_;
  std::string source_;
  long long text_size_ = 0;
  std::string section_ = "header";
  double version_ = 0.0;
  Mesh mesh_;
  std::unordered_map<long long, int> node_of_tag_;
  std::map<std::pair<int, int>, std::string> physical_names_;           ///< (dim, tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals_;    ///< (dim, entity) -> physical tags
  std::map<std::string, std::vector<int>> cell_groups_, node_groups_;
};

long long GmshParser::read_count(const char* what) {
  const long long n = read<long long>(what);
  const std::streamoff pos = in_.tellg();
  const long long left = pos < 0 ? 0 : text_size_ - static_cast<long long>(pos);
  if (n < 0 || n > left / 2 + 1)
    fail("malformed input in " + section_ + ": " + what + " " + std::to_string(n) + " is impossible for a file of " +
         std::to_string(text_size_) + " bytes (truncated or corrupt file?)");
  return n;
}

void GmshParser::expect_end(const std::string& name) {
  std::string token;
  if (!(in_ >> token)) fail("truncated input: missing $End" + name);
  if (token != "$End" + name) fail("expected $End" + name + ", got '" + token + "'");
}

void GmshParser::skip_section(const std::string& name) {
  std::string token;
  while (in_ >> token)
    if (token == "$End" + name) return;
  fail("truncated input: missing $End" + name);
}

void GmshParser::read_format() {
  section_ = "$MeshFormat";
  version_ = read<double>("version");
  const int file_type = read<int>("file type");
  read<int>("data size");
  if (file_type != 0) fail("binary Gmsh files are not supported (save as ASCII: Mesh.Binary = 0)");
  const bool v2 = version_ >= 2.0 && version_ < 2.25;
  const bool v41 = version_ > 4.05 && version_ < 4.15;
  if (!v2 && !v41) {
    std::ostringstream os;
    os << "unsupported format version " << version_ << " (supported: 2.2 and 4.1 ASCII)";
    fail(os.str());
  }
  expect_end("MeshFormat");
}

void GmshParser::read_physical_names() {
  section_ = "$PhysicalNames";
  const long long n = read_count("count");
  for (long long i = 0; i < n; ++i) {
    const int dim = read<int>("dimension");
    const int tag = read<int>("tag");
    std::string rest;
    std::getline(in_, rest);
    const auto a = rest.find('"'), b = rest.rfind('"');
    if (a == std::string::npos || b == a) fail("malformed physical name: " + rest);
    physical_names_[{dim, tag}] = rest.substr(a + 1, b - a - 1);
  }
  expect_end("PhysicalNames");
}

void GmshParser::read_entities() {
  section_ = "$Entities";
  int counts[4];
  for (int& c : counts) c = static_cast<int>(read_count("entity count"));
  for (int dim = 0; dim < 4; ++dim) {
    for (int i = 0; i < counts[dim]; ++i) {
      const int tag = read<int>("entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) read<double>("bounding box");
      const int n_phys = static_cast<int>(read_count("physical count"));
      auto& phys = entity_physicals_[{dim, tag}];
      for (int k = 0; k < n_phys; ++k) phys.push_back(read<int>("physical tag"));
      if (dim > 0) {
        const int n_bound = static_cast<int>(read_count("bounding entity count"));
        for (int k = 0; k < n_bound; ++k) read<int>("bounding entity");
      }
    }
  }
  expect_end("Entities");
}

void GmshParser::read_nodes_22() {
  section_ = "$Nodes";
  const long long n = read_count("node count");
  for (long long i = 0; i < n; ++i) {
    const long long tag = read<long long>("node tag");
    const double x = read<double>("x"), y = read<double>("y"), z = read<double>("z");
    if (!node_of_tag_.emplace(tag, mesh_.n_nodes()).second) fail("node tag " + std::to_string(tag) + " repeated");
    mesh_.add_node(x, y, z, "N" + std::to_string(tag));
  }
  expect_end("Nodes");
}

void GmshParser::read_nodes_41() {
  section_ = "$Nodes";
  const long long n_blocks = read_count("block count");
  read<long long>("node count");
  read<long long>("min tag");
  read<long long>("max tag");
  for (long long b = 0; b < n_blocks; ++b) {
    const int dim = read<int>("entity dimension");
    read<int>("entity tag");
    const int parametric = read<int>("parametric flag");
    const long long n = read_count("block size");
    std::vector<long long> tags(n);
    for (auto& t : tags) t = read<long long>("node tag");
    for (long long i = 0; i < n; ++i) {
      const double x = read<double>("x"), y = read<double>("y"), z = read<double>("z");
      for (int k = 0; parametric && k < dim; ++k) read<double>("parametric coordinate");
      if (!node_of_tag_.emplace(tags[i], mesh_.n_nodes()).second)
        fail("node tag " + std::to_string(tags[i]) + " repeated");
      mesh_.add_node(x, y, z, "N" + std::to_string(tags[i]));
    }
  }
  expect_end("Nodes");
}

void GmshParser::add_element_group(int cell, int dim, int physical, CellType type) {
  const auto it = physical_names_.find({dim, physical});
  const std::string name = it != physical_names_.end() ? it->second : "GM" + std::to_string(physical);
  cell_groups_[name].push_back(cell);
  if (type == CellType::Point1) node_groups_[name].push_back(mesh_.cell(cell)[0]);
}

void GmshParser::add_element(long long tag, int gmsh_type, const std::vector<long long>& nodes, int dim,
                             int physical) {
  const GmshType* info = nullptr;
  for (const auto& t : gmsh_types())
    if (t.gmsh == gmsh_type) info = &t;
  if (!info) fail("unsupported element type " + std::to_string(gmsh_type) + " (element " + std::to_string(tag) + ")");
  std::vector<int> med(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) {
    const auto it = node_of_tag_.find(nodes[k]);
    if (it == node_of_tag_.end())
      fail("element " + std::to_string(tag) + " refers to unknown node " + std::to_string(nodes[k]));
    med[info->to_med.empty() ? k : static_cast<size_t>(info->to_med[k])] = it->second;
  }
  const int cell = mesh_.add_cell(info->type, med, "M" + std::to_string(tag));
  if (physical > 0) add_element_group(cell, dim, physical, info->type);
}

void GmshParser::read_elements_22() {
  section_ = "$Elements";
  const long long n = read_count("element count");
  for (long long i = 0; i < n; ++i) {
    const long long tag = read<long long>("element tag");
    const int type = read<int>("element type");
    const int n_tags = static_cast<int>(read_count("tag count"));
    std::vector<int> tags(n_tags);
    for (int& t : tags) t = read<int>("element tag value");
    const GmshType* info = nullptr;
    for (const auto& t : gmsh_types())
      if (t.gmsh == type) info = &t;
    if (!info) fail("unsupported element type " + std::to_string(type) + " (element " + std::to_string(tag) + ")");
    std::vector<long long> nodes(cell_info(info->type).n_nodes);
    for (auto& v : nodes) v = read<long long>("element node");
    add_element(tag, type, nodes, cell_info(info->type).dim, n_tags > 0 ? tags[0] : 0);
  }
  expect_end("Elements");
}

void GmshParser::read_elements_41() {
  section_ = "$Elements";
  const long long n_blocks = read_count("block count");
  read<long long>("element count");
  read<long long>("min tag");
  read<long long>("max tag");
  for (long long b = 0; b < n_blocks; ++b) {
    const int dim = read<int>("entity dimension");
    const int entity = read<int>("entity tag");
    const int type = read<int>("element type");
    const long long n = read_count("block size");
    const GmshType* info = nullptr;
    for (const auto& t : gmsh_types())
      if (t.gmsh == type) info = &t;
    if (!info) fail("unsupported element type " + std::to_string(type));
    const auto phys_it = entity_physicals_.find({dim, entity});
    for (long long i = 0; i < n; ++i) {
      const long long tag = read<long long>("element tag");
      std::vector<long long> nodes(cell_info(info->type).n_nodes);
      for (auto& v : nodes) v = read<long long>("element node");
      add_element(tag, type, nodes, dim, 0);
      if (phys_it == entity_physicals_.end()) continue;
      for (int p : phys_it->second) add_element_group(mesh_.n_cells() - 1, dim, p, info->type);
    }
  }
  expect_end("Elements");
}

Mesh GmshParser::parse() {
  std::string token;
  bool have_format = false, have_elements = false;
  while (in_ >> token) {
    if (token == "$MeshFormat") {
      read_format();
      have_format = true;
    } else if (!have_format) {
      fail("not a Gmsh file (it does not start with $MeshFormat)");
    } else if (token == "$PhysicalNames") {
      read_physical_names();
    } else if (token == "$Entities") {
      read_entities();
    } else if (token == "$Nodes") {
      version_ < 3 ? read_nodes_22() : read_nodes_41();
    } else if (token == "$Elements") {
      version_ < 3 ? read_elements_22() : read_elements_41();
      have_elements = true;
    } else if (token.size() > 1 && token[0] == '$') {
      skip_section(token.substr(1));
    } else {
      fail("unexpected text '" + token + "' outside a section");
    }
  }
  if (!have_format) fail("empty file or not a Gmsh file");
  if (mesh_.n_nodes() == 0 || !have_elements) fail("no $Nodes or $Elements section (truncated file?)");
  for (auto& [name, cells] : cell_groups_) mesh_.add_to_cell_group(name, cells);
  // A named physical group without elements stays an (empty) group, so that a deck
  // using it is told "empty" rather than "unknown".
  for (const auto& [key, name] : physical_names_)
    if (!mesh_.cell_groups.count(name) && !mesh_.node_groups.count(name)) mesh_.cell_groups[name];
  for (auto& [name, nodes] : node_groups_) mesh_.add_to_node_group(name, nodes);
  mesh_.detect_dimension();
  return std::move(mesh_);
}

const GmshType& gmsh_type_of(CellType type) {
  for (const auto& t : gmsh_types())
    if (t.type == type) return t;
  throw InternalError("no Gmsh element type for " + std::string(cell_info(type).name));
}

}  // namespace

int gmsh_element_type(CellType type) { return gmsh_type_of(type).gmsh; }

const std::vector<int>& gmsh_to_med_order(CellType type) { return gmsh_type_of(type).to_med; }

Mesh read_gmsh_text(const std::string& text, const std::string& source) {
  GmshParser parser(text, source);
  return parser.parse();
}

Mesh read_gmsh(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw DeckError("Gmsh file '" + path + "': cannot be opened (no such file?)");
  std::ostringstream text;
  text << file.rdbuf();
  return read_gmsh_text(text.str(), path);
}

}  // namespace lunaster::engine
