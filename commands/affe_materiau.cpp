// AFFE_MATERIAU: assigns materials to cells (later occurrences override earlier ones).
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"

namespace lunaster::cmd {

ConceptPtr affe_materiau(const Args& args, Session&) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  if (args.has("MODELE")) {
    auto mo = args.concept_as<Modele>("MODELE");
    if (mo->maillage->mesh != ma->mesh)
      throw args.error("MODELE", "a model of mesh '" + ma->user_name + "' (MAILLAGE)",
                       "'" + mo->user_name + "', a model of mesh '" + mo->maillage->user_name + "'");
  }
  auto cm = std::make_shared<ChamMater>();
  cm->maillage = ma;
  cm->material.assign(ma->mesh->n_cells(), -1);
  for (const auto& occ : args.factors("AFFE")) {
    auto mat = occ.concept_as<Mater>("MATER");
    if (!mat->has_elas)
      throw occ.error("MATER", "a material with ELAS", "'" + mat->user_name + "' without ELAS");
    cm->materials.push_back(mat->elas);
    cm->maters.push_back(mat);
    const int index = static_cast<int>(cm->materials.size()) - 1;
    for (int c : select_cells(occ, *ma->mesh)) cm->material[c] = index;
  }
  return cm;
}

}  // namespace lunaster::cmd
