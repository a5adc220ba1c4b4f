#pragma once
/// Diagnosis of a singular system: which body can move, in which direction,
/// and what the user can do about it.
#include <optional>
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/error.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/solver/linear_solver.hpp"

namespace lunaster::engine {

/// Builds the SolveError reported when the tangent could not be factorised at
/// instant `t`. Refactorises the elastic part restricted to the free
/// displacement equations with CHOLMOD to find an equation that carries a
/// rigid-body mode, then names the node, the component and the body (the
/// connected set of cells holding the node, named by the cell groups that
/// contain it), with the remedies. Falls back to the original error when the
/// elastic part alone is regular (the singularity then comes from contact).
/// The rigid-body error for the elastic part on the free displacement equations,
/// or nothing if that part is regular (CHOLMOD with its pivot-ratio test).
/// `elastic` is the elastic stiffness on the free equations, column free_index[eq] for
/// equation eq.
/// `test`: the pivots that count as singular (its `stop` is not read: the search stops at
/// the first).
std::optional<SolveError> find_rigid_body_mode(const FeModel& model, const DofMap& dofs,
                                               const std::vector<int>& free_index,
                                               const SparseMatrix& elastic, double t,
                                               SingularityTest test = {});

/// The rigid-body error for a body (connected set of cells) that no condition holds:
/// a translation or rotation of it (AXIS: the axial translation) that vanishes on every
/// equation fixed by a Dirichlet condition or listed in `held` (equations tied by
/// relations, counted as holding). Geometry only: no factorisation, the same answer on
/// every rank of a shared model and for every backend. It sees no mechanism inside a
/// body (two parts joined at one node): find_rigid_body_mode does.
std::optional<SolveError> find_unheld_body(const FeModel& model, const DofMap& dofs,
                                           const std::vector<int>& free_index, const std::vector<int>& held,
                                           double t);

/// The stiffness that tells whether the contact of a failed system holds the bodies: K_ff's
/// displacement block (free numbering, as `k_ff`) plus that system's contact terms, scaled so
/// that their largest diagonal is K_ff's: which motions they restrain counts, not how stiffly
/// (a penalty far stiffer than the bodies would otherwise be a weak pivot of its own). The
/// terms are `system` less K_ff on the displacement equations (`system` alone when
/// `increment`: the interface solver's contact terms), and B^T B for the couplings B of its
/// multiplier columns to the displacements. A displacement equation whose column in `system`
/// is a unit diagonal alone (eliminated by a relation) counts as held.
SparseMatrix contact_hold_stiffness(const DofMap& dofs, const std::vector<int>& free_index, const SparseMatrix& k_ff,
                                    const SparseMatrix& system, bool increment);

/// What a rigid-body error of find_rigid_body_mode says of the body and its motion ("the body
/// V2 (8 cells) has a rigid-body mode (free to move along DY, detected at node N3)").
std::string rigid_body_mode_of(const SolveError& rigid);

/// `contact_terms`: the failed system had contact terms besides K (then, with K regular,
/// they are blamed; otherwise the solve's accuracy is). `approximations`: how the factors were
/// approximate by request ("in single precision"), which the message then names; empty
/// when they were exact.
SolveError diagnose_singular_system(const FeModel& model, const DofMap& dofs, const std::vector<int>& free_index,
                                    const SparseMatrix& elastic, const SolveError& original, double t,
                                    SingularityTest test = {}, bool contact_terms = true,
                                    const std::string& approximations = {});

}  // namespace lunaster::engine
