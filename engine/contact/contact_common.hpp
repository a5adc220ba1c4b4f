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
/// The contact state's components: CONT (status), JEU (gap), RN (norm of the normal force), RNX,
/// RNY[, RNZ] (the normal force), with `pressure` PRES, and with `friction` code_aster's friction
/// components: GLIX, GLIY (the slip of the last step along the point's tangents, m), GLI (its
/// norm), RTAX, RTAY[, RTAZ] (the tangential force at a sticking node), RTGX, RTGY[, RTGZ] (at a
/// slipping node), RX, RY[, RZ] (the whole contact force) and R (its norm).
std::vector<std::string> contact_state_components(int dim, bool pressure, bool friction = false);

/// One slave node of a method with one condition per slave node (node to segment, mortar).
struct NodalContactState {
  int node = -1;
  bool active = false;
  double gap = 0.0;                  ///< m, > 0 open
  double force[3] = {0.0, 0.0, 0.0}; ///< contact force on the slave node (N, or N per radian on AXIS)
  double pressure = 0.0;             ///< Pa, negative in compression
  // ---- with friction ----
  int status = 1;                          ///< CONT when active: 1 stick, 2 slip
  double tangential[3] = {0.0, 0.0, 0.0};  ///< tangential contact force on the node (N)
  double slip[2] = {0.0, 0.0};             ///< slip of the last step along the tangents (m)
};
/// CONT_NOEU of such a method: CONT, JEU, RN (norm of the force), RNX, RNY[, RNZ], PRES, and
/// with `friction` the friction components (contact_state_components).
NodalField nodal_contact_field(const std::vector<NodalContactState>& states, int n_nodes, int dim,
                               bool friction = false);
/// Sets the friction components of `node` in a field of contact_state_components(dim, ., true):
/// the status (CONT), the slip, the tangential force under RTA* or RTG* by the status, and the
/// whole force R* (`normal` the normal force).
void set_friction_components(NodalField& field, int node, int dim, int status, const double* slip,
                             const double* tangential, const double* normal);

}  // namespace lunaster::engine::contact
