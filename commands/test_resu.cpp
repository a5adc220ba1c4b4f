// TEST_RESU: checks result values against non-regression (VALE_CALC) and
// reference (VALE_REFE) values; prints one OK/NOOK line per check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"
#include "commands/test_report.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

const engine::ResultStep& find_step(const Args& occ, const EvolNoli& resu) {
  for (const auto& s : resu.steps) {
    if (occ.has("NUME_ORDRE") && s.nume_ordre == occ.integer("NUME_ORDRE")) return s;
    if (occ.has("INST") && std::abs(s.inst - occ.real("INST")) <= 1e-6 * std::max(1.0, std::abs(s.inst))) return s;
  }
  if (occ.has("INST")) throw occ.error("INST", "an instant stored in the result", std::to_string(occ.real("INST")));
  throw occ.error("NUME_ORDRE", "a numéro d'ordre stored in the result (0.." + std::to_string(resu.steps.size() - 1) + ")",
                  std::to_string(occ.integer("NUME_ORDRE")));
}

struct Probe {
  double value = 0.0;
  std::string where;  ///< node name or "MIN"/"MAX"...
};

/// Values of one component of a nodal field over a node set.
std::vector<double> nodal_values(const Args& occ, const engine::NodalField& f, int cmp, const std::vector<int>& nodes) {
  std::vector<double> out;
  for (int n : nodes)
    if (f.has(n, cmp)) out.push_back(f.value(n, cmp));
  if (out.empty()) throw occ.error("NOM_CMP", "a component defined on the selected nodes", "'" + f.components[cmp] + "' undefined there");
  return out;
}

double reduce(const std::string& type, const std::vector<double>& v) {
  if (type == "MIN") return *std::min_element(v.begin(), v.end());
  if (type == "MAX") return *std::max_element(v.begin(), v.end());
  double s = 0.0;
  for (double x : v) s += type == "SOMM_ABS" ? std::abs(x) : x;
  return s;
}

/// probe_value on a mesh in parts: each node's value from the rank owning it; a TYPE_TEST
/// reduction over each rank's owned nodes, then over the ranks. Collective; every rank returns
/// the same probe.
Probe probe_in_parts(const Args& occ, const engine::MeshPart& part, const engine::NodalField& f, int cmp) {
  namespace parallel = engine::parallel;
  const engine::Mesh& mesh = part.mesh;
  const bool reduced = occ.has("TYPE_TEST");
  std::vector<int> nodes;
  if (!reduced || occ.has("GROUP_NO") || occ.has("NOEUD") || occ.has("GROUP_MA")) {
    nodes = select_nodes(occ, mesh);
  } else {
    for (int n = 0; n < mesh.n_nodes(); ++n) nodes.push_back(n);
  }
  agree_over_ranks(nullptr);  // the selection is the whole mesh's on every rank (names, empty groups)
  std::vector<double> values;  // the selected owned nodes' values
  int owned = 0;
  for (int n : nodes)
    if (part.owns(n)) {
      ++owned;
      if (f.has(n, cmp)) values.push_back(f.value(n, cmp));
    }
  double counts[2] = {static_cast<double>(owned), static_cast<double>(values.size())};
  parallel::sum_over_ranks(counts, 2);
  if (counts[1] == 0)
    throw occ.error("NOM_CMP", "a component defined on the selected nodes",
                    "'" + f.components[cmp] + "' undefined there");
  Probe p;
  if (reduced) {
    const std::string type = occ.text("TYPE_TEST");
    if (type == "MIN" || type == "MAX") {
      const double sign = type == "MAX" ? 1.0 : -1.0;
      double best = -std::numeric_limits<double>::infinity();
      for (double x : values) best = std::max(best, sign * x);
      p.value = sign * parallel::max_over_ranks(best);
    } else {
      double sum = values.empty() ? 0.0 : reduce(type, values);
      parallel::sum_over_ranks(&sum, 1);
      p.value = sum;
    }
    p.where = type;
    if (occ.has("GROUP_NO")) p.where += "(" + occ.texts("GROUP_NO").front() + ")";
    else if (occ.has("GROUP_MA")) p.where += "(" + occ.texts("GROUP_MA").front() + ")";
    return p;
  }
  const char* kw = occ.has("GROUP_NO") ? "GROUP_NO" : "NOEUD";
  if (counts[0] != 1)
    throw occ.error(kw, "a single node (or TYPE_TEST to reduce over a group)",
                    std::to_string(static_cast<long long>(counts[0])) + " nodes");
  // The one owner gives the value and the node's name.
  const int owner = static_cast<int>(parallel::max_over_ranks(owned == 1 ? part.rank : -1));
  p.value = values.empty() ? 0.0 : values.front();
  parallel::broadcast_from(owner, &p.value, 1);
  if (occ.has("GROUP_NO")) {
    p.where = occ.texts("GROUP_NO").front();
  } else {
    for (int n : nodes)
      if (part.owns(n)) p.where = mesh.node_names[n];
    parallel::broadcast_from(owner, p.where);
  }
  return p;
}

/// The column of NOM_CMP in a field's components; DeckError naming them otherwise.
int component_column(const Args& occ, const std::vector<std::string>& components, const std::string& cham) {
  const std::string cmp_name = occ.text("NOM_CMP");
  const auto it = std::find(components.begin(), components.end(), cmp_name);
  if (it != components.end()) return static_cast<int>(it - components.begin());
  std::string have;
  for (const auto& c : components) have += (have.empty() ? "" : ", ") + c;
  throw occ.error("NOM_CMP", "a component of " + cham + " (" + have + ")", "'" + cmp_name + "'");
}

/// One component of a nodal field of a mesh read whole: at one node, or reduced by TYPE_TEST.
Probe nodal_probe(const Args& occ, const engine::Mesh& mesh, const engine::NodalField& f, int cmp) {
  Probe p;
  if (occ.has("TYPE_TEST")) {
    std::vector<int> nodes;
    const bool group_ma = occ.declares("GROUP_MA") && occ.has("GROUP_MA");  // RESU's; CHAM_NO has none
    if (occ.has("GROUP_NO") || occ.has("NOEUD") || group_ma) nodes = select_nodes(occ, mesh);
    else for (int n = 0; n < mesh.n_nodes(); ++n) nodes.push_back(n);
    p.value = reduce(occ.text("TYPE_TEST"), nodal_values(occ, f, cmp, nodes));
    p.where = occ.text("TYPE_TEST");
    if (occ.has("GROUP_NO")) p.where += "(" + occ.texts("GROUP_NO").front() + ")";
    else if (group_ma) p.where += "(" + occ.texts("GROUP_MA").front() + ")";
    return p;
  }
  const std::vector<int> nodes = select_nodes(occ, mesh);
  const char* kw = occ.has("GROUP_NO") ? "GROUP_NO" : "NOEUD";
  if (nodes.size() != 1)
    throw occ.error(kw, "a single node (or TYPE_TEST to reduce over a group)", std::to_string(nodes.size()) + " nodes");
  p.value = nodal_values(occ, f, cmp, nodes).front();
  p.where = occ.has("GROUP_NO") ? occ.texts("GROUP_NO").front() : mesh.node_names[nodes.front()];
  return p;
}

/// One component of a field per cell (TEST_RESU CHAM_ELEM, or RESU of a result's ELNO/ELGA field
/// `name`): at the node NOEUD (or one-node GROUP_NO) of the cell MAILLE for an ELNO field, at its
/// integration point POINT (1-based) for an ELGA field, or reduced by TYPE_TEST over every value.
/// `kw` names the field in messages (CHAM_GD or NOM_CHAM).
Probe cell_probe(const Args& occ, const engine::ElnoField& f, bool elno, const std::string& name, const char* kw,
                 const engine::Mesh& mesh) {
  const int cmp = component_column(occ, f.components, name);
  const std::string kind = elno ? "ELNO" : "ELGA";
  Probe p;
  if (occ.has("TYPE_TEST")) {
    std::vector<double> values;
    for (size_t row = 0; row * f.components.size() < f.values.size(); ++row)
      values.push_back(f.values[row * f.components.size() + cmp]);
    if (values.empty()) throw occ.error(kw, "a field with values", "an empty " + kind + " field " + name);
    p.value = reduce(occ.text("TYPE_TEST"), values);
    p.where = occ.text("TYPE_TEST");
    return p;
  }
  const std::string cell_name = occ.text("MAILLE");
  const auto cell = std::find(mesh.cell_names.begin(), mesh.cell_names.end(), cell_name);
  if (cell == mesh.cell_names.end()) throw occ.error("MAILLE", "a cell of the field's mesh", "'" + cell_name + "'");
  const int c = static_cast<int>(cell - mesh.cell_names.begin());
  if (c >= f.n_cells() || f.n_rows(c) == 0)
    throw occ.error("MAILLE", "a cell carrying " + name, "'" + cell_name + "', which carries none");
  const bool at_point = occ.declares("POINT") && occ.has("POINT");
  if (elno == at_point)
    throw occ.error("MAILLE", elno ? "NOEUD or GROUP_NO with an ELNO field (the value at a node of the cell)"
                                   : "POINT with an ELGA field (the value at an integration point of the cell)",
                    "'" + cell_name + "' with " + (at_point ? "POINT" : "a node"));
  if (at_point) {
    const long long point = occ.integer("POINT");
    if (point > f.n_rows(c))
      throw occ.error("POINT", "an integration point of cell " + cell_name + " (1.." + std::to_string(f.n_rows(c)) + ")",
                      std::to_string(point));
    p.where = cell_name + " point " + std::to_string(point);
    p.value = f.value(c, static_cast<int>(point - 1), cmp);
    return p;
  }
  int row = -1;
  std::string node_name;
  if (occ.has("GROUP_NO")) {
    const auto nodes = node_group(occ, "GROUP_NO", mesh, occ.texts("GROUP_NO").front());
    if (nodes.size() != 1)
      throw occ.error("GROUP_NO", "a group of one node", "'" + occ.texts("GROUP_NO").front() + "', of " +
                                                            std::to_string(nodes.size()) + " nodes");
    node_name = mesh.node_names[nodes.front()];
  } else {
    node_name = occ.text("NOEUD");
  }
  for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
    if (mesh.node_names[mesh.cell(c)[a]] == node_name) row = a;
  if (row < 0)
    throw occ.error(occ.has("GROUP_NO") ? "GROUP_NO" : "NOEUD", "a node of cell " + cell_name, "'" + node_name + "'");
  p.where = cell_name + " " + node_name;
  p.value = f.value(c, row, cmp);
  return p;
}

Probe probe_value(const Args& occ, const EvolNoli& resu, const engine::ResultStep& step) {
  const engine::Mesh& mesh = *resu.modele->maillage->mesh;
  const std::string cham = occ.text("NOM_CHAM");
  const std::string cmp_name = occ.text("NOM_CMP");
  auto nit = step.nodal.find(cham);
  if (nit == step.nodal.end()) {
    const auto elno = step.elno.find(cham);
    const auto elga = step.elga.find(cham);
    if (elno != step.elno.end() || elga != step.elga.end()) {
      if (resu.modele->maillage->part)
        throw occ.error("NOM_CHAM", "a field at nodes (a mesh in parts)", "'" + cham + "', a field per cell",
                        {"test its nodal counterpart (CALC_CHAMP ..._NOEU)"});
      if (elno != step.elno.end()) return cell_probe(occ, elno->second, true, cham, "NOM_CHAM", mesh);
      return cell_probe(occ, elga->second, false, cham, "NOM_CHAM", mesh);
    }
    std::string have;
    for (const auto& [name, field] : step.nodal) have += (have.empty() ? "" : ", ") + name;
    for (const auto& [name, field] : step.elno) have += (have.empty() ? "" : ", ") + name;
    for (const auto& [name, field] : step.elga) have += (have.empty() ? "" : ", ") + name;
    throw occ.error("NOM_CHAM", "a field stored at this step (" + have + ")", "'" + cham + "'",
                    {"stresses need CALC_CHAMP (CONTRAINTE='SIGM_NOEU') first"});
  }
  if (occ.has("MAILLE") || occ.has("POINT"))
    throw occ.error(occ.has("MAILLE") ? "MAILLE" : "POINT", "a field per cell (ELNO, ELGA) with MAILLE (at its NOEUD or POINT)",
                    "'" + cham + "', a field at nodes", {"name the node by NOEUD or GROUP_NO"});
  const engine::NodalField& f = nit->second;
  const int cmp = f.component_index(cmp_name);
  if (cmp < 0) {
    std::string have;
    for (const auto& c : f.components) have += (have.empty() ? "" : ", ") + c;
    throw occ.error("NOM_CMP", "a component of " + cham + " (" + have + ")", "'" + cmp_name + "'");
  }
  if (resu.modele->maillage->part) return probe_in_parts(occ, *resu.modele->maillage->part, f, cmp);
  return nodal_probe(occ, mesh, f, cmp);
}

/// The field of a CHAM_NO or CHAM_ELEM occurrence, of the kind it tests.
std::shared_ptr<ChamGd> tested_field(const Args& occ, bool at_nodes) {
  auto field = occ.concept_as<ChamGd>("CHAM_GD");
  if (field->at_nodes() != at_nodes)
    throw occ.error("CHAM_GD", at_nodes ? "a field at nodes (NOEU_*)" : "a field per cell (ELNO_*, ELGA_*)",
                    "'" + field->user_name + "', a field of type " + field->type_cham,
                    {at_nodes ? "test it under CHAM_ELEM" : "test it under CHAM_NO"});
  if (field->of_functions())
    throw occ.error("CHAM_GD", "a field of values", "'" + field->user_name + "', a field of functions (" + field->type_cham + ")",
                    {"evaluate it first: CREA_CHAMP OPERATION='EVAL'"});
  return field;
}

}  // namespace

ConceptPtr test_resu(const Args& args, Session& session) {
  for (const auto& occ : args.factors("RESU")) {
    auto resu = occ.concept_as<EvolNoli>("RESULTAT");
    const engine::ResultStep& step = find_step(occ, *resu);
    if (occ.has("PARA")) {  // 'INST', the only parameter a lunaster result stores per step
      std::string what = "INST  NUME_ORDRE " + std::to_string(step.nume_ordre);
      if (occ.has("LEGENDE")) what += "  [" + occ.text("LEGENDE") + "]";
      report_checks(occ, session, step.inst, what);
      continue;
    }
    const Probe p = probe_value(occ, *resu, step);
    std::string what = occ.text("NOM_CHAM") + "  " + p.where + "  " + occ.text("NOM_CMP");
    if (occ.has("LEGENDE")) what += "  [" + occ.text("LEGENDE") + "]";
    report_checks(occ, session, p.value, what);
  }
  for (const auto& occ : args.factors("CHAM_NO")) {
    const auto field = tested_field(occ, true);
    const int cmp = component_column(occ, field->nodal.components, field->nom_cham);
    const Probe p = nodal_probe(occ, *field->maillage->mesh, field->nodal, cmp);
    std::string what = field->nom_cham + "  " + p.where + "  " + occ.text("NOM_CMP");
    if (occ.has("LEGENDE")) what += "  [" + occ.text("LEGENDE") + "]";
    report_checks(occ, session, p.value, what);
  }
  for (const auto& occ : args.factors("CHAM_ELEM")) {
    const auto field = tested_field(occ, false);
    const Probe p = cell_probe(occ, field->cells, field->type_cham.rfind("ELNO_", 0) == 0, field->nom_cham, "CHAM_GD",
                               *field->maillage->mesh);
    std::string what = field->nom_cham + "  " + p.where + "  " + occ.text("NOM_CMP");
    if (occ.has("LEGENDE")) what += "  [" + occ.text("LEGENDE") + "]";
    report_checks(occ, session, p.value, what);
  }
  return nullptr;
}

}  // namespace lunaster::cmd
