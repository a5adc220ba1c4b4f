// LIRE_MAILLAGE: reads a MED or Gmsh mesh.
#include <filesystem>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "engine/io/gmsh_reader.hpp"
#include "commands/failures.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/mesh/mesh_checks.hpp"
#include "engine/mesh/orientation.hpp"

namespace lunaster::cmd {

namespace {

/// Under an .export, UNITE is the unit its `F mmed|msh PATH D UNIT` line binds. Otherwise
/// UNITE 20 is the mesh of the study: <deck name>.med (or .msh) beside the deck;
/// any other unit maps to fort.<UNITE> beside the deck, as in a code_aster study folder.
std::filesystem::path mesh_path(const Args& args, const Session& session, const std::string& format) {
  if (args.has("FICHIER")) return session.resolve_input(args.text("FICHIER"));
  const long long unit = args.integer("UNITE");
  if (!session.export_path.empty()) {
    const std::string type = format == "GMSH" ? "msh" : "mmed";
    const auto found = session.data_units.find(static_cast<int>(unit));
    std::string units;
    for (const auto& [n, f] : session.data_units) units += (units.empty() ? "" : ", ") + std::to_string(n) + " (" + f.type + ")";
    if (found == session.data_units.end())
      throw args.error("UNITE", "a data unit of " + session.export_path.string() + (units.empty() ? " (it has none)" : ": " + units),
                       std::to_string(unit), {"add a line 'F " + type + " MESH_FILE D " + std::to_string(unit) + "' to the .export"});
    if (found->second.type != type)
      throw args.error("UNITE", "a '" + type + "' file for FORMAT='" + format + "'",
                       "unit " + std::to_string(unit) + ", a '" + found->second.type + "' file in " + session.export_path.string());
    return found->second.path;
  }
  if (unit == 20) {
    std::filesystem::path p = session.deck_path;
    p.replace_extension(format == "GMSH" ? ".msh" : ".med");
    return p;
  }
  return session.deck_path.parent_path() / ("fort." + std::to_string(unit));
}

}  // namespace

ConceptPtr lire_maillage(const Args& args, Session& session) {
  Session::Timer timer(session, "read");
  const std::string format = args.text("FORMAT");
  const std::filesystem::path path = mesh_path(args, session, format);
  auto result = std::make_shared<Maillage>();
  result->source_file = path.string();
  if (format == "GMSH") {
    *result->mesh = engine::read_gmsh(path.string());
  } else {
    try {
      *result->mesh = engine::read_med(path.string(), args.has("NOM_MED") ? args.text("NOM_MED") : std::string());
    } catch (Error& err) {
      say_in_keywords(err);
      throw;
    }
  }
  // Clockwise 2D cells and mirrored 3D cells are valid cells listed in the other
  // orientation: reorient them once here (tangled or collapsed cells stop the run).
  const std::vector<int> reoriented = engine::orient_cells(*result->mesh, path.string());
  const auto& mesh = *result->mesh;
  if (const auto orphans = engine::unreferenced_nodes(mesh); !orphans.empty()) {
    std::string names;
    for (size_t i = 0; i < orphans.size() && i < 10; ++i) names += (i ? ", " : "") + mesh.node_names[orphans[i]];
    if (orphans.size() > 10) names += ", ...";
    session.warn("mesh file '" + path.string() + "': " + std::to_string(orphans.size()) +
                 " node(s) belong to no cell and carry no unknown: " + names);
  }
  session.log().info("  mesh " + path.filename().string() + ": " + std::to_string(mesh.n_nodes()) + " nodes, " +
                     std::to_string(mesh.n_cells()) + " cells, dimension " + std::to_string(mesh.dim));
  if (!reoriented.empty()) {
    std::string names;
    for (size_t i = 0; i < reoriented.size() && i < 5; ++i) names += (i ? ", " : "") + mesh.cell_names[reoriented[i]];
    if (reoriented.size() > 5) names += ", ...";
    session.log().info("  mesh " + path.filename().string() + ": " + std::to_string(reoriented.size()) +
                       (mesh.dim == 2 ? " clockwise cell(s) reoriented counter-clockwise (node order reversed): "
                                      : " mirrored cell(s) reoriented (node order mirrored to MED's): ") +
                       names);
  }
  return result;
}

}  // namespace lunaster::cmd
