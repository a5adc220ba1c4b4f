// MODI_MAILLAGE: orients boundary cells outward (ORIE_PEAU_2D / ORIE_PEAU_3D).
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"
#include "engine/mesh/orientation.hpp"

namespace lunaster::cmd {

ConceptPtr modi_maillage(const Args& args, Session& session) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  engine::Mesh& mesh = *ma->mesh;
  for (const char* kw : {"ORIE_PEAU_2D", "ORIE_PEAU_3D"}) {
    for (const auto& occ : args.factors(kw)) {
      const int needed = std::string(kw) == "ORIE_PEAU_2D" ? 2 : 3;
      if (mesh.dim != needed)
        throw occ.error("GROUP_MA", "a " + std::to_string(needed) + "D mesh for " + kw,
                        "a " + std::to_string(mesh.dim) + "D mesh", {"use ORIE_PEAU_" + std::to_string(mesh.dim) + "D"});
      for (const auto& g : occ.texts("GROUP_MA")) {
        const auto cells = cell_group(occ, "GROUP_MA", mesh, g);
        const int flipped = engine::orient_boundary_outward(mesh, cells);
        session.log().info("  " + std::string(kw) + " " + g + ": " + std::to_string(flipped) + " of " +
                           std::to_string(cells.size()) + " cells reoriented");
      }
    }
  }
  return ma;
}

}  // namespace lunaster::cmd
