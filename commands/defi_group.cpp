// DEFI_GROUP: creates node groups (from cell groups, node lists, other groups' intersection,
// union or difference, or by geometry: a plane, a sphere's or cylinder's envelope, a segment, a
// line of cells) and cell groups.
#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <cstdio>
#include <set>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"

namespace lunaster::cmd {

namespace {

/// The members of several groups combined as code_aster's INTERSEC, UNION, DIFFE (sets).
std::vector<int> combine(const std::string& how, const std::vector<std::vector<int>>& groups) {
  std::set<int> out(groups.front().begin(), groups.front().end());
  for (size_t g = 1; g < groups.size(); ++g) {
    const std::set<int> other(groups[g].begin(), groups[g].end());
    if (how == "UNION") {
      out.insert(other.begin(), other.end());
    } else {
      for (auto it = out.begin(); it != out.end();) {
        const bool in_other = other.count(*it) > 0;
        it = (how == "INTERSEC" ? !in_other : in_other) ? out.erase(it) : std::next(it);
      }
    }
  }
  return {out.begin(), out.end()};
}

/// The one node of a one-node group (GROUP_NO_ORIG, GROUP_NO_EXTR).
int single_node(const Args& occ, const std::string& kw, const engine::Mesh& mesh) {
  const auto nodes = node_group(occ, kw, mesh, occ.text(kw));
  if (nodes.size() != 1)
    throw occ.error(kw, "a group of one node", "'" + occ.text(kw) + "', of " + std::to_string(nodes.size()) + " nodes");
  return nodes.front();
}

std::string distance_text(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", d);
  return buf;
}

/// A point or vector keyword of as many components as the mesh's dimension, as 3 coordinates.
std::array<double, 3> coordinates(const Args& occ, const std::string& kw, const engine::Mesh& mesh, int needed = 0) {
  const auto v = occ.reals(kw);
  const int dim = needed ? needed : mesh.dim;
  if (static_cast<int>(v.size()) != dim)
    throw occ.error(kw, std::to_string(dim) + " components (the mesh is " + std::to_string(mesh.dim) + "D)",
                    std::to_string(v.size()));
  return {v[0], v[1], v.size() > 2 ? v[2] : 0.0};
}

std::array<double, 3> unit(const Args& occ, const std::string& kw, std::array<double, 3> v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (n == 0.0) throw occ.error(kw, "a non-zero vector", "a zero vector");
  for (double& x : v) x /= n;
  return v;
}

/// PLAN, ENV_SPHERE, ENV_CYLINDRE: the nodes within PRECISION of the surface.
std::vector<int> geometric_nodes(const Args& occ, const std::string& option, const engine::Mesh& mesh) {
  if (option == "ENV_CYLINDRE" && mesh.dim != 3)
    throw occ.error("OPTION", "ENV_CYLINDRE on a 3D mesh", "a 2D mesh", {"in 2D, ENV_SPHERE gives a circle"});
  const auto p = coordinates(occ, "POINT", mesh);
  const double prec = occ.real("PRECISION");
  std::array<double, 3> n{};
  if (option == "PLAN") n = unit(occ, "VECT_NORMALE", coordinates(occ, "VECT_NORMALE", mesh));
  if (option == "ENV_CYLINDRE") n = unit(occ, "VECT_NORMALE", coordinates(occ, "VECT_NORMALE", mesh, 3));
  std::vector<int> nodes;
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    const double* x = mesh.node(i);
    const double d[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    const double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    double distance = 0.0;
    if (option == "PLAN") {
      distance = std::abs(along);
    } else {
      double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (option == "ENV_CYLINDRE") r2 -= along * along;
      distance = std::abs(std::sqrt(std::max(r2, 0.0)) - occ.real("RAYON"));
    }
    if (distance <= prec) nodes.push_back(i);
  }
  return nodes;
}

/// The given nodes (GROUP_NO, NOEUD), unsorted and without repeats, in their given order.
std::vector<int> given_nodes(const Args& occ, const engine::Mesh& mesh) {
  std::vector<int> nodes;
  if (occ.has("GROUP_NO"))
    for (const auto& g : occ.texts("GROUP_NO")) {
      const auto more = node_group(occ, "GROUP_NO", mesh, g);
      nodes.insert(nodes.end(), more.begin(), more.end());
    }
  if (occ.has("NOEUD"))
    for (const auto& name : occ.texts("NOEUD")) {
      const int i = mesh.find_node(name);
      if (i < 0) throw occ.error("NOEUD", "a node name of the mesh", "'" + name + "'");
      nodes.push_back(i);
    }
  std::vector<int> unique;
  for (int n : nodes)
    if (std::find(unique.begin(), unique.end(), n) == unique.end()) unique.push_back(n);
  return unique;
}

std::string node_list(const engine::Mesh& mesh, const std::vector<int>& nodes) {
  std::string out;
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (i == 6 && nodes.size() > 8) {
      out += " ... " + mesh.node_names[nodes.back()];
      break;
    }
    out += (i ? " " : "") + mesh.node_names[nodes[i]];
  }
  return out;
}

/// SEGM_DROI_ORDO: the nodes of GROUP_NO/NOEUD ordered by their abscissa on the segment from
/// GROUP_NO_ORIG to GROUP_NO_EXTR; as code_aster, a node farther from its line than PRECISION
/// (absolute, or relative to the segment's length), or outside the segment, is an alarm.
std::vector<int> segment_nodes(const Args& occ, const engine::Mesh& mesh, Session& session, bool say) {
  std::vector<int> nodes = given_nodes(occ, mesh);
  const double* a = mesh.node(single_node(occ, "GROUP_NO_ORIG", mesh));
  const double* b = mesh.node(single_node(occ, "GROUP_NO_EXTR", mesh));
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ab2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  if (ab2 == 0.0) throw occ.error("GROUP_NO_EXTR", "a node away from GROUP_NO_ORIG's", "the same point");
  const bool relative = occ.text("CRITERE") == "RELATIF";
  std::vector<std::pair<double, int>> abscissa;
  for (int n : nodes) {
    const double* m = mesh.node(n);
    const double am[3] = {m[0] - a[0], m[1] - a[1], m[2] - a[2]};
    const double c = (am[0] * ab[0] + am[1] * ab[1] + am[2] * ab[2]) / ab2;
    const double v[3] = {am[0] - c * ab[0], am[1] - c * ab[1], am[2] - c * ab[2]};
    const double off = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if ((relative ? off / std::sqrt(ab2) : off) > occ.real("PRECISION") && say)
      session.log().warning("DEFI_GROUP: SEGM_DROI_ORDO " + occ.texts("NOM").front() + ": node " + mesh.node_names[n] +
                            " is " + distance_text(off) + " away from the segment's line (PRECISION " +
                            distance_text(occ.real("PRECISION")) + (relative ? " relative" : "") + ")");
    const double am2 = am[0] * am[0] + am[1] * am[1] + am[2] * am[2];
    if ((c < 0.0 || am2 > ab2) && (am2 - ab2) / ab2 > 1e-15 && say)
      session.log().warning("DEFI_GROUP: SEGM_DROI_ORDO " + occ.texts("NOM").front() + ": node " + mesh.node_names[n] +
                            " lies outside the segment (abscissa " + distance_text(c) + " of its length)");
    abscissa.emplace_back(c, n);
  }
  std::stable_sort(abscissa.begin(), abscissa.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (size_t i = 0; i < abscissa.size(); ++i) nodes[i] = abscissa[i].second;
  return nodes;
}

/// NOEUD_ORDO: the nodes of a line of SEG2/SEG3 cells, in their order along it from
/// GROUP_NO_ORIG (an end of an open line; absent: the end of lowest number) to GROUP_NO_EXTR
/// (absent: the other end).
std::vector<int> line_nodes(const Args& occ, const engine::Mesh& mesh) {
  std::vector<int> cells;
  for (const auto& g : occ.texts("GROUP_MA")) {
    const auto& more = cell_group(occ, "GROUP_MA", mesh, g);
    cells.insert(cells.end(), more.begin(), more.end());
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  // Each cell joins its two ends; a SEG3's middle node lies between them.
  std::map<int, std::vector<int>> at_end;  // end node -> cells
  for (int c : cells) {
    const auto type = mesh.cell_types[static_cast<size_t>(c)];
    if (type != engine::CellType::Seg2 && type != engine::CellType::Seg3)
      throw occ.error("GROUP_MA", "line cells (SEG2, SEG3)",
                      "cell " + mesh.cell_names[static_cast<size_t>(c)] + ", a " + std::string(engine::cell_info(type).name));
    at_end[mesh.cell(c)[0]].push_back(c);
    at_end[mesh.cell(c)[1]].push_back(c);
  }
  std::vector<int> ends;
  for (const auto& [node, touching] : at_end) {
    if (touching.size() > 2)
      throw occ.error("GROUP_MA", "a line (each node joining at most two cells)",
                      "node " + mesh.node_names[static_cast<size_t>(node)] + " joining " + std::to_string(touching.size()) + " cells");
    if (touching.size() == 1) ends.push_back(node);
  }
  const bool closed = ends.empty();
  if (!closed && ends.size() != 2)
    throw occ.error("GROUP_MA", "one connected line", std::to_string(ends.size() / 2) + " separate lines");
  int start = closed ? at_end.begin()->first : ends.front();
  if (occ.has("GROUP_NO_ORIG")) {
    start = single_node(occ, "GROUP_NO_ORIG", mesh);
    if (!at_end.count(start) || (!closed && at_end[start].size() != 1))
      throw occ.error("GROUP_NO_ORIG", closed ? "a node joining two cells of the closed line" : "an end of the open line (" +
                                                   mesh.node_names[ends[0]] + " or " + mesh.node_names[ends[1]] + ")",
                      "'" + occ.text("GROUP_NO_ORIG") + "' (node " + mesh.node_names[start] + ")");
  }
  const int stop = occ.has("GROUP_NO_EXTR") ? single_node(occ, "GROUP_NO_EXTR", mesh) : -1;
  std::vector<int> nodes{start};
  std::set<int> used;
  int here = start;
  while (true) {
    int next_cell = -1;
    for (int c : at_end[here])
      if (!used.count(c)) next_cell = c;
    if (next_cell < 0 || (here == stop && here != start)) break;
    used.insert(next_cell);
    const int* cn = mesh.cell(next_cell);
    const int other = cn[0] == here ? cn[1] : cn[0];
    if (mesh.cell_types[static_cast<size_t>(next_cell)] == engine::CellType::Seg3) nodes.push_back(cn[2]);
    if (other != start) nodes.push_back(other);
    here = other;
    if (here == start) break;  // a closed line, once around
  }
  if (stop >= 0 && std::find(nodes.begin(), nodes.end(), stop) == nodes.end())
    throw occ.error("GROUP_NO_EXTR", "a node of the line GROUP_MA", "'" + occ.text("GROUP_NO_EXTR") + "' (node " +
                                                                        mesh.node_names[stop] + ")");
  return nodes;
}

/// GROUP_MA's nodes chosen by CRIT_NOEUD: all, the corners, or the mid-side nodes.
std::vector<int> cell_nodes(const Args& occ, const std::vector<int>& cells, const engine::Mesh& mesh) {
  const std::string crit = occ.text("CRIT_NOEUD");
  if (crit == "TOUS") return mesh.nodes_of_cells(cells);
  std::vector<int> nodes;
  for (int c : cells) {
    const auto& info = engine::cell_info(mesh.cell_types[static_cast<size_t>(c)]);
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
      if ((crit == "SOMMET") == (a < info.n_vertices) && crit != "CENTRE") nodes.push_back(mesh.cell(c)[a]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void add_nodes(const Args& occ, engine::Mesh& mesh, Session& session, bool say, const std::string& name,
               const std::vector<int>& nodes, const std::string& how) {
  require_somewhere(mesh, !nodes.empty(), occ.error("NOM", "a group of at least one node", "no node " + how + " for '" + name + "'"));
  mesh.add_to_node_group(name, nodes);
  if (say) session.log().info("  node group " + name + ": " + std::to_string(mesh.node_groups[name].size()) + " nodes");
}

void create_node_groups(const Args& occ, engine::Mesh& mesh, Session& session, bool say) {
  if (occ.has("OPTION")) {
    const std::string option = occ.text("OPTION"), name = occ.texts("NOM").front();
    if (occ.text("CRIT_NOEUD") != "TOUS")
      throw occ.error("CRIT_NOEUD", "'TOUS' with OPTION (CRIT_NOEUD chooses among GROUP_MA's nodes without OPTION)",
                      "'" + occ.text("CRIT_NOEUD") + "'");
    if (occ.texts("NOM").size() != 1) throw occ.error("NOM", "one name with OPTION", std::to_string(occ.texts("NOM").size()));
    if (option == "SEGM_DROI_ORDO" || option == "NOEUD_ORDO") {
      if (mesh.is_part)
        throw occ.error("OPTION", "an option settled on one rank's part of the mesh",
                        "'" + option + "' on a mesh in parts (its nodes may lie on several ranks)",
                        {"define the group on the whole mesh (before the mesh is divided) or with GROUP_MA/GROUP_NO"});
      const auto ordered = option == "NOEUD_ORDO" ? line_nodes(occ, mesh) : segment_nodes(occ, mesh, session, say);
      if (say) session.log().info("  " + option + " " + name + ", in order: " + node_list(mesh, ordered));
      add_nodes(occ, mesh, session, say, name, ordered, "on the line");
      return;
    }
    add_nodes(occ, mesh, session, say, name, geometric_nodes(occ, option, mesh), "within PRECISION of the surface");
    return;
  }
  if (occ.has("TOUT_GROUP_MA")) {
    const auto groups = mesh.cell_groups;  // copy: adding node groups does not touch it, but be explicit
    for (const auto& [name, cells] : groups) mesh.add_to_node_group(name, mesh.nodes_of_cells(cells));
    return;
  }
  if (occ.has("GROUP_MA")) {
    const auto groups = occ.texts("GROUP_MA");
    const std::vector<std::string> names = occ.has("NOM") ? occ.texts("NOM") : groups;
    if (names.size() != 1 && names.size() != groups.size())
      throw occ.error("NOM", "one name, or one per group of GROUP_MA (" + std::to_string(groups.size()) + ")",
                      std::to_string(names.size()) + " names");
    for (size_t i = 0; i < groups.size(); ++i) {
      const auto& cells = cell_group(occ, "GROUP_MA", mesh, groups[i]);
      const std::string name = names.size() == 1 ? names.front() : names[i];
      const auto nodes = cell_nodes(occ, cells, mesh);
      if (occ.text("CRIT_NOEUD") != "TOUS") {
        add_nodes(occ, mesh, session, say, name, nodes, "with CRIT_NOEUD='" + occ.text("CRIT_NOEUD") + "'");
        continue;
      }
      mesh.add_to_node_group(name, nodes);
      if (say)
        session.log().info("  node group " + name + ": " + std::to_string(mesh.node_groups[name].size()) + " nodes");
    }
    return;
  }
  if (occ.texts("NOM").size() != 1) throw occ.error("NOM", "one name", std::to_string(occ.texts("NOM").size()));
  const std::string name = occ.texts("NOM").front();
  for (const char* how : {"INTERSEC", "UNION", "DIFFE"}) {
    if (!occ.has(how)) continue;
    std::vector<std::vector<int>> groups;
    for (const auto& g : occ.texts(how)) groups.push_back(node_group(occ, how, mesh, g));
    add_nodes(occ, mesh, session, say, name, combine(how, groups), "left by " + std::string(how));
    return;
  }
  if (occ.has("NOEUD")) {
    std::vector<int> nodes;
    for (const auto& n : occ.texts("NOEUD")) {
      const int i = mesh.find_node(n);
      require_somewhere(mesh, i >= 0, occ.error("NOEUD", "a node name of the mesh", "'" + n + "'"));
      if (i >= 0) nodes.push_back(i);
    }
    mesh.add_to_node_group(name, nodes);
    return;
  }
  std::vector<int> nodes;
  for (const auto& g : occ.texts("GROUP_NO")) {
    auto more = node_group(occ, "GROUP_NO", mesh, g);
    nodes.insert(nodes.end(), more.begin(), more.end());
  }
  mesh.add_to_node_group(name, nodes);
}

std::vector<int> group_cells(const Args& occ, const engine::Mesh& mesh) {
  for (const char* how : {"INTERSEC", "UNION", "DIFFE"}) {
    if (!occ.has(how)) continue;
    std::vector<std::vector<int>> groups;
    for (const auto& g : occ.texts(how)) groups.push_back(cell_group(occ, how, mesh, g));
    return combine(how, groups);
  }
  return select_cells(occ, mesh);
}

}  // namespace

ConceptPtr defi_group(const Args& args, Session& session) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  // A mesh in parts: each rank makes the groups on its part (empty ones too, so that every part
  // holds every group), and rank 0 on the whole mesh as well, which it writes and logs.
  const std::vector<engine::Mesh*> meshes = ma->changed_meshes();
  for (engine::Mesh* mesh : meshes) {
    const bool say = mesh == meshes.back();
    for (const auto& occ : args.factors("CREA_GROUP_MA")) {
      const std::vector<int> cells = group_cells(occ, *mesh);
      require_somewhere(*mesh, !cells.empty(),
                        occ.error("NOM", "a selection of at least one cell", "an empty selection"));
      mesh->add_to_cell_group(occ.text("NOM"), cells);
    }
    for (const auto& occ : args.factors("CREA_GROUP_NO")) create_node_groups(occ, *mesh, session, say);
  }
  return ma;
}

}  // namespace lunaster::cmd
