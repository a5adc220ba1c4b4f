#pragma once
/// Why a linear solve failed, said in the engine's terms: a body nothing holds, a null pivot
/// of the stiffness, contact terms that leave the system singular, approximate factors.
#include <functional>
#include <string>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/nonlinear/newton_options.hpp"

namespace lunaster::engine {

class FailureDiagnosis {
 public:
  /// `model` and `options` are borrowed for the run; `with_contact`: a contact hook adds terms.
  FailureDiagnosis(const FeModel& model, const NewtonOptions& options, bool with_contact);

  /// Where the stiffness K_ff of the failed system is to be read.
  struct Stiffness {
    const SparseMatrix* k_ff = nullptr;  ///< the whole K_ff on this process; null: assembled whole for it
    std::vector<int> constrained;        ///< the Dirichlet set K_ff was split by (when assembled here)
    bool on_no_rank = false;             ///< a mesh in parts: no rank holds it, the failure is said as it is
    /// The failed system with its contact terms (free numbering as K_ff), when K_ff is here:
    /// a body K_ff alone leaves free is looked for in it too (contact_hold_stiffness). Null: none.
    const SparseMatrix* system = nullptr;
    bool increment = false;  ///< `system` is the contact terms alone (the interface solver's)
  };
  /// A solve failure `err` at instant t explained by the elastic stiffness (rigid-body modes, a
  /// null pivot), with the approximations of the factors the run asked for named first. A
  /// rigid-body mode of K_ff alone that the contact terms of the failed system hold is not the
  /// cause: the failure is then the contact's conditioning, and its hints say that contact
  /// holds that body.
  SolveError explain(const SolveError& err, double t, const DofMap& dofs, const std::vector<int>& free_index,
                     const Stiffness& stiffness) const;
  /// What check_held looks at.
  struct HeldCheck {
    std::vector<int> related;  ///< unknowns tied by relations: counted as holding
    bool geometry = true;      ///< look for a body that a rigid motion moves (not in parts)
    bool factorise = false;    ///< then factorise K_ff (Cholesky) for a mechanism geometry does not see
  };
  /// Whether something holds every body (with no contact point active), before any
  /// factorisation: a body nothing holds throws SolveError, or is a warning in `log` when the
  /// run goes on past singular matrices. `k_ff_alone` gives K_ff without this iteration's terms
  /// (called only to factorise it). Returns whether it was called.
  bool check_held(const DofMap& dofs, const std::vector<int>& free_index, double t, const HeldCheck& check,
                  const std::function<const SparseMatrix&()>& k_ff_alone, const Log& log) const;
  /// The singularity test a diagnosis factorises with: the run's digits, or code_aster's
  /// default 8 when the run asked for no test.
  SingularityTest test() const;

 private:
  /// One approximation of the factors the run asked for: how it factorised ("in single
  /// precision"), and the hint a failure gives about it.
  struct Approximation {
    std::string what, hint;
  };
  /// The approximations of the factors the run asked for (MUMPS's filter, block low rank,
  /// single precision); empty when the factors are exact.
  std::vector<Approximation> approximations() const;
  /// `found`, a rigid-body mode of K_ff alone, checked against the contact terms of the failed
  /// system (Stiffness::system): still free, `found` with a hint that contact does not hold it
  /// either; held, the contact's error instead (diagnose_singular_system on the held stiffness).
  SolveError against_contact(const SolveError& found, const SolveError& err, double t, const DofMap& dofs,
                             const std::vector<int>& free_index, const Stiffness& stiffness,
                             const std::string& named) const;
  const FeModel& model_;
  const NewtonOptions& options_;
  bool with_contact_;
};

}  // namespace lunaster::engine
