#pragma once
/// Assembly of the elastic stiffness, internal forces and external loads.
#include <array>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/linalg.hpp"
#include "engine/fe/fe_model.hpp"

namespace lunaster::engine {

class CellBehaviours;
class MaterialStates;

/// Appends the stiffness of every volume cell of `model` as triplets.
/// Full integration for every element type (see engine/fe/quadrature). AXIS cells are
/// integrated per radian (weight r = x), as code_aster's AXIS elements.
void assemble_stiffness(const FeModel& model, const DofMap& dofs, std::vector<Triplet>& out);

/// The same stiffness assembled straight into a compressed matrix (n_dofs x n_dofs, both
/// triangles, sorted columns): the pattern comes from the cell connectivity (each node
/// coupled with every node of its cells, all their displacement components; DOFs that are
/// not displacements get empty columns) and the element matrices are added in place, so no
/// triplet list is ever stored. Each entry sums its cells in the same order as the
/// triplets' setFromTriplets does: pattern and values are those of that matrix.
///
/// With `owned_nodes` (a rank's share of the model under MPI, per mesh node): only the
/// columns of the owned nodes are filled, each complete (every cell of the node, also those
/// the rank shares with another); the other columns are empty. K being symmetric, the
/// owned columns are also the owned rows, and the ranks' matrices sum to K.
SparseMatrix assemble_stiffness_matrix(const FeModel& model, const DofMap& dofs,
                                       const std::vector<char>* owned_nodes = nullptr);

/// The same for the linear behaviours `behaviours` (each Behaviour::is_linear; the model's own
/// elasticity in the overload above): the tangent at rest.
SparseMatrix assemble_stiffness_matrix(const CellBehaviours& behaviours, const DofMap& dofs,
                                       const std::vector<char>* owned_nodes = nullptr);

/// f_int = K u for linear elasticity, assembled cell by cell (no global matrix needed).
/// With `cell_rank` (per mesh cell, the rank whose cell it is: a shared model's partition),
/// only this rank's cells are assembled: the ranks' vectors sum to the whole one.
void assemble_internal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, Vector& f_int,
                              const std::vector<int>* cell_rank = nullptr);

/// Zero states (MaterialStates) for the full-integration points of every volume cell of the
/// behaviours' model, with each cell's behaviour's internal variables. DeckError for a cell
/// carrying an element but no material.
MaterialStates make_material_states(const CellBehaviours& behaviours);

/// The model's internal force f_int = sum_e f_e and tangent K_t = sum_e K_e at displacement `u`,
/// every point integrated by its cell's behaviour from `states`' step start to the strain of `u`
/// under the cell's kinematics (CellBehaviours::kinematics: small strain, or total Lagrangian with
/// the Green-Lagrange strain, the second Piola-Kirchhoff stress in the states and the geometric
/// stiffness in k_t); the states' trial slot (end of step) is written. Each of `f_int` (n_dofs) and
/// `k_t` (n_dofs x n_dofs, the pattern of assemble_stiffness_matrix) is computed when given.
/// Returns false when a point's integration failed (the step is to be subdivided; the outputs
/// and the trial slot are then incomplete).
bool assemble_internal_force(const CellBehaviours& behaviours, const DofMap& dofs, const Vector& u,
                             MaterialStates& states, Vector* f_int, SparseMatrix* k_t);

/// Adds the consistent nodal forces of a pressure `pressure` (Pa, positive
/// pushes against the boundary cell's normal, as PRES_REP) on boundary cells
/// (SEG2/SEG3 in 2D, TRIA3/6 and QUAD4/8 in 3D) to `f_ext`. Cell normals follow
/// the cell's node order (ORIE_PEAU makes them outward). `axisymmetric` (AXIS model, x = r):
/// the surface measure is r dl, per radian like the AXIS stiffness. With `node_owner` (a shared
/// model's owner rank per node), only the cells whose first node is this rank's are added (a
/// node of no rank counts as rank 0's): the ranks' vectors sum to the whole one.
void assemble_pressure(const Mesh& mesh, int dim, const std::vector<int>& cells, double pressure,
                       const DofMap& dofs, Vector& f_ext, bool axisymmetric = false,
                       const std::vector<int>* node_owner = nullptr);

/// Adds the consistent nodal forces of a force density `force` (its first `dim` components)
/// on `cells`, each of dimension `cells_dim`: N/m on edges (cells_dim 1), N/m2 on faces (2),
/// N/m3 on the model's cells (dim). The same quadrature as assemble_pressure, with the cell's
/// measure in place of its oriented normal (the force does not depend on the cells' orientation);
/// `axisymmetric` and `node_owner` as there.
void assemble_distributed_force(const Mesh& mesh, int dim, const std::vector<int>& cells, int cells_dim,
                                const std::array<double, 3>& force, const DofMap& dofs, Vector& f_ext,
                                bool axisymmetric = false, const std::vector<int>* node_owner = nullptr);

}  // namespace lunaster::engine
