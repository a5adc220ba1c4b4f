#include "commands/concepts.hpp"

namespace lunaster::cmd {

engine::FeModel build_fe_model(const Modele& mo, const ChamMater& cm, const catalog::Args& args, const std::string& kw) {
  const engine::Mesh& mesh = *mo.maillage->mesh;
  if (cm.maillage->mesh != mo.maillage->mesh)
    throw args.error(kw, "a material field on the model's mesh", "one defined on another mesh");
  engine::FeModel model;
  model.mesh = &mesh;
  model.dim = mo.dim;
  model.modelisation = mo.modelisation;
  model.material = cm.material;
  model.materials = cm.materials;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mo.modelisation[c] != engine::Modelisation::None && cm.material[c] < 0)
      throw args.error(kw, "a material on every modelled cell",
                       "none on cell " + mesh.cell_names[c] + " (" + std::string(engine::cell_info(mesh.cell_types[c]).name) + ")",
                       {"add its group to AFFE_MATERIAU/AFFE"});
  return model;
}

}  // namespace lunaster::cmd
