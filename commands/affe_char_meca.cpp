// AFFE_CHAR_MECA: imposed displacements, pressures, nodal forces and (seed syntax) contact.
#include <algorithm>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/contact_keywords.hpp"
#include "commands/selection.hpp"

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

void read_pres_rep(const Args& occ, const Modele& mo, CharMeca& load) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  std::vector<int> cells;
  for (int c : select_cells(occ, mesh))
    if (engine::cell_info(mesh.cell_types[c]).dim == mo.dim - 1) cells.push_back(c);
  if (cells.empty())
    throw occ.error("GROUP_MA", "boundary cells (" + std::string(mo.dim == 2 ? "SEG2/SEG3" : "TRIA/QUAD") + ")",
                    "a selection without any");
  load.pressures.push_back({cells, occ.real("PRES"), 0});
}

void read_force_nodale(const Args& occ, const Modele& mo, CharMeca& load) {
  const std::vector<int> nodes = select_nodes(occ, *mo.maillage->mesh);
  for (ComponentKeyword ck : {ComponentKeyword{"FX", engine::DX}, {"FY", engine::DY}, {"FZ", engine::DZ}}) {
    if (!occ.has(ck.name)) continue;
    const double value = occ.real(ck.name);
    for (int n : nodes) load.forces.push_back({n, ck.component, value, 0});
  }
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

}  // namespace

ConceptPtr affe_char_meca(const Args& args, Session& session) {
  auto load = std::make_shared<CharMeca>();
  load->modele = args.concept_as<Modele>("MODELE");
  const Modele& mo = *load->modele;
  for (const auto& occ : args.factors("DDL_IMPO")) read_ddl_impo(occ, mo, *load);
  for (const auto& occ : args.factors("PRES_REP")) read_pres_rep(occ, mo, *load);
  for (const auto& occ : args.factors("FORCE_NODALE")) read_force_nodale(occ, mo, *load);
  if (args.count("CONTACT") > 0) {
    load->has_contact = true;
    auto& def = load->contact;
    for (const auto& occ : args.factors("CONTACT")) {
      check_modl_axis(occ, mo);
      def.method = seed_method(occ.text("METHODE"));
      def.zones.push_back(read_contact_zone(occ, *mo.maillage->mesh, mo.dim, def.method));
      warn_coincident_slave_nodes(occ, def.zones.back(), *mo.maillage, session);
      read_contact_loops(occ, def);
    }
    warn_incompatible_pairs(def, *mo.maillage->mesh, session);
  }
  return load;
}

}  // namespace lunaster::cmd
