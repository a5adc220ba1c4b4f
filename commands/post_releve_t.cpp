// POST_RELEVE_T: reads nodal field values of a result into a table. Columns follow
// code_aster's: INTITULE, RESU, NOM_CHAM, NUME_ORDRE, INST, then NOEUD and COOR_X/Y/Z for
// an extraction node by node, then the components.
#include <algorithm>
#include <cmath>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"
#include "commands/table.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

std::vector<const engine::ResultStep*> releve_steps(const Args& occ, const EvolNoli& resu) {
  std::vector<const engine::ResultStep*> out;
  if (occ.has("NUME_ORDRE")) {
    for (long long order : occ.integers("NUME_ORDRE")) {
      auto it = std::find_if(resu.steps.begin(), resu.steps.end(), [&](const auto& s) { return s.nume_ordre == order; });
      if (it == resu.steps.end())
        throw occ.error("NUME_ORDRE", "a step stored in the result (0.." + std::to_string(resu.steps.size() - 1) + ")",
                        std::to_string(order));
      out.push_back(&*it);
    }
  } else if (occ.has("INST")) {
    for (double t : occ.reals("INST")) {
      auto it = std::find_if(resu.steps.begin(), resu.steps.end(), [&](const auto& s) {
        return std::abs(s.inst - t) <= 1e-6 * std::max(1.0, std::abs(t));
      });
      if (it == resu.steps.end()) throw occ.error("INST", "an instant stored in the result", std::to_string(t));
      out.push_back(&*it);
    }
  } else {
    for (const auto& s : resu.steps) out.push_back(&s);
  }
  return out;
}

/// The field NOM_CHAM of a step; DeckError naming the fields the step holds.
const engine::NodalField& field_of(const Args& occ, const engine::ResultStep& step) {
  const std::string cham = occ.text("NOM_CHAM");
  auto it = step.nodal.find(cham);
  if (it != step.nodal.end()) return it->second;
  std::string have;
  for (const auto& [name, field] : step.nodal) have += (have.empty() ? "" : ", ") + name;
  throw occ.error("NOM_CHAM", "a nodal field stored at NUME_ORDRE " + std::to_string(step.nume_ordre) + " (" + have + ")",
                  "'" + cham + "'", {"REAC_NODA, FORC_NODA and SIGM_NOEU need CALC_CHAMP first"});
}

/// Columns of the components read: NOM_CMP, RESULTANTE or every component (TOUT_CMP).
std::vector<int> component_columns(const Args& occ, const engine::NodalField& field, std::vector<std::string>& names) {
  const char* kw = occ.has("RESULTANTE") ? "RESULTANTE" : "NOM_CMP";
  names = occ.has("TOUT_CMP") ? field.components : occ.texts(kw);
  std::vector<int> out;
  for (const auto& name : names) {
    const int c = field.component_index(name);
    if (c < 0) {
      std::string have;
      for (const auto& n : field.components) have += (have.empty() ? "" : ", ") + n;
      throw occ.error(kw, "a component of " + occ.text("NOM_CHAM") + " (" + have + ")", "'" + name + "'");
    }
    out.push_back(c);
  }
  return out;
}

/// One selected node of a mesh in parts, from the rank owning it: its number in the whole mesh,
/// name, coordinates and the values of the components read.
struct OwnedNode {
  double global = 0.0;
  std::string name;
  std::vector<double> coords, values;  ///< values: defined (0/1), value, for each component
};

/// The selected nodes of every rank's part, each once (from its owner), in the whole mesh's
/// order: the rows of the serial extraction. Collective.
std::vector<OwnedNode> owned_nodes_everywhere(const engine::MeshPart& part, const std::vector<int>& nodes,
                                              const engine::NodalField& field, const std::vector<int>& cmps, int dim) {
  namespace parallel = engine::parallel;
  const size_t width = 1 + dim + 2 * cmps.size();
  std::vector<double> numbers;
  std::string names;
  for (int node : nodes) {
    if (!part.owns(node)) continue;
    numbers.push_back(part.global_node[node]);
    for (int d = 0; d < dim; ++d) numbers.push_back(part.mesh.node(node)[d]);
    for (int c : cmps) {
      numbers.push_back(field.has(node, c) ? 1.0 : 0.0);
      numbers.push_back(field.has(node, c) ? field.value(node, c) : 0.0);
    }
    names += part.mesh.node_names[node] + '\n';
  }
  const std::vector<double> all = parallel::gather_all(numbers);
  const std::string all_names = parallel::gather_all(names);
  std::vector<OwnedNode> out(all.size() / width);
  size_t at = 0;
  for (size_t k = 0; k < out.size(); ++k) {
    const double* row = &all[k * width];
    out[k].global = row[0];
    out[k].coords.assign(row + 1, row + 1 + dim);
    out[k].values.assign(row + 1 + dim, row + width);
    const size_t end = all_names.find('\n', at);
    out[k].name = all_names.substr(at, end - at);
    at = end + 1;
  }
  std::sort(out.begin(), out.end(), [](const OwnedNode& a, const OwnedNode& b) { return a.global < b.global; });
  return out;
}

void add_action(const Args& occ, Table& table) {
  auto resu = occ.concept_as<EvolNoli>("RESULTAT");
  const engine::Mesh& mesh = *resu->modele->maillage->mesh;
  const std::vector<int> nodes = select_nodes(occ, mesh);
  // On a mesh in parts each node is read from its owner, and the ranks' rows or sums are put
  // together on every rank: the table of the serial run, the same on every rank.
  const engine::MeshPart* part = resu->modele->maillage->part.get();
  if (part) agree_over_ranks(nullptr);
  const bool extraction = occ.text("OPERATION") == "EXTRACTION" && !occ.has("RESULTANTE");
  for (const engine::ResultStep* step : releve_steps(occ, *resu)) {
    const engine::NodalField& field = field_of(occ, *step);
    std::vector<std::string> names;
    const std::vector<int> cmps = component_columns(occ, field, names);
    const std::vector<std::pair<std::string, Cell>> head = {
        {"INTITULE", occ.text("INTITULE")}, {"RESU", resu->user_name}, {"NOM_CHAM", occ.text("NOM_CHAM")},
        {"NUME_ORDRE", static_cast<long long>(step->nume_ordre)}, {"INST", step->inst}};
    if (extraction && part) {
      static const char* coor[] = {"COOR_X", "COOR_Y", "COOR_Z"};
      for (const OwnedNode& node : owned_nodes_everywhere(*part, nodes, field, cmps, resu->modele->dim)) {
        auto row = head;
        row.emplace_back("NOEUD", node.name);
        for (int d = 0; d < resu->modele->dim; ++d) row.emplace_back(coor[d], node.coords[d]);
        for (size_t k = 0; k < cmps.size(); ++k)
          if (node.values[2 * k] != 0.0) row.emplace_back(names[k], node.values[2 * k + 1]);
        table.add_row(row);
      }
      continue;
    }
    if (extraction) {
      for (int node : nodes) {
        auto row = head;
        row.emplace_back("NOEUD", mesh.node_names[node]);
        static const char* coor[] = {"COOR_X", "COOR_Y", "COOR_Z"};
        for (int d = 0; d < resu->modele->dim; ++d) row.emplace_back(coor[d], mesh.node(node)[d]);
        for (size_t k = 0; k < cmps.size(); ++k)
          if (field.has(node, cmps[k])) row.emplace_back(names[k], field.value(node, cmps[k]));
        table.add_row(row);
      }
      continue;
    }
    // RESULTANTE (sum) or MOYENNE_ARITH (mean) over the nodes where the component exists.
    auto row = head;
    for (size_t k = 0; k < cmps.size(); ++k) {
      double sum = 0.0;
      double n = 0, selected = static_cast<double>(nodes.size());
      if (part)
        selected = static_cast<double>(std::count_if(nodes.begin(), nodes.end(), [&](int v) { return part->owns(v); }));
      for (int node : nodes)
        if ((!part || part->owns(node)) && field.has(node, cmps[k])) sum += field.value(node, cmps[k]), ++n;
      if (part) {
        double all[3] = {sum, n, selected};
        engine::parallel::sum_over_ranks(all, 3);
        sum = all[0], n = all[1], selected = all[2];
      }
      if (n == 0)
        throw occ.error(occ.has("RESULTANTE") ? "RESULTANTE" : "NOM_CMP", "a component defined on the selected nodes",
                        "'" + names[k] + "' undefined on all " + std::to_string(static_cast<long long>(selected)) +
                            " of them");
      row.emplace_back(names[k], occ.has("RESULTANTE") ? sum : sum / n);
    }
    table.add_row(row);
  }
}

}  // namespace

ConceptPtr post_releve_t(const Args& args, Session& session) {
  Session::Timer timer(session, "post");
  auto table = std::make_shared<Table>();
  for (const auto& occ : args.factors("ACTION")) add_action(occ, *table);
  session.log().info("POST_RELEVE_T: table of " + std::to_string(table->n_rows()) + " row(s), parameters " +
                     table->parameter_list());
  return table;
}

}  // namespace lunaster::cmd
