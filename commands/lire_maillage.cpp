// LIRE_MAILLAGE: reads a MED, Gmsh or code_aster text (.mail) mesh.
#include <exception>
#include <filesystem>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/failures.hpp"
#include "commands/parts.hpp"
#include "engine/io/aster_mail_reader.hpp"
#include "engine/io/gmsh_reader.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/mesh/mesh_bytes.hpp"
#include "engine/mesh/mesh_checks.hpp"
#include "engine/mesh/orientation.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

/// The .export file type and the file extension of a FORMAT.
const char* export_type(const std::string& format) {
  return format == "GMSH" ? "msh" : format == "ASTER" ? "mail" : "mmed";
}

/// Under an .export, UNITE is the unit its `F mmed|msh|mail PATH D UNIT` line binds. Otherwise
/// UNITE 20 is the mesh of the study: <deck name>.med (or .msh, .mail) beside the deck;
/// any other unit maps to fort.<UNITE> beside the deck, as in a code_aster study folder.
std::filesystem::path mesh_path(const Args& args, const Session& session, const std::string& format) {
  if (args.has("FICHIER")) return session.resolve_input(args.text("FICHIER"));
  const long long unit = args.integer("UNITE");
  if (!session.export_path.empty()) {
    const std::string type = export_type(format);
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
    p.replace_extension(format == "GMSH" ? ".msh" : format == "ASTER" ? ".mail" : ".med");
    return p;
  }
  return session.deck_path.parent_path() / ("fort." + std::to_string(unit));
}

/// Reads the mesh file into `mesh` and reorients its clockwise 2D and mirrored 3D cells
/// (valid cells listed in the other orientation; tangled or collapsed cells stop the run).
/// Returns the reoriented cells.
std::vector<int> read_mesh_file(const Args& args, const std::string& format, const std::filesystem::path& path,
                                engine::Mesh& mesh) {
  if (format == "GMSH") {
    mesh = engine::read_gmsh(path.string());
  } else if (format == "ASTER") {
    mesh = engine::read_aster_mail(path.string());
  } else {
    try {
      mesh = engine::read_med(path.string(), args.has("NOM_MED") ? args.text("NOM_MED") : std::string());
    } catch (Error& err) {
      say_in_keywords(err);
      throw;
    }
  }
  return engine::orient_cells(mesh, path.string());
}

/// The first ten of `items`, by `name`, comma-separated.
template <class T, class Name>
std::string first_names(const std::vector<T>& items, Name name) {
  std::string out;
  for (size_t i = 0; i < items.size() && i < 10; ++i) out += (i ? ", " : "") + name(items[i]);
  return items.size() > 10 ? out + ", ..." : out;
}

/// VERI_MAIL: code_aster's checks of a mesh read, as warnings. Without VERI_MAIL only the nodes in
/// no cell are reported; VERIF='NON' reports nothing.
void verify_mesh(const Args& args, Session& session, const engine::Mesh& mesh, const std::filesystem::path& path) {
  const bool given = args.count("VERI_MAIL") > 0;
  if (given && args.factor("VERI_MAIL").text("VERIF") == "NON") return;
  const std::string file = "mesh file '" + path.string() + "': ";
  const auto node_name = [&](int n) { return mesh.node_names[n]; };
  const auto cell_name = [&](int c) { return mesh.cell_names[c]; };
  if (const auto orphans = engine::unreferenced_nodes(mesh); !orphans.empty())
    session.warn(file + std::to_string(orphans.size()) + " node(s) belong to no cell and carry no unknown: " +
                 first_names(orphans, node_name));
  if (!given) return;
  if (const auto twice = engine::cells_repeating_a_node(mesh); !twice.empty())
    session.warn(file + std::to_string(twice.size()) + " cell(s) list a node twice (VERI_MAIL): " +
                 first_names(twice, cell_name));
  if (const auto doubles = engine::duplicate_cells(mesh); !doubles.empty())
    session.warn(file + std::to_string(doubles.size()) + " pair(s) of cells of one type on the same nodes (VERI_MAIL): " +
                 first_names(doubles, [&](const std::pair<int, int>& p) {
                   return mesh.cell_names[p.first] + " = " + mesh.cell_names[p.second];
                 }));
  const double aplat = args.factor("VERI_MAIL").real("APLAT");
  if (const auto flat = engine::flat_cells(mesh, aplat); !flat.empty())
    session.warn(file + std::to_string(flat.size()) + " flat cell(s), shortest over longest distance between their nodes below APLAT = " +
                 number_text(aplat) + " (VERI_MAIL): " +
                 first_names(flat, [&](const std::pair<int, double>& f) {
                   return mesh.cell_names[f.first] + " (" + number_text(f.second) + ")";
                 }));
}

}  // namespace

ConceptPtr lire_maillage(const Args& args, Session& session) {
  Session::Timer timer(session, "read");
  const std::string format = args.text("FORMAT");
  if (format != "MED" && args.has("NOM_MED"))
    throw args.error("NOM_MED", "no NOM_MED with FORMAT='" + format + "' (the file holds one mesh)",
                     "NOM_MED='" + args.text("NOM_MED") + "'", {"remove NOM_MED, or read a MED file (FORMAT='MED')"});
  const std::filesystem::path path = mesh_path(args, session, format);
  auto result = std::make_shared<Maillage>();
  result->source_file = path.string();
  std::vector<int> reoriented;
  namespace parallel = engine::parallel;
  if (args.has("PARTITIONNEUR")) {
    // A mesh in parts: rank 0 reads the file, cuts the mesh with Scotch and sends each rank its
    // part (its cells, the ghost layer, their nodes, every group restricted); it keeps the whole
    // mesh for IMPR_RESU. From here on the commands agree over the ranks (commands/parts.hpp).
    set_parts_in_run(true);
    if (parallel::rank() == 0) result->whole = std::make_shared<engine::Mesh>();
    agreed([&] {
      if (result->whole) reoriented = read_mesh_file(args, format, path, *result->whole);
    });
    result->part = std::make_shared<engine::MeshPart>(engine::distribute_mesh(result->whole.get()));
    result->part->mesh.is_part = true;
    result->mesh = std::shared_ptr<engine::Mesh>(result->part, &result->part->mesh);
  } else if (parallel::size() == 1) {
    reoriented = read_mesh_file(args, format, path, *result->mesh);
  } else {
    // Under mpirun the file is read once, by rank 0, which sends the mesh (reoriented) to the
    // others: one reader of a shared file, not one per rank. Only rank 0 logs, so only it
    // keeps the list of reoriented cells. Where rank 0 cannot read the file, the others read
    // it themselves and so stop on the same error (or, if the failure was rank 0's alone,
    // carry on until the run is brought down by rank 0's error).
    std::exception_ptr failure;
    std::string bytes;
    if (parallel::rank() == 0) {
      try {
        reoriented = read_mesh_file(args, format, path, *result->mesh);
        bytes = engine::mesh_to_bytes(*result->mesh);
      } catch (...) {
        failure = std::current_exception();
      }
    }
    int read = failure ? 0 : 1;
    parallel::broadcast(&read, 1);
    if (failure) std::rethrow_exception(failure);
    if (!read) {
      read_mesh_file(args, format, path, *result->mesh);
    } else {
      parallel::broadcast(bytes);
      if (parallel::rank() != 0) *result->mesh = engine::mesh_from_bytes(bytes);
    }
  }
  // What the log says of the mesh is said of the whole mesh (rank 0 holds it with a part).
  const auto& mesh = result->whole ? *result->whole : *result->mesh;
  if (result->part && !result->whole) return result;  // a rank other than 0 logs nothing
  verify_mesh(args, session, mesh, path);
  session.log().info("  mesh " + path.filename().string() + ": " + std::to_string(mesh.n_nodes()) + " nodes, " +
                     std::to_string(mesh.n_cells()) + " cells, dimension " + std::to_string(mesh.dim));
  if (result->part)
    session.log().info("  mesh in " + std::to_string(result->part->parts) + " part(s) (PARTITIONNEUR = '" +
                       args.text("PARTITIONNEUR") + "': Scotch on rank 0), this rank's " +
                       std::to_string(result->part->n_owned_nodes) + " owned nodes and " +
                       std::to_string(result->part->mesh.n_nodes() - result->part->n_owned_nodes) + " ghosts");
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
