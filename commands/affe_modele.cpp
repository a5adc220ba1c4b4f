// AFFE_MODELE: assigns mechanical elements (D_PLAN, C_PLAN, 3D) to cells.
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"

namespace lunaster::cmd {

namespace {

engine::Modelisation to_modelisation(const std::string& name) {
  if (name == "D_PLAN") return engine::Modelisation::PlaneStrain;
  if (name == "C_PLAN") return engine::Modelisation::PlaneStress;
  return engine::Modelisation::Solid3D;
}

}  // namespace

ConceptPtr affe_modele(const Args& args, Session& session) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  const engine::Mesh& mesh = *ma->mesh;
  auto mo = std::make_shared<Modele>();
  mo->maillage = ma;
  mo->modelisation.assign(mesh.n_cells(), engine::Modelisation::None);
  int n_volume = 0;
  for (const auto& occ : args.factors("AFFE")) {
    const std::string name = occ.text("MODELISATION");
    const engine::Modelisation mod = to_modelisation(name);
    const int dim = mod == engine::Modelisation::Solid3D ? 3 : 2;
    if (mo->dim != 0 && mo->dim != dim)
      throw occ.error("MODELISATION", std::to_string(mo->dim) + "D modelisations as in the other occurrences",
                      "'" + name + "'");
    if (mesh.dim < dim)
      throw occ.error("MODELISATION", "a modelisation of the mesh's dimension (" + std::to_string(mesh.dim) + "D)",
                      "'" + name + "'");
    mo->dim = dim;
    for (int c : select_cells(occ, mesh)) {
      // Cells of the modelisation's dimension carry the element; boundary cells
      // (edges in 2D, faces in 3D) are kept as skins for loads and contact.
      const int cdim = engine::cell_info(mesh.cell_types[c]).dim;
      if (cdim == dim) {
        if (mo->modelisation[c] == engine::Modelisation::None) ++n_volume;
        mo->modelisation[c] = mod;
      }
    }
  }
  if (n_volume == 0)
    throw args.error("AFFE", "a selection containing cells of the modelisation's dimension",
                     "none (only boundary cells or points)");
  session.log().info("  " + std::to_string(n_volume) + " cells carry a " + std::to_string(mo->dim) + "D element");
  return mo;
}

}  // namespace lunaster::cmd
