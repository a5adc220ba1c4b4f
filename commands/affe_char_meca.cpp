// AFFE_CHAR_MECA: imposed displacements, linear relations, pressures, distributed and nodal
// forces, gravity and (seed syntax) contact.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/contact_keywords.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/bytes.hpp"
#include "engine/fe/point_location.hpp"
#include "engine/fe/shape.hpp"
#include "engine/mesh/orientation.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

struct ComponentKeyword {
  const char* name;
  int component;
};

void read_ddl_impo(const Args& occ, const Modele& mo, CharMeca& load) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  const std::vector<int> nodes = select_nodes(occ, mesh);
  bool any = false;
  for (ComponentKeyword ck : {ComponentKeyword{"DX", engine::DX}, {"DY", engine::DY}, {"DZ", engine::DZ}}) {
    if (!occ.has(ck.name)) continue;
    if (ck.component == engine::DZ && mo.dim == 2)
      throw occ.error("DZ", "DX or DY in a 2D model", "DZ");
    any = true;
    const double value = occ.real(ck.name);
    for (int n : nodes) load.dirichlet.push_back({n, ck.component, value, 0});
  }
  if (!any) throw occ.error("DX", "at least one of DX, DY, DZ", "none");
}

/// VERI_NORM = 'OUI': which way the cells of one group of a PRES_REP occurrence (or its MAILLE
/// cells, or TOUT's) face the body they bound. On a mesh in parts each cell is counted by the
/// rank owning its first node (which holds it and its volume cells), and the counts are summed
/// over the ranks after the occurrences are read (check_pressure_facing).
struct PressureFacing {
  Args occ;
  std::string kw;     ///< GROUP_MA, MAILLE or TOUT
  std::string group;  ///< the group's name (GROUP_MA)
  double inward = 0.0, outward = 0.0;
  std::vector<std::pair<int, std::string>> first_inward;  ///< whole mesh's number and name, the first 3
};

/// Keeps the first three of `unit`'s inward cells, in the whole mesh's order.
void keep_first_inward(PressureFacing& unit) {
  std::sort(unit.first_inward.begin(), unit.first_inward.end());
  if (unit.first_inward.size() > 3) unit.first_inward.resize(3);
}

void count_facing(const Modele& mo, const std::vector<int>& cells, PressureFacing& unit) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  std::vector<int> checked;
  for (int c : cells)
    if (mo.dim == mesh.dim && engine::is_boundary_type(mesh.cell_types[c], mesh.dim)) checked.push_back(c);
  const engine::MeshPart* part = mo.in_parts() ? mo.maillage->part.get() : nullptr;
  const std::vector<engine::BoundaryFacing> facing = engine::boundary_facing(mesh, checked);
  for (size_t i = 0; i < checked.size(); ++i) {
    const int c = checked[i];
    if (part && !part->owns(mesh.cell(c)[0])) continue;
    // A cell between two cells of the mesh has no outside, one on no cell no body: unchecked.
    if (facing[i].side == engine::BoundarySide::Outward) unit.outward += 1.0;
    if (facing[i].side != engine::BoundarySide::Inward) continue;
    unit.inward += 1.0;
    unit.first_inward.emplace_back(part ? part->global_cell[c] : c, mesh.cell_names[c]);
  }
  keep_first_inward(unit);
}

void read_pres_rep(const Args& occ, const Modele& mo, CharMeca& load, std::vector<PressureFacing>* facing) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  std::vector<int> cells;
  for (int c : select_cells(occ, mesh))
    if (engine::cell_info(mesh.cell_types[c]).dim == mo.dim - 1) cells.push_back(c);
  // On a part, the boundary cells may all be on other ranks: the ranks decide.
  require_somewhere(mesh, !cells.empty(),
                    occ.error("GROUP_MA",
                              "boundary cells (" + std::string(mo.dim == 2 ? "SEG2/SEG3" : "TRIA/QUAD") + ")",
                              "a selection without any"));
  load.pressures.push_back({cells, occ.real("PRES"), 0});
  if (!facing) return;
  if (occ.has("GROUP_MA")) {
    for (const auto& name : occ.texts("GROUP_MA")) {
      facing->push_back({occ, "GROUP_MA", name, 0.0, 0.0, {}});
      count_facing(mo, cell_group(occ, "GROUP_MA", mesh, name), facing->back());
    }
  } else {
    facing->push_back({occ, occ.has("MAILLE") ? "MAILLE" : "TOUT", "", 0.0, 0.0, {}});
    count_facing(mo, cells, facing->back());
  }
}

/// VERI_NORM = 'OUI': a pressure on cells whose normal points into their body (it would pull
/// where the deck means to push) is an error, and so are the cells of one group facing both
/// ways. On a mesh in parts the counts are the whole mesh's (collective: every rank has the
/// same units and decides alike).
void check_pressure_facing(std::vector<PressureFacing>& units, const Modele& mo) {
  if (units.empty()) return;  // alike on every rank: the same occurrences and groups
  if (mo.in_parts()) {
    // Each rank's counts and first inward cells (unit, number; names one a line), gathered.
    std::vector<double> counts;
    std::vector<int> numbers;
    std::string names;
    for (size_t i = 0; i < units.size(); ++i) {
      counts.push_back(units[i].inward), counts.push_back(units[i].outward);
      for (const auto& [number, name] : units[i].first_inward)
        numbers.insert(numbers.end(), {static_cast<int>(i), number}), names += name + '\n';
      units[i].first_inward.clear();
    }
    engine::parallel::sum_over_ranks(counts.data(), static_cast<long long>(counts.size()));
    const std::vector<int> all_numbers = engine::parallel::gather_all(numbers);
    const std::string all_names = engine::parallel::gather_all(names);
    size_t at = 0;
    for (size_t k = 0; k + 1 < all_numbers.size(); k += 2) {
      const size_t end = all_names.find('\n', at);
      units[all_numbers[k]].first_inward.emplace_back(all_numbers[k + 1], all_names.substr(at, end - at));
      at = end + 1;
    }
    for (size_t i = 0; i < units.size(); ++i) {
      units[i].inward = counts[2 * i], units[i].outward = counts[2 * i + 1];
      keep_first_inward(units[i]);
    }
  }
  for (const PressureFacing& u : units) {
    if (u.inward == 0.0) continue;
    const long inward = std::lround(u.inward), outward = std::lround(u.outward);
    std::string names;
    for (const auto& cell : u.first_inward) names += (names.empty() ? "" : ", ") + cell.second;
    if (inward > 3) names += ", ...";
    const std::string what = u.kw == "GROUP_MA" ? "group '" + u.group + "'"
                             : u.kw == "MAILLE" ? std::string("the cells of MAILLE")
                                                : std::string("the boundary cells of the mesh");
    const std::string given =
        what + ": " + std::to_string(inward) + " of " + std::to_string(inward + outward) +
        " cells point into their body (" + names + ")" +
        (outward ? ", " + std::to_string(outward) + " out of it: mixed orientation" : std::string());
    const std::string mesh_name = mo.maillage->user_name.empty() ? "MA" : mo.maillage->user_name;
    const std::string orie = mo.dim == 3 ? "ORIE_PEAU_3D" : "ORIE_PEAU_2D";
    std::vector<std::string> hints;
    if (u.kw == "GROUP_MA")
      hints.push_back("orient them outward after reading the mesh: " + mesh_name + " = MODI_MAILLAGE{ reuse = " +
                      mesh_name + ", MAILLAGE = " + mesh_name + ", " + orie + " = _F{ GROUP_MA = '" + u.group +
                      "' } }");
    else
      hints.push_back("gather them in a group (DEFI_GROUP CREA_GROUP_MA) and orient it outward: MODI_MAILLAGE " +
                      orie + " = _F{ GROUP_MA = ... }");
    hints.push_back("VERI_NORM = 'NON' applies the pressure on the cells as they are (pulling on those that point "
                    "inward)");
    throw u.occ.error(u.kw, "boundary cells whose normal points out of the body they bound (VERI_NORM = 'OUI')",
                      given, hints);
  }
}

void read_force_nodale(const Args& occ, const Modele& mo, CharMeca& load) {
  const std::vector<int> nodes = select_nodes(occ, *mo.maillage->mesh);
  for (ComponentKeyword ck : {ComponentKeyword{"FX", engine::DX}, {"FY", engine::DY}, {"FZ", engine::DZ}}) {
    if (!occ.has(ck.name)) continue;
    const double value = occ.real(ck.name);
    for (int n : nodes) load.forces.push_back({n, ck.component, value, 0});
  }
}

/// FORCE_CONTOUR, FORCE_FACE, FORCE_ARETE, FORCE_INTERNE and PESANTEUR: a force density on the
/// selected cells of one dimension, refused (with code_aster's reason) on a model they do not apply to.
struct DistributedKeyword {
  const char* name;
  int model_dim;       ///< 2 or 3: the only models it applies to; 0: every model
  int cells_below;     ///< the loaded cells' dimension is the model's minus this
  const char* reason;  ///< why it does not apply to the other models, with what to use there
};

constexpr DistributedKeyword kForceContour{"FORCE_CONTOUR", 2, 1,
                                           "FORCE_CONTOUR loads the edges of 2D and AXIS models (code_aster: "
                                           "forces per unit length on the boundary of a 2D domain); in 3D use "
                                           "FORCE_FACE or FORCE_ARETE"};
constexpr DistributedKeyword kForceFace{"FORCE_FACE", 3, 1,
                                        "FORCE_FACE loads the faces of 3D solid elements (code_aster: surface "
                                        "forces on a face of a volume element); on a 2D or AXIS model use "
                                        "FORCE_CONTOUR"};
constexpr DistributedKeyword kForceArete{"FORCE_ARETE", 3, 2,
                                         "FORCE_ARETE loads the edges of 3D elements (code_aster: forces per unit "
                                         "length on an edge of a volume element); on a 2D or AXIS model use "
                                         "FORCE_CONTOUR or FORCE_NODALE"};
constexpr DistributedKeyword kForceInterne{"FORCE_INTERNE", 0, 0, ""};
constexpr DistributedKeyword kPesanteur{"PESANTEUR", 0, 0, ""};

const char* model_label(const Modele& mo) {
  if (mo.dim == 3) return "a 3D model";
  for (engine::Modelisation m : mo.modelisation)
    if (m == engine::Modelisation::Axisymmetric) return "an AXIS model";
  return "a 2D model";
}

void read_distributed(const Args& occ, const Modele& mo, CharMeca& load, const DistributedKeyword& kw) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  const std::string first = occ.has("GROUP_MA") ? "GROUP_MA" : occ.has("MAILLE") ? "MAILLE" : "TOUT";
  if (kw.model_dim != 0 && mo.dim != kw.model_dim)
    throw DeckError::at(occ.where(), kw.model_dim == 2 ? "a 2D or AXIS model" : "a 3D model", model_label(mo),
                        {kw.reason});
  const int cells_dim = mo.dim - kw.cells_below;
  const bool pesanteur = std::string(kw.name) == "PESANTEUR";
  std::array<double, 3> force = {0.0, 0.0, 0.0};
  if (pesanteur) {
    const std::vector<double> d = occ.reals("DIRECTION");
    const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (norm == 0.0) throw occ.error("DIRECTION", "a non-zero direction (it is normalised)", "(0, 0, 0)");
    if (mo.dim == 2 && d[2] != 0.0) {
      char given[64];
      std::snprintf(given, sizeof given, "a third component %g", d[2]);
      throw occ.error("DIRECTION", "a direction in the model's plane (third component 0) on " +
                                       std::string(model_label(mo)),
                      given);
    }
    for (int k = 0; k < 3; ++k) force[k] = occ.real("GRAVITE") * d[k] / norm;
  } else {
    if (mo.dim == 2 && occ.has("FZ"))
      throw occ.error("FZ", std::string("FX or FY on ") + model_label(mo),
                      "FZ (the out-of-plane force of code_aster's AXIS_FOURIER, which is not modelled here)");
    for (ComponentKeyword ck : {ComponentKeyword{"FX", engine::DX}, {"FY", engine::DY}, {"FZ", engine::DZ}})
      if (occ.has(ck.name)) force[ck.component] = occ.real(ck.name);
  }
  // PESANTEUR without GROUP_MA or MAILLE: every cell of the model.
  const bool whole_model = pesanteur && !occ.has("GROUP_MA") && !occ.has("MAILLE");
  std::vector<int> cells;
  for (int c : whole_model ? std::vector<int>{} : select_cells(occ, mesh))
    if (engine::cell_info(mesh.cell_types[c]).dim == cells_dim) cells.push_back(c);
  if (whole_model)
    for (int c = 0; c < mesh.n_cells(); ++c)
      if (mo.modelisation[c] != engine::Modelisation::None) cells.push_back(c);
  const char* expected = cells_dim == mo.dim ? "cells of the model's dimension"
                         : cells_dim == 2    ? "face cells (TRIA/QUAD)"
                                             : "edge cells (SEG2/SEG3)";
  // On a part, the cells may all be on other ranks: the ranks decide.
  require_somewhere(mesh, !cells.empty(), occ.error(first, expected, "a selection without any"));
  if (cells_dim == mo.dim)
    for (int c : cells)
      if (mo.modelisation[c] == engine::Modelisation::None)
        throw occ.error(first, "cells that carry an element of MODELE", "cell " + mesh.cell_names[c] + ", which does not");
  load.distributed.push_back({cells, cells_dim, force, pesanteur, 0});
}

/// Per mesh node, whether a cell that carries an element of `mo` holds it.
std::vector<char> model_nodes(const Modele& mo) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  std::vector<char> in_model(mesh.n_nodes(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mo.modelisation[c] != engine::Modelisation::None)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) in_model[mesh.cell(c)[a]] = 1;
  return in_model;
}

/// The nodes a linear relation reads, as a serial run has them: the mesh's numbers and names, or
/// on a mesh in parts the whole mesh's (docs/distributed-model.md, step 5), gathered over the
/// ranks, so that one relation may tie nodes of several parts and reads alike on every rank.
/// The functions taking a Modele are collective on a mesh in parts.
struct RelationNodes {
  std::vector<int> nodes;
  std::vector<std::string> names;
};

/// `local`, nodes of this rank's mesh (a selection, a group: sorted), as a relation reads them:
/// on a mesh in parts, the union over the ranks in the whole mesh's numbers, sorted (a group's
/// nodes in the whole mesh's order, as a serial run has them).
RelationNodes relation_nodes(const Modele& mo, const std::vector<int>& local) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  RelationNodes out;
  if (!mo.in_parts()) {
    out.nodes = local;
    for (int v : local) out.names.push_back(mesh.node_names[v]);
    return out;
  }
  const engine::MeshPart& part = *mo.maillage->part;
  std::vector<int> mine;
  std::string names;
  for (int v : local) mine.push_back(part.global_node[v]), names += mesh.node_names[v] + '\n';
  const std::vector<int> all = engine::parallel::gather_all(mine);
  const std::string all_names = engine::parallel::gather_all(names);
  std::map<int, std::string> whole;
  size_t at = 0;
  for (int g : all) {
    const size_t end = all_names.find('\n', at);
    whole.emplace(g, all_names.substr(at, end - at));
    at = end + 1;
  }
  for (auto& [g, name] : whole) out.nodes.push_back(g), out.names.push_back(std::move(name));
  return out;
}

/// The node named `name` as a relation reads it (its number in the whole mesh on a mesh in
/// parts, found by a rank holding it), or -1 when the mesh has none.
int relation_node(const Modele& mo, const std::string& name) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  const int here = mesh.find_node(name);
  if (!mo.in_parts()) return here;
  const double found = here < 0 ? -1.0 : mo.maillage->part->global_node[here];
  return static_cast<int>(engine::parallel::max_over_ranks(found));
}

/// Per node of `nodes` (as relation_nodes gives them), whether a cell of the model holds it (on
/// a mesh in parts: on some rank).
std::vector<char> on_model(const Modele& mo, const std::vector<int>& nodes) {
  const std::vector<char> in_model = model_nodes(mo);
  std::vector<char> out(nodes.size(), 0);
  if (!mo.in_parts()) {
    for (size_t i = 0; i < nodes.size(); ++i) out[i] = in_model[nodes[i]];
    return out;
  }
  const std::unordered_map<int, int> local = engine::local_nodes(*mo.maillage->part);
  std::vector<double> flags(nodes.size(), 0.0);
  for (size_t i = 0; i < nodes.size(); ++i) {
    const auto it = local.find(nodes[i]);
    flags[i] = it != local.end() && in_model[it->second] ? 1.0 : 0.0;
  }
  if (!flags.empty()) engine::parallel::sum_over_ranks(flags.data(), static_cast<long long>(flags.size()));
  for (size_t i = 0; i < nodes.size(); ++i) out[i] = flags[i] > 0.0;
  return out;
}

/// A DDL value of LIAISON_DDL / LIAISON_UNIF as a component; DZ refused in a 2D model.
int relation_component(const Args& occ, const Modele& mo, const std::string& ddl) {
  if (ddl == "DZ" && mo.dim == 2) throw occ.error("DDL", "DX or DY in a 2D model", "'DZ'");
  return ddl == "DX" ? engine::DX : ddl == "DY" ? engine::DY : engine::DZ;
}

/// LIAISON_DDL: one relation, its nodes in the order written (GROUP_NO: each group's nodes in
/// the group's order), one DDL and COEF_MULT per node. On a mesh in parts its nodes are the
/// whole mesh's numbers (relation_nodes).
void read_liaison_ddl(const Args& occ, const Modele& mo, CharMeca& load) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  const std::string where = occ.has("GROUP_NO") ? "GROUP_NO" : "NOEUD";
  RelationNodes nodes;
  for (const auto& name : occ.texts(where)) {
    if (where == "GROUP_NO") {
      const RelationNodes group = relation_nodes(mo, node_group(occ, "GROUP_NO", mesh, name));
      nodes.nodes.insert(nodes.nodes.end(), group.nodes.begin(), group.nodes.end());
      nodes.names.insert(nodes.names.end(), group.names.begin(), group.names.end());
      continue;
    }
    const int n = relation_node(mo, name);
    if (n < 0) {
      std::vector<std::string> hints;
      if (mesh.node_groups.count(name)) hints.push_back("'" + name + "' is a node group: use GROUP_NO");
      throw occ.error("NOEUD", "a node name of the mesh", "'" + name + "'", hints);
    }
    nodes.nodes.push_back(n), nodes.names.push_back(name);
  }
  const std::vector<std::string> ddl = occ.texts("DDL");
  const std::vector<double> coef = occ.reals("COEF_MULT");
  const std::string counted = std::to_string(nodes.nodes.size()) + " node(s) from " + where;
  if (ddl.size() != nodes.nodes.size())
    throw occ.error("DDL", "one component per node (" + counted + ")", std::to_string(ddl.size()) + " component(s)",
                    {"a GROUP_NO group gives all its nodes: name groups of one node each, or use NOEUD"});
  if (coef.size() != nodes.nodes.size())
    throw occ.error("COEF_MULT", "one coefficient per node (" + counted + ")",
                    std::to_string(coef.size()) + " coefficient(s)");
  const std::vector<char> in_model = on_model(mo, nodes.nodes);
  engine::LinearRelation relation;
  for (size_t i = 0; i < nodes.nodes.size(); ++i) {
    const int component = relation_component(occ, mo, ddl[i]);
    if (!in_model[i])
      throw occ.error(where, "nodes of cells of MODELE '" + mo.user_name + "'",
                      "node " + nodes.names[i] + ", on no cell of it");
    relation.terms.push_back({nodes.nodes[i], component, coef[i]});
  }
  relation.value = occ.real("COEF_IMPO");
  relation.label = occ.where();
  // Terms on one component of one node add up; a relation left with none says 0 = COEF_IMPO.
  std::vector<engine::DirichletValue> unused;
  const auto kept = engine::split_dirichlet({relation}, unused);
  if (!kept.empty() && kept[0].terms.empty())
    throw occ.error("COEF_MULT", "coefficients that do not cancel on one component of one node",
                    "terms that sum to zero on every component");
  load.relations.push_back(relation);
}

/// LIAISON_UNIF: u(node) - u(first node) = 0 for every other node of the set (nodes in mesh
/// order) and every DDL. On a mesh in parts its nodes are the whole mesh's numbers.
void read_liaison_unif(const Args& occ, const Modele& mo, CharMeca& load) {
  const RelationNodes set = relation_nodes(mo, select_nodes(occ, *mo.maillage->mesh));
  const std::vector<int>& nodes = set.nodes;
  const std::string where = occ.has("GROUP_NO") ? "GROUP_NO" : "GROUP_MA";
  if (nodes.size() < 2)
    throw occ.error(where, "two nodes or more (one value shared among them)",
                    std::to_string(nodes.size()) + " node");
  const std::vector<char> in_model = on_model(mo, nodes);
  for (size_t i = 0; i < nodes.size(); ++i)
    if (!in_model[i])
      throw occ.error(where, "nodes of cells of MODELE '" + mo.user_name + "'",
                      "node " + set.names[i] + ", on no cell of it");
  const std::vector<std::string> ddls = occ.texts("DDL");
  for (size_t k = 0; k < ddls.size(); ++k)
    if (std::find(ddls.begin(), ddls.begin() + k, ddls[k]) != ddls.begin() + k)
      throw occ.error("DDL", "each component once", "'" + ddls[k] + "' twice");
  for (const auto& ddl : ddls) {
    const int component = relation_component(occ, mo, ddl);
    for (size_t i = 1; i < nodes.size(); ++i) {
      engine::LinearRelation r;
      r.terms = {{nodes[i], component, 1.0}, {nodes[0], component, -1.0}};
      r.label = occ.where() + " (" + ddl + " of node " + set.names[i] + " equal to node " + set.names[0] + "'s)";
      load.relations.push_back(r);
    }
  }
}

/// A cell's size: the longest distance between two of its nodes.
double cell_size(const engine::Mesh& mesh, int c) {
  double size = 0.0;
  const int nn = mesh.cell_n_nodes(c);
  for (int a = 0; a < nn; ++a)
    for (int b = a + 1; b < nn; ++b) {
      double d2 = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double d = mesh.node(mesh.cell(c)[a])[i] - mesh.node(mesh.cell(c)[b])[i];
        d2 += d * d;
      }
      size = std::max(size, std::sqrt(d2));
    }
  return size;
}

/// LIAISON_MAIL DDL = 'DNOR': the unit normal of the slave face (the boundary cells of
/// GROUP_MA_ESCL) at each slave node.
std::unordered_map<int, std::array<double, 3>> slave_normals(const Args& occ, const Modele& mo,
                                                            const std::vector<int>& slaves) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  std::vector<int> skin;
  for (const auto& name : occ.texts("GROUP_MA_ESCL"))
    for (int c : cell_group(occ, "GROUP_MA_ESCL", mesh, name))
      if (engine::cell_info(mesh.cell_types[c]).dim == mo.dim - 1) skin.push_back(c);
  if (skin.empty())
    throw occ.error("GROUP_MA_ESCL",
                    std::string("with DDL = 'DNOR', boundary cells (") + (mo.dim == 3 ? "TRIA, QUAD" : "SEG") +
                        ") whose normal the slave nodes take",
                    "groups without any");
  const auto normals = engine::contact::node_normals(mesh, skin);
  for (int s : slaves) {
    auto it = normals.find(s);
    if (it == normals.end() || (*it).second == std::array<double, 3>{0.0, 0.0, 0.0})
      throw occ.error("GROUP_MA_ESCL", "slave nodes with a normal (on the boundary cells of GROUP_MA_ESCL)",
                      "node " + mesh.node_names[s] + (it == normals.end() ? ", on none of them" :
                                                                              ", where their normals cancel"));
  }
  return normals;
}

/// LIAISON_MAIL, TYPE_RACCORD = 'MASSIF' (code_aster's gluing of meshes that do not match):
/// each slave node follows the master cell that holds it, or the nearest one,
/// u(node) - sum_a N_a(xi) u_a = 0 for each DDL, one relation each. As in code_aster: a slave
/// node that is a node of its master cell would be tied to itself (no relation, a warning);
/// beyond DISTANCE_MAX a node is not tied; an occurrence with ELIM_MULT = 'OUI' leaves out the
/// slave nodes of the earlier ones with ELIM_MULT = 'OUI' (`listed`, tied or not: code_aster's
/// list of nodes already used). Nodes tied from outside their cell by more than
/// DISTANCE_ALARME (default: a tenth of the cell's size) are counted in a warning. TRAN looks for
/// each slave node TRAN away from it (periodic conditions, as code_aster's TRAN).
void read_liaison_mail(const Args& occ, const Modele& mo, CharMeca& load, std::set<int>& listed, Session& session) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  std::vector<int> master;
  for (const auto& name : occ.texts("GROUP_MA_MAIT"))
    for (int c : cell_group(occ, "GROUP_MA_MAIT", mesh, name))
      if (engine::cell_info(mesh.cell_types[c]).dim == mo.dim && mo.modelisation[c] != engine::Modelisation::None)
        master.push_back(c);
  std::sort(master.begin(), master.end());
  master.erase(std::unique(master.begin(), master.end()), master.end());
  if (master.empty())
    throw occ.error("GROUP_MA_MAIT",
                    std::string(mo.dim == 3 ? "volume cells (HEXA, PENTA, TETRA)" : "face cells (QUAD, TRIA)") +
                        " of MODELE '" + mo.user_name + "'",
                    "groups without any");
  std::vector<int> slaves;
  for (const auto& name : occ.texts("GROUP_MA_ESCL")) {
    const std::vector<int> nodes = mesh.nodes_of_cells(cell_group(occ, "GROUP_MA_ESCL", mesh, name));
    slaves.insert(slaves.end(), nodes.begin(), nodes.end());
  }
  for (const auto& name : occ.texts("GROUP_NO_ESCL")) {
    const std::vector<int> nodes = node_group(occ, "GROUP_NO_ESCL", mesh, name);
    slaves.insert(slaves.end(), nodes.begin(), nodes.end());
  }
  std::sort(slaves.begin(), slaves.end());
  slaves.erase(std::unique(slaves.begin(), slaves.end()), slaves.end());
  const std::string slave_kw = occ.has("GROUP_MA_ESCL") ? "GROUP_MA_ESCL" : "GROUP_NO_ESCL";
  const std::vector<char> in_model = model_nodes(mo);
  for (int n : slaves)
    if (!in_model[n])
      throw occ.error(slave_kw, "nodes of cells of MODELE '" + mo.user_name + "'",
                      "node " + mesh.node_names[n] + ", on no cell of it");
  if (occ.text("ELIM_MULT") == "OUI") {
    const size_t before = slaves.size();
    slaves.erase(std::remove_if(slaves.begin(), slaves.end(), [&](int n) { return listed.count(n) > 0; }),
                 slaves.end());
    if (slaves.empty())
      throw occ.error(slave_kw, "slave nodes that no earlier LIAISON_MAIL of this AFFE_CHAR_MECA listed (ELIM_MULT = "
                                "'OUI' leaves those out; 'NON' ties them again)",
                      "all " + std::to_string(before) + " listed before");
    listed.insert(slaves.begin(), slaves.end());
  }
  std::vector<std::string> ddls = {"DX", "DY", "DZ"};
  if (occ.has("DDL")) {
    ddls = occ.texts("DDL");
    for (size_t k = 0; k < ddls.size(); ++k)
      if (std::find(ddls.begin(), ddls.begin() + k, ddls[k]) != ddls.begin() + k)
        throw occ.error("DDL", "each component once", "'" + ddls[k] + "' twice");
  } else if (mo.dim == 2) {
    ddls.pop_back();
  }
  // DDL = 'DNOR': the normal component alone, n . u(node) = n . sum N_a u_a, n the slave face's
  // normal at the node (from the GROUP_MA_ESCL cells): the faces slide on each other.
  const bool normal = std::find(ddls.begin(), ddls.end(), "DNOR") != ddls.end();
  std::unordered_map<int, std::array<double, 3>> normals;
  std::vector<int> components;
  if (normal) {
    if (ddls.size() > 1)
      throw occ.error("DDL", "'DNOR' alone (the normal component), or components among DX, DY, DZ",
                      std::to_string(ddls.size()) + " components with 'DNOR'");
    if (!occ.has("GROUP_MA_ESCL") || occ.has("GROUP_NO_ESCL"))
      throw occ.error(occ.has("GROUP_NO_ESCL") ? "GROUP_NO_ESCL" : "GROUP_MA_ESCL",
                      "with DDL = 'DNOR', the slave face as GROUP_MA_ESCL alone (its cells give the normal)",
                      occ.has("GROUP_NO_ESCL") ? "GROUP_NO_ESCL" : "no GROUP_MA_ESCL");
    normals = slave_normals(occ, mo, slaves);
  } else {
    for (const auto& ddl : ddls) components.push_back(relation_component(occ, mo, ddl));
  }

  double tran[3] = {0.0, 0.0, 0.0};  // TRAN: where each slave node is looked for, from where it is
  if (occ.has("TRAN")) {
    const std::vector<double> t = occ.reals("TRAN");
    if (static_cast<int>(t.size()) != mo.dim)
      throw occ.error("TRAN", std::to_string(mo.dim) + " values (one per coordinate of the " +
                                  std::to_string(mo.dim) + "D model)",
                      std::to_string(t.size()));
    std::copy(t.begin(), t.end(), tran);
  }
  const engine::CellLocator locator(mesh, master);
  const bool has_max = occ.has("DISTANCE_MAX"), has_alarm = occ.has("DISTANCE_ALARME");
  const double distance_max = has_max ? occ.real("DISTANCE_MAX") : 0.0;
  const double alarm = has_alarm ? occ.real("DISTANCE_ALARME") : 0.0;
  int n_tied = 0, n_self = 0, n_beyond = 0, n_far = 0;
  double farthest = 0.0, nearest_beyond = 0.0;
  int farthest_node = -1;
  std::set<int> cells_used;
  for (int s : slaves) {
    const double at[3] = {mesh.node(s)[0] + tran[0], mesh.node(s)[1] + tran[1], mesh.node(s)[2] + tran[2]};
    const engine::PointLocation loc = locator.locate(at);
    const int c = loc.cell;
    const int nn = mesh.cell_n_nodes(c);
    if (std::find(mesh.cell(c), mesh.cell(c) + nn, s) != mesh.cell(c) + nn) {
      ++n_self;  // a node of its own master cell: u = u
      continue;
    }
    if (has_max && loc.distance > distance_max) {
      nearest_beyond = n_beyond++ ? std::min(nearest_beyond, loc.distance) : loc.distance;
      continue;
    }
    if (loc.distance > 0.0 && loc.distance > (has_alarm ? alarm : 0.1 * cell_size(mesh, c))) ++n_far;
    if (loc.distance > farthest) farthest = loc.distance, farthest_node = s;
    double shape[engine::kMaxCellNodes];
    engine::shape_functions(mesh.cell_types[c], loc.xi, shape, nullptr);
    if (normal) {
      const std::array<double, 3>& n = normals.at(s);
      engine::LinearRelation r;
      for (int k = 0; k < mo.dim; ++k)
        if (std::abs(n[k]) > 1e-14) r.terms.push_back({s, k, -n[k]});
      for (int a = 0; a < nn; ++a)
        for (int k = 0; k < mo.dim; ++k)
          if (std::abs(shape[a] * n[k]) > 1e-14) r.terms.push_back({mesh.cell(c)[a], k, shape[a] * n[k]});
      r.label = occ.where() + " (DNOR of node " + mesh.node_names[s] + " following cell " + mesh.cell_names[c] + ")";
      load.relations.push_back(std::move(r));
    }
    for (size_t k = 0; k < components.size(); ++k) {
      engine::LinearRelation r;
      r.terms.push_back({s, components[k], -1.0});
      for (int a = 0; a < nn; ++a)
        if (std::abs(shape[a]) > 1e-14) r.terms.push_back({mesh.cell(c)[a], components[k], shape[a]});
      r.label = occ.where() + " (" + ddls[k] + " of node " + mesh.node_names[s] + " following cell " +
                mesh.cell_names[c] + ")";
      load.relations.push_back(std::move(r));
    }
    cells_used.insert(c);
    ++n_tied;
  }
  if (n_tied == 0 && n_beyond) {
    char nearest[96];
    std::snprintf(nearest, sizeof nearest, " (the nearest %.3g m from a master cell)", nearest_beyond);
    throw occ.error("DISTANCE_MAX", "slave nodes within DISTANCE_MAX of a master cell",
                    std::to_string(n_beyond) + " slave node(s) beyond it" + nearest +
                        (n_self ? " and " + std::to_string(n_self) + " node(s) of their own master cell" : ""));
  }
  if (n_tied == 0)
    throw occ.error(slave_kw, "slave nodes that are not nodes of the master cell holding them",
                    std::to_string(n_self) + " slave node(s), each a node of its master cell (tied to itself)",
                    {"GROUP_MA_MAIT names the cells the slave nodes follow: those of the other body"});
  char far_said[160] = "";
  if (farthest_node >= 0)
    std::snprintf(far_said, sizeof far_said, "; the farthest outside its cell: node %s, %.3g m",
                  mesh.node_names[farthest_node].c_str(), farthest);
  session.log().info("  AFFE_CHAR_MECA " + occ.where() + ": " + std::to_string(n_tied) + " slave node(s) follow " +
                     std::to_string(cells_used.size()) + " master cell(s), " +
                     std::to_string(n_tied * (normal ? 1 : components.size())) + " linear relation(s)" +
                     (n_beyond ? ", " + std::to_string(n_beyond) + " node(s) beyond DISTANCE_MAX left free" : "") +
                     far_said);
  if (n_self)
    session.warn(occ.path(slave_kw) + ": " + std::to_string(n_self) +
                 " slave node(s) are nodes of the master cell that holds them (each would be tied to itself): no "
                 "relation for them");
  if (n_far)
    session.warn(occ.path(slave_kw) + ": " + std::to_string(n_far) +
                 " slave node(s) lie outside every master cell, by more than " +
                 (has_alarm ? std::string("DISTANCE_ALARME") : std::string("a tenth of the cell")) +
                 "; each follows the nearest point of its nearest cell" + far_said +
                 " (DISTANCE_MAX leaves such nodes free)");
}

engine::ContactMethod seed_method(const std::string& methode) {
  if (methode == "CONTRAINTE") return engine::ContactMethod::DiscreteLagrange;
  if (methode == "PENALISATION") return engine::ContactMethod::DiscretePenalty;
  return engine::ContactMethod::Continuous;
}

/// MODL_AXIS, when given, must say what the model is: the contact measures follow the model
/// (r dl per radian on AXIS), and a deck saying otherwise was written for another model.
void check_modl_axis(const Args& occ, const Modele& mo) {
  if (!occ.has("MODL_AXIS")) return;
  const bool axis = std::any_of(mo.modelisation.begin(), mo.modelisation.end(),
                                [](engine::Modelisation m) { return m == engine::Modelisation::Axisymmetric; });
  const std::string given = occ.text("MODL_AXIS");
  if (axis && given != "OUI")
    throw occ.error("MODL_AXIS", "'OUI' (or no MODL_AXIS) on MODELE '" + mo.user_name + "', an AXIS model",
                    "'" + given + "'");
  if (!axis && given != "NON")
    throw occ.error("MODL_AXIS",
                    "'NON' (or no MODL_AXIS) on MODELE '" + mo.user_name + "', a " +
                        (mo.dim == 3 ? std::string("3D") : std::string("plane (D_PLAN/C_PLAN)")) +
                        " model (MODL_AXIS = 'OUI' needs AFFE_MODELE MODELISATION = 'AXIS')",
                    "'" + given + "'");
}

/// On a mesh in parts: LIAISON_MAIL's occurrences read by rank 0 on the whole mesh it holds (it
/// read and cut it), as a serial run reads them, and their relations given to every rank in the
/// whole mesh's node numbers: locating each slave node in a master cell needs the master cells
/// whole, which no other rank holds. An error is every rank's (commands/parts.hpp). Collective.
void read_liaison_mail_on_rank0(const Args& args, const Modele& mo, CharMeca& load, Session& session) {
  const engine::MeshPart& part = *mo.maillage->part;
  // The model's cells in the whole mesh's numbers, to rank 0.
  std::vector<int> mine;
  for (int c = 0; c < part.mesh.n_cells(); ++c)
    if (mo.modelisation[c] != engine::Modelisation::None)
      mine.insert(mine.end(), {part.global_cell[c], static_cast<int>(mo.modelisation[c])});
  const std::vector<int> modelled = engine::parallel::gather_to_root(mine);
  std::string bytes;
  agreed([&] {
    if (!mo.maillage->whole) return;
    Modele whole;
    whole.user_name = mo.user_name;
    whole.dim = mo.dim;
    whole.maillage = std::make_shared<Maillage>();
    whole.maillage->mesh = mo.maillage->whole;
    whole.maillage->source_file = mo.maillage->source_file;
    whole.modelisation.assign(mo.maillage->whole->n_cells(), engine::Modelisation::None);
    for (size_t i = 0; i + 1 < modelled.size(); i += 2)
      whole.modelisation[modelled[i]] = static_cast<engine::Modelisation>(modelled[i + 1]);
    CharMeca read;
    std::set<int> glued;  // slave nodes of the occurrences before with ELIM_MULT = 'OUI'
    for (const auto& occ : args.factors("LIAISON_MAIL")) read_liaison_mail(occ, whole, read, glued, session);
    // Each relation: its terms' nodes, components and coefficients, its value and its label (the
    // carriers are the driver's to choose, the load STAT_NON_LINE's).
    engine::ByteWriter out;
    out.value<std::uint64_t>(read.relations.size());
    for (const engine::LinearRelation& r : read.relations) {
      std::vector<int> nodes, components;
      std::vector<double> coefs;
      for (const auto& t : r.terms) nodes.push_back(t.node), components.push_back(t.component), coefs.push_back(t.coef);
      out.array(nodes), out.array(components), out.array(coefs), out.value(r.value), out.text(r.label);
    }
    bytes = out.take();
  });
  engine::parallel::broadcast(bytes);
  engine::ByteReader in(bytes);
  const auto n = in.value<std::uint64_t>();
  for (std::uint64_t i = 0; i < n; ++i) {
    engine::LinearRelation r;
    const std::vector<int> nodes = in.array<int>(), components = in.array<int>();
    const std::vector<double> coefs = in.array<double>();
    for (size_t k = 0; k < nodes.size(); ++k) r.terms.push_back({nodes[k], components[k], coefs[k]});
    r.value = in.value<double>();
    r.label = in.text();
    load.relations.push_back(std::move(r));
  }
}

}  // namespace

ConceptPtr affe_char_meca(const Args& args, Session& session) {
  auto load = std::make_shared<CharMeca>();
  load->modele = args.concept_as<Modele>("MODELE");
  const Modele& mo = *load->modele;
  const bool check_facing = args.text("VERI_NORM") == "OUI";
  std::vector<PressureFacing> facing;
  auto read_here = [&] {
    for (const auto& occ : args.factors("DDL_IMPO")) read_ddl_impo(occ, mo, *load);
    for (const auto& occ : args.factors("PRES_REP")) read_pres_rep(occ, mo, *load, check_facing ? &facing : nullptr);
    for (const auto& occ : args.factors("FORCE_NODALE")) read_force_nodale(occ, mo, *load);
    for (const DistributedKeyword& kw : {kForceContour, kForceFace, kForceArete, kForceInterne, kPesanteur})
      for (const auto& occ : args.factors(kw.name)) read_distributed(occ, mo, *load, kw);
  };
  // On a mesh in parts the relations gather their nodes over the ranks: the ranks agree on what
  // they read first (commands/parts.hpp), and the relations' checks fail alike on every rank.
  if (mo.in_parts()) agreed(read_here);
  else read_here();
  if (check_facing) check_pressure_facing(facing, mo);
  for (const auto& occ : args.factors("LIAISON_DDL")) read_liaison_ddl(occ, mo, *load);
  for (const auto& occ : args.factors("LIAISON_UNIF")) read_liaison_unif(occ, mo, *load);
  if (mo.in_parts() && args.count("LIAISON_MAIL") > 0) {
    read_liaison_mail_on_rank0(args, mo, *load, session);
  } else {
    std::set<int> glued;  // slave nodes of the LIAISON_MAIL occurrences before with ELIM_MULT = 'OUI'
    for (const auto& occ : args.factors("LIAISON_MAIL")) read_liaison_mail(occ, mo, *load, glued, session);
  }
  if (args.count("CONTACT") > 0) {
    load->has_contact = true;
    auto& def = load->contact;
    const auto occurrences = args.factors("CONTACT");
    for (const auto& occ : occurrences) {
      check_modl_axis(occ, mo);
      def.method = seed_method(occ.text("METHODE"));
      def.zones.push_back(read_contact_zone(occ, *mo.maillage->mesh, mo.dim, def.method));
      read_contact_loops(occ, def);
    }
    // On a mesh in parts the surfaces are checked whole.
    warn_contact_surfaces(occurrences, contact_surfaces(def, mo), *mo.maillage, session, true);
  }
  return load;
}

}  // namespace lunaster::cmd
