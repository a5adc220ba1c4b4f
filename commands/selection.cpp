#include "commands/selection.hpp"

#include <algorithm>

#include "commands/parts.hpp"

namespace lunaster::cmd {

namespace {

template <class Map>
std::vector<std::string> keys_of(const Map& map) {
  std::vector<std::string> keys;
  for (const auto& kv : map) keys.push_back(kv.first);
  return keys;
}

std::vector<std::string> suggestion(const std::string& given, const std::vector<std::string>& names) {
  const std::string best = catalog::closest_name(given, names);
  if (!best.empty()) return {"did you mean '" + best + "'?"};
  std::string list;
  for (size_t i = 0; i < names.size() && i < 12; ++i) list += (i ? ", " : "") + names[i];
  if (names.size() > 12) list += ", ...";
  return {"the mesh has: " + (list.empty() ? std::string("none") : list)};
}

void merge(std::vector<int>& into, const std::vector<int>& more) {
  into.insert(into.end(), more.begin(), more.end());
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

bool declared_and_present(const catalog::Args& args, const std::string& kw) {
  return args.declares(kw) && args.has(kw);
}

/// A cell or node `name` at `kw`, `found` in `mesh` or not. On a part, one another rank holds is
/// not here: the ranks decide whether it exists (and a part's names are too few to suggest from).
void require_name(const catalog::Args& args, const std::string& kw, const engine::Mesh& mesh, bool found,
                  const std::string& expected, const std::string& name, const std::vector<std::string>& names) {
  if (found) return require_somewhere(mesh, true, DeckError(""));
  require_somewhere(mesh, false,
                    args.error(kw, expected, "'" + name + "'",
                               mesh.is_part ? std::vector<std::string>{} : suggestion(name, names)));
}

}  // namespace

const std::vector<int>& cell_group(const catalog::Args& args, const std::string& kw, const engine::Mesh& mesh,
                                   const std::string& group) {
  auto it = mesh.cell_groups.find(group);
  if (it == mesh.cell_groups.end())
    throw args.error(kw, "a cell group of the mesh", "'" + group + "'", suggestion(group, keys_of(mesh.cell_groups)));
  // A part holds every group, maybe empty: whether the group is empty is the whole mesh's.
  const bool filled = !it->second.empty();
  const std::string given = "'" + group + "', which is empty";
  require_somewhere(mesh, filled, filled ? DeckError("") : args.error(kw, "a non-empty cell group", given));
  return it->second;
}

std::vector<int> node_group(const catalog::Args& args, const std::string& kw, const engine::Mesh& mesh,
                            const std::string& group) {
  auto it = mesh.node_groups.find(group);
  if (it != mesh.node_groups.end()) {
    const bool filled = !it->second.empty();
    const std::string given = "'" + group + "', which is empty";
    require_somewhere(mesh, filled, filled ? DeckError("") : args.error(kw, "a non-empty node group", given));
    return it->second;
  }
  auto cit = mesh.cell_groups.find(group);
  if (cit != mesh.cell_groups.end()) return mesh.nodes_of_cells(cit->second);
  // GROUP_NO also accepts cell groups (their nodes): suggest among both.
  std::vector<std::string> names = keys_of(mesh.node_groups);
  for (const auto& [name, cells] : mesh.cell_groups)
    if (!mesh.node_groups.count(name)) names.push_back(name);
  throw args.error(kw, "a node group of the mesh", "'" + group + "'", suggestion(group, names));
}

namespace {

/// Cells named by GROUP_MA and/or MAILLE (whichever the spec declares), unsorted.
std::vector<int> named_cells(const catalog::Args& args, const engine::Mesh& mesh) {
  std::vector<int> cells;
  if (declared_and_present(args, "GROUP_MA"))
    for (const auto& g : args.texts("GROUP_MA")) merge(cells, cell_group(args, "GROUP_MA", mesh, g));
  if (declared_and_present(args, "MAILLE"))
    for (const auto& name : args.texts("MAILLE")) {
      const int c = mesh.find_cell(name);
      require_name(args, "MAILLE", mesh, c >= 0, "a cell name of the mesh", name, mesh.cell_names);
      if (c >= 0) cells.push_back(c);
    }
  return cells;
}

}  // namespace

std::vector<int> select_cells(const catalog::Args& args, const engine::Mesh& mesh) {
  std::vector<int> cells;
  if (declared_and_present(args, "TOUT")) {
    cells.resize(mesh.n_cells());
    for (int c = 0; c < mesh.n_cells(); ++c) cells[c] = c;
    return cells;
  }
  cells = named_cells(args, mesh);
  sort_unique(cells);
  return cells;
}

std::vector<int> select_nodes(const catalog::Args& args, const engine::Mesh& mesh) {
  std::vector<int> nodes;
  if (declared_and_present(args, "TOUT")) {
    nodes.resize(mesh.n_nodes());
    for (int n = 0; n < mesh.n_nodes(); ++n) nodes[n] = n;
    return nodes;
  }
  if (declared_and_present(args, "GROUP_NO"))
    for (const auto& g : args.texts("GROUP_NO")) merge(nodes, node_group(args, "GROUP_NO", mesh, g));
  if (declared_and_present(args, "NOEUD"))
    for (const auto& name : args.texts("NOEUD")) {
      const int n = mesh.find_node(name);
      if (n < 0 && mesh.node_groups.count(name))  // every part holds every group: the same on every rank
        throw args.error("NOEUD", "a node name of the mesh", "'" + name + "'",
                         {"'" + name + "' is a node group: use GROUP_NO = '" + name + "'"});
      require_name(args, "NOEUD", mesh, n >= 0, "a node name of the mesh", name, mesh.node_names);
      if (n >= 0) nodes.push_back(n);
    }
  if (declared_and_present(args, "GROUP_MA") || declared_and_present(args, "MAILLE"))
    merge(nodes, mesh.nodes_of_cells(named_cells(args, mesh)));
  sort_unique(nodes);
  return nodes;
}

}  // namespace lunaster::cmd
