// AFFE_MODELE: assigns mechanical elements (D_PLAN, C_PLAN, 3D, AXIS) to cells.
#include <sstream>

#include "engine/parallel/mpi_runtime.hpp"

#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/parts.hpp"
#include "commands/selection.hpp"

namespace lunaster::cmd {

namespace {

engine::Modelisation to_modelisation(const std::string& name) {
  if (name == "D_PLAN") return engine::Modelisation::PlaneStrain;
  if (name == "C_PLAN") return engine::Modelisation::PlaneStress;
  if (name == "AXIS") return engine::Modelisation::Axisymmetric;
  return engine::Modelisation::Solid3D;
}

/// AXIS: x is the radius, so every node of an axisymmetric cell must have x >= 0.
template <class Occurrence>
void check_axis_cell(const Occurrence& occ, const engine::Mesh& mesh, int c) {
  const int* nodes = mesh.cell(c);
  for (int a = 0, nn = mesh.cell_n_nodes(c); a < nn; ++a) {
    const double r = mesh.node(nodes[a])[0];
    if (r < 0.0) {
      std::ostringstream given;
      given.precision(17);
      given << "node " << mesh.node_names[nodes[a]] << " of cell " << mesh.cell_names[c] << " at x = " << r;
      throw occ.error("MODELISATION", "'AXIS' cells with every node at x = r >= 0 (x is the radius)", given.str());
    }
  }
}

}  // namespace

ConceptPtr affe_modele(const Args& args, Session& session) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  const engine::Mesh& mesh = *ma->mesh;
  auto mo = std::make_shared<Modele>();
  mo->maillage = ma;
  mo->modelisation.assign(mesh.n_cells(), engine::Modelisation::None);
  int n_volume = 0;
  bool axis_model = false;
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
    // AXIS measures are per radian, plane ones per unit thickness: one model cannot hold both.
    const bool axis = mod == engine::Modelisation::Axisymmetric;
    if (dim == 2 && mo->dim == 2 && axis != axis_model)
      throw occ.error("MODELISATION",
                      axis_model ? "'AXIS' as in the other occurrences (an axisymmetric model cannot mix plane "
                                   "modelisations)"
                                 : "'D_PLAN' or 'C_PLAN' as in the other occurrences (a plane model cannot mix "
                                   "'AXIS')",
                      "'" + name + "'");
    axis_model = axis;
    mo->dim = dim;
    for (int c : select_cells(occ, mesh)) {
      // Cells of the modelisation's dimension carry the element; boundary cells
      // (edges in 2D, faces in 3D) are kept as skins for loads and contact.
      const int cdim = engine::cell_info(mesh.cell_types[c]).dim;
      if (cdim == dim) {
        if (axis) check_axis_cell(occ, mesh, c);
        if (mo->modelisation[c] == engine::Modelisation::None) ++n_volume;
        mo->modelisation[c] = mod;
      }
    }
  }
  require_somewhere(mesh, n_volume > 0,
                    args.error("AFFE", "a selection containing cells of the modelisation's dimension",
                               "none (only boundary cells or points)"));
  double counted = n_volume;
  if (ma->part) {
    // Each rank counts the cells it assembles (a ghost cell is another rank's), once every
    // rank has modelled its part: the count is the whole mesh's.
    agree_over_ranks(nullptr);
    counted = 0;
    for (int c = 0; c < mesh.n_cells(); ++c)
      counted += mo->modelisation[c] != engine::Modelisation::None && ma->part->cell_part[c] == ma->part->rank;
    engine::parallel::sum_over_ranks(&counted, 1);
  }
  session.log().info("  " + std::to_string(static_cast<long long>(counted)) + " cells carry a " +
                     std::to_string(mo->dim) + "D element");
  return mo;
}

}  // namespace lunaster::cmd
