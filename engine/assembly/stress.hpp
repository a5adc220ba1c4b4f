#pragma once
/// Post-processing: stresses at cell nodes, nodal averages, equivalent stresses.
#include "engine/assembly/dof_map.hpp"
#include "engine/assembly/mesh_part.hpp"
#include "engine/core/linalg.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/fields/fields.hpp"

namespace lunaster::engine {

/// SIGM_ELNO: stresses at the nodes of every volume cell. Components
/// SIXX SIYY SIZZ SIXY (2D) or SIXX SIYY SIZZ SIXY SIXZ SIYZ (3D), Pa.
/// Computed at Gauss points and extrapolated to the nodes. With `cell_rank` (per mesh cell,
/// the rank whose cell it is: a shared model's partition) each rank computes its own cells
/// and the ranks sum their rows (collective): every rank ends with the whole field.
ElnoField compute_sigm_elno(const FeModel& model, const DofMap& dofs, const Vector& u,
                            const std::vector<int>* cell_rank = nullptr);

/// *_NOEU from *_ELNO: arithmetic mean over the cells sharing each node (code_aster's rule).
NodalField elno_to_noeu(const Mesh& mesh, const ElnoField& elno);

/// elno_to_noeu on a mesh in parts, `elno` holding the rows of the part's cells (compute_sigm_elno
/// on the part's model without `cell_rank`: every cell of a part has all its nodes there): an
/// owned node's mean is over all its cells, which its part holds; a ghost takes its owner's.
/// Collective.
NodalField elno_to_noeu(const MeshPart& part, const ElnoField& elno);

/// SIEQ_ELNO from SIGM_ELNO: VMIS, TRESCA, PRIN_1, PRIN_2, PRIN_3, VMIS_SG, TRSIG.
ElnoField compute_sieq_elno(const ElnoField& sigm);

}  // namespace lunaster::engine
