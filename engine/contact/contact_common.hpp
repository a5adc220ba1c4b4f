#pragma once
/// What both shared parts of contact use (contact_problem.hpp for point discretisations,
/// mortar_problem.hpp for mortar's dual rows) and the discretisations with them: names of
/// mesh entities for messages, the current configuration, the geometry loop's criterion, the
/// smallest slave edge, and the CONT_NOEU field of a method with one condition per slave node.
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/linalg.hpp"
#include "engine/fields/fields.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::contact {

/// "M12" or "#11" when the mesh has no names.
std::string cell_label(const Mesh& mesh, int cell);
/// "N5" or "#4".
std::string node_label(const Mesh& mesh, int node);
/// Node coordinates in the configuration u (3 per node; nodes without displacement unknowns unmoved).
std::vector<double> current_coordinates(const Mesh& mesh, const DofMap& dofs, int dim, const Vector& u);
/// Largest displacement change of `nodes` since `u_before`, over their largest displacement
/// (0 when nothing moved): the geometry loops' criterion for a new pairing.
double geometric_residual(const std::vector<int>& nodes, const DofMap& dofs, int dim, const Vector& u,
                          const Vector& u_before);
/// Smallest vertex-to-vertex edge length of surface cells (m).
double smallest_edge(const Mesh& mesh, const std::vector<int>& cells);

/// The result fields contact writes (fields.hpp's ResultStep::nodal), by the names the results
/// keep: the displacements (where a method without multiplier unknowns reports its pressure,
/// as the DOF map's LAGS_C component) and the nodal contact state.
inline constexpr const char* kDisplacementField = "DEPL";
inline constexpr const char* kContactStateField = "CONT_NOEU";
/// The contact state's components: CONT (status), JEU (gap), RN (norm of the force), RNX, RNY[,
/// RNZ] (the force), and with `pressure` PRES.
std::vector<std::string> contact_state_components(int dim, bool pressure);

/// One slave node of a method with one condition per slave node (node to segment, mortar).
struct NodalContactState {
  int node = -1;
  bool active = false;
  double gap = 0.0;                  ///< m, > 0 open
  double force[3] = {0.0, 0.0, 0.0}; ///< contact force on the slave node (N, or N per radian on AXIS)
  double pressure = 0.0;             ///< Pa, negative in compression
};
/// CONT_NOEU of such a method: CONT, JEU, RN (norm of the force), RNX, RNY[, RNZ], PRES.
NodalField nodal_contact_field(const std::vector<NodalContactState>& states, int n_nodes, int dim);

}  // namespace lunaster::engine::contact
