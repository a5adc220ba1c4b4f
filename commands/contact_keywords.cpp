#include "commands/contact_keywords.hpp"

#include <algorithm>
#include <cstdio>

#include "commands/parts.hpp"
#include "commands/selection.hpp"
#include "engine/contact/compatibility.hpp"
#include "engine/mesh/mesh_checks.hpp"

namespace lunaster::cmd {

namespace {

using engine::IntegrationScheme;

bool opt(const catalog::Args& a, const char* kw) { return a.declares(kw) && a.has(kw); }

/// Seed names SIMPSON1/SIMPSON2 and NCOTES1/NCOTES2 mean the scheme on 2 / 3
/// sub-elements of the slave cell (the seed: 'SIMPSON2' uses three
/// sub-elements); current code_aster spells Simpson sub-elements as ORDRE_INT.
void read_integration(const catalog::Args& zone, engine::ContactZone& z) {
  const std::string name = opt(zone, "INTEGRATION") ? zone.text("INTEGRATION") : "AUTO";
  std::string base = name;
  int sub = 1;
  if (!name.empty() && (name.back() == '1' || name.back() == '2')) {
    sub = name.back() == '1' ? 2 : 3;
    base = name.substr(0, name.size() - 1);
  }
  if (base == "GAUSS") z.integration = IntegrationScheme::Gauss;
  else if (base == "SIMPSON") z.integration = IntegrationScheme::Simpson;
  else if (base == "NCOTES") z.integration = IntegrationScheme::NewtonCotes;
  else if (base == "NOEUD") z.integration = IntegrationScheme::Nodes;
  else z.integration = IntegrationScheme::Auto;
  if (z.integration == IntegrationScheme::Simpson) {
    z.integration_order = sub;  // SIMPSONk: composite Simpson on k+1 sub-elements
    sub = 1;
  }
  z.sub_elements = sub;
  if (opt(zone, "ORDRE_INT")) z.integration_order = static_cast<int>(zone.integer("ORDRE_INT"));
}

std::vector<int> contact_surface(const catalog::Args& zone, const char* kw, const engine::Mesh& mesh, int model_dim) {
  const std::string group = zone.text(kw);
  const std::vector<int>& cells = cell_group(zone, kw, mesh, group);
  for (int c : cells)
    if (engine::cell_info(mesh.cell_types[c]).dim != model_dim - 1)
      throw zone.error(kw, "a group of boundary cells (" + std::string(model_dim == 2 ? "SEG2/SEG3" : "TRIA/QUAD") + ")",
                       "'" + group + "' containing " + std::string(engine::cell_info(mesh.cell_types[c]).name) +
                           " cell " + mesh.cell_names[c]);
  return cells;
}

}  // namespace

engine::ContactZone read_contact_zone(const catalog::Args& zone, const engine::Mesh& mesh, int model_dim,
                                      engine::ContactMethod method) {
  engine::ContactZone z;
  z.slave_cells = contact_surface(zone, "GROUP_MA_ESCL", mesh, model_dim);
  z.master_cells = contact_surface(zone, "GROUP_MA_MAIT", mesh, model_dim);
  z.slave_group = zone.text("GROUP_MA_ESCL");
  z.master_group = zone.text("GROUP_MA_MAIT");
  read_integration(zone, z);
  // code_aster marks a negative TOLE_PROJ_EXT as -1: any projection outside the cell is
  // excluded, as with 0 (a point inside is 0 outside).
  if (opt(zone, "TOLE_PROJ_EXT")) z.tole_proj_ext = std::max(0.0, zone.real("TOLE_PROJ_EXT"));
  if (opt(zone, "COEF_CONT")) z.coef_cont = zone.real("COEF_CONT");
  if (opt(zone, "COEF_REGU_CONT")) z.coef_cont = zone.real("COEF_REGU_CONT");
  if (opt(zone, "E_N")) z.coef_pena = zone.real("E_N");
  if (opt(zone, "COEF_PENA_CONT")) z.coef_pena = zone.real("COEF_PENA_CONT");
  if ((method == engine::ContactMethod::DiscretePenalty || method == engine::ContactMethod::ContinuousPenalty) &&
      z.coef_pena <= 0.0)
    throw zone.error("E_N", "a positive penalty coefficient (E_N or COEF_PENA_CONT) with penalisation", "none");
  if (opt(zone, "CONTACT_INIT")) {
    const std::string init = zone.text("CONTACT_INIT");
    z.init = init == "OUI" ? engine::ContactInit::Yes
             : init == "NON" ? engine::ContactInit::No
                             : engine::ContactInit::Interpenetrated;
  }
  return z;
}

void read_contact_loops(const catalog::Args& args, engine::ContactDefinition& def) {
  using engine::FixedPointOrNewton;
  if (opt(args, "ALGO_RESO_CONT"))
    def.status_loop = args.text("ALGO_RESO_CONT") == "NEWTON" ? FixedPointOrNewton::Newton : FixedPointOrNewton::FixedPoint;
  if (opt(args, "ALGO_RESO_GEOM"))
    def.geometry_loop = args.text("ALGO_RESO_GEOM") == "NEWTON" ? FixedPointOrNewton::Newton : FixedPointOrNewton::FixedPoint;
  if (opt(args, "REAC_GEOM")) {
    const std::string r = args.text("REAC_GEOM");
    def.reac_geom = r == "SANS" ? engine::GeometryUpdate::None
                    : r == "CONTROLE" ? engine::GeometryUpdate::Controlled
                                      : engine::GeometryUpdate::Automatic;
  }
  if (opt(args, "NB_ITER_GEOM")) def.nb_iter_geom = static_cast<int>(args.integer("NB_ITER_GEOM"));
  if (opt(args, "ITER_GEOM_MAXI")) def.iter_geom_maxi = static_cast<int>(args.integer("ITER_GEOM_MAXI"));
  // The discrete formulation's status loop is bounded per contact point (ITER_CONT_MULT, whose
  // default is code_aster's), unless ITER_CONT_MAXI names a number of iterations (the catalogue
  // refuses both, so ITER_CONT_MULT has no catalogue default).
  constexpr int kIterContMultDefault = 4;
  if (opt(args, "ITER_CONT_MAXI"))
    def.iter_cont_maxi = static_cast<int>(args.integer("ITER_CONT_MAXI"));
  else if (args.declares("ITER_CONT_MULT"))
    def.status_iterations_per_point =
        opt(args, "ITER_CONT_MULT") ? static_cast<int>(args.integer("ITER_CONT_MULT")) : kIterContMultDefault;
  if (opt(args, "RESI_GEOM")) def.resi_geom = args.real("RESI_GEOM");
}

void warn_incompatible_pairs(const engine::ContactDefinition& def, const engine::Mesh& mesh, Session& session) {
  // One rule, in the engine (engine/contact/compatibility): the message names the cells.
  for (size_t z = 0; z < def.zones.size(); ++z) {
    for (const auto& message : engine::check_contact_zone_compatibility(mesh, def.zones[z], static_cast<int>(z)))
      session.warn(message);
    const bool continuous = def.method == engine::ContactMethod::Continuous ||
                            def.method == engine::ContactMethod::ContinuousPenalty;
    if (continuous)
      for (const auto& w : engine::check_contact_zone_integration(mesh, def.zones[z], static_cast<int>(z)))
        session.warn(w.text + (w.kind == engine::IntegrationWarning::Kind::TooFewPoints
                                   ? " (ORDRE_INT; INTEGRATION='AUTO', 'SIMPSON' or 'NCOTES')"
                                   : " (INTEGRATION='GAUSS' or 'SIMPSON')"));
  }
}

void warn_coincident_slave_nodes(const catalog::Args& zone_args, const engine::ContactZone& zone,
                                 const engine::Mesh& mesh, const Maillage& ma, Session& session) {
  const double tolerance = engine::coincidence_tolerance(mesh, zone.slave_cells);
  const auto pairs = engine::coincident_nodes(mesh, mesh.nodes_of_cells(zone.slave_cells), tolerance);
  if (pairs.empty()) return;
  std::string list;
  for (size_t i = 0; i < pairs.size() && i < 10; ++i) {
    const double* p = mesh.node(pairs[i].first);
    char at[96];
    std::snprintf(at, sizeof at, " at (%g, %g, %g)", p[0], p[1], p[2]);
    list += (i ? ", " : "") + mesh.node_names[pairs[i].first] + " and " + mesh.node_names[pairs[i].second] + at;
  }
  if (pairs.size() > 10) list += ", ...";
  session.warn(zone_args.path("GROUP_MA_ESCL") + ": slave surface '" + zone_args.text("GROUP_MA_ESCL") +
               "' of mesh file '" + ma.source_file + "' has " + std::to_string(pairs.size()) +
               " pair(s) of distinct nodes at the same position: " + list +
               "; contact treats them as separate points (merge the nodes, or check the mesh for a crack)");
}

ContactSurfaces contact_surfaces(const engine::ContactDefinition& def, const Modele& mo, bool tie_columns) {
  ContactSurfaces out;
  out.definition = def;
  out.mesh = mo.maillage->mesh.get();
  if (!mo.in_parts()) return out;
  agree_over_ranks(nullptr);
  std::vector<std::vector<int>> lists;
  std::vector<char> layered;  // eliminated unknowns (mortar's slave ones, ties'): their whole columns
  for (const engine::ContactZone& zone : def.zones) {
    lists.push_back(zone.slave_cells);
    lists.push_back(zone.master_cells);
    layered.push_back(def.method == engine::ContactMethod::MortarLagrange || tie_columns);
    layered.push_back(tie_columns);
  }
  auto whole =
      std::make_shared<engine::SurfacePart>(engine::with_whole_surfaces(*mo.maillage->part, lists, layered));
  for (size_t z = 0; z < def.zones.size(); ++z) {
    out.definition.zones[z].slave_cells = whole->lists[2 * z];
    out.definition.zones[z].master_cells = whole->lists[2 * z + 1];
  }
  out.mesh = &whole->part.mesh;
  out.part = std::move(whole);
  return out;
}

void warn_contact_surfaces(const std::vector<catalog::Args>& zone_args, const ContactSurfaces& surfaces,
                           const Maillage& ma, Session& session, bool pairs) {
  for (size_t z = 0; z < zone_args.size(); ++z)
    warn_coincident_slave_nodes(zone_args[z], surfaces.definition.zones[z], *surfaces.mesh, ma, session);
  if (pairs) warn_incompatible_pairs(surfaces.definition, *surfaces.mesh, session);
}

}  // namespace lunaster::cmd
