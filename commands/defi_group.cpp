// DEFI_GROUP: creates node groups (from cell groups or node lists) and cell groups.
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"

namespace lunaster::cmd {

namespace {

void create_node_groups(const Args& occ, engine::Mesh& mesh, Session& session, bool say) {
  if (occ.has("TOUT_GROUP_MA")) {
    const auto groups = mesh.cell_groups;  // copy: adding node groups does not touch it, but be explicit
    for (const auto& [name, cells] : groups) mesh.add_to_node_group(name, mesh.nodes_of_cells(cells));
    return;
  }
  if (occ.has("GROUP_MA")) {
    for (const auto& g : occ.texts("GROUP_MA")) {
      const auto& cells = cell_group(occ, "GROUP_MA", mesh, g);
      const std::string name = occ.has("NOM") ? occ.text("NOM") : g;
      mesh.add_to_node_group(name, mesh.nodes_of_cells(cells));
      if (say)
        session.log().info("  node group " + name + ": " + std::to_string(mesh.node_groups[name].size()) + " nodes");
    }
    return;
  }
  if (occ.has("NOEUD")) {
    if (!occ.has("NOM")) throw occ.error("NOM", "a group name with NOEUD", "nothing");
    std::vector<int> nodes;
    for (const auto& n : occ.texts("NOEUD")) {
      const int i = mesh.find_node(n);
      require_somewhere(mesh, i >= 0, occ.error("NOEUD", "a node name of the mesh", "'" + n + "'"));
      if (i >= 0) nodes.push_back(i);
    }
    mesh.add_to_node_group(occ.text("NOM"), nodes);
    return;
  }
  if (occ.has("GROUP_NO")) {
    if (!occ.has("NOM")) throw occ.error("NOM", "a group name with GROUP_NO", "nothing");
    std::vector<int> nodes;
    for (const auto& g : occ.texts("GROUP_NO")) {
      auto more = node_group(occ, "GROUP_NO", mesh, g);
      nodes.insert(nodes.end(), more.begin(), more.end());
    }
    mesh.add_to_node_group(occ.text("NOM"), nodes);
  }
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
      const std::vector<int> cells = select_cells(occ, *mesh);
      require_somewhere(*mesh, !cells.empty(),
                        occ.error("NOM", "a selection of at least one cell", "an empty selection"));
      mesh->add_to_cell_group(occ.text("NOM"), cells);
    }
    for (const auto& occ : args.factors("CREA_GROUP_NO")) create_node_groups(occ, *mesh, session, say);
  }
  return ma;
}

}  // namespace lunaster::cmd
