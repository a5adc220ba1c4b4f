#include "engine/nonlinear/failure_diagnosis.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "engine/assembly/assembly.hpp"
#include "engine/nonlinear/reduction.hpp"
#include "engine/nonlinear/rigid_body.hpp"
#include "engine/nonlinear/sci.hpp"

namespace lunaster::engine {

FailureDiagnosis::FailureDiagnosis(const FeModel& model, const NewtonOptions& options, bool with_contact)
    : model_(model), options_(options), with_contact_(with_contact) {}

SolveError FailureDiagnosis::explain(const SolveError& err, double t, const DofMap& dofs,
                                     const std::vector<int>& free_index, const Stiffness& stiffness) const {
  // Approximate factors asked for are the likeliest cause: named in the first line, their
  // hints said first.
  const std::vector<Approximation> approximate = approximations();
  std::string named;
  for (const auto& a : approximate) named += (named.empty() ? "" : ", ") + a.what;
  if (stiffness.on_no_rank) {
    SolveError as_is = err;
    as_is.add_hint("the model is in parts: no rank holds the whole stiffness to find the cause");
    return as_is;
  }
  SolveError found = [&] {
    if (stiffness.k_ff)
      return diagnose_singular_system(model_, dofs, free_index, *stiffness.k_ff, err, t, test(), with_contact_, named);
    SplitMatrix whole;
    SparseMatrix k = assemble_stiffness_matrix(model_, dofs);
    split_matrix(k, stiffness.constrained, whole);
    return diagnose_singular_system(model_, dofs, free_index, whole.ff, err, t, test(), with_contact_, named);
  }();
  if (found.failure().what == Failure::What::RigidBodyMode && stiffness.system && stiffness.k_ff &&
      stiffness.system->rows() == stiffness.k_ff->rows())
    found = against_contact(found, err, t, dofs, free_index, stiffness, named);
  if (!approximate.empty()) {
    std::vector<std::string> hints;
    for (const auto& a : approximate) hints.push_back(a.hint);
    hints.insert(hints.end(), found.hints().begin(), found.hints().end());
    found.set_hints(std::move(hints));
  }
  if (!options_.factor.preprocessing && options_.factor.singularity.digits >= 0)
    found.add_hint("the matrix was factorised as assembled (MUMPS without preprocessing), so its pivots were tested "
                   "unscaled: a multiplier's pivot, small in absolute terms, counts as null; let MUMPS scale the "
                   "matrix, or turn the pivot test off");
  return found;
}

SolveError FailureDiagnosis::against_contact(const SolveError& found, const SolveError& err, double t,
                                            const DofMap& dofs, const std::vector<int>& free_index,
                                            const Stiffness& stiffness, const std::string& named) const {
  const SparseMatrix held =
      contact_hold_stiffness(dofs, free_index, *stiffness.k_ff, *stiffness.system, stiffness.increment);
  if (auto still = find_rigid_body_mode(model_, dofs, free_index, held, t, test())) {  // the motion left free
    still->add_hint("the contact terms of the failed system do not hold it either");
    return *still;
  }
  SolveError contact = diagnose_singular_system(model_, dofs, free_index, held, err, t, test(), true, named);
  std::vector<std::string> hints{"without its contact terms the stiffness is singular (" + rigid_body_mode_of(found) +
                                 "), but the contact terms of the failed system hold that body: the trouble is not "
                                 "its support but the system with the contact terms"};
  if (contact.hints().size() > 1)  // not its first, that the stiffness alone is regular
    hints.insert(hints.end(), contact.hints().begin() + 1, contact.hints().end());
  contact.set_hints(std::move(hints));
  return contact;
}

std::vector<FailureDiagnosis::Approximation> FailureDiagnosis::approximations() const {
  std::vector<Approximation> out;
  if (options_.solver != SolverKind::Mumps) return out;
  if (options_.factor.filter > 0.0)
    out.push_back({"without its smallest entries",
                   "the matrix was factorised without its smallest entries (filter " + sci(options_.factor.filter) +
                       "), which this system needs" +
                       (with_contact_ ? ": its contact couplings are small beside the stiffness's diagonal" : "") +
                       "; lower the filter, or keep every entry"});
  if (options_.factor.low_rank.on)
    out.push_back({"in block low rank", "the factors were compressed in block low rank (threshold " +
                                            sci(std::abs(options_.factor.low_rank.threshold)) +
                                            "), too coarsely for this system: lower the threshold, refine more, or "
                                            "factorise in full rank"});
  if (options_.single_precision)
    out.push_back({"in single precision",
                   "the factors were computed in single precision, too coarse for this system's conditioning: "
                   "refine more, or factorise in double precision"});
  return out;
}

bool FailureDiagnosis::check_held(const DofMap& dofs, const std::vector<int>& free_index, double t,
                                  const HeldCheck& check, const std::function<const SparseMatrix&()>& k_ff_alone,
                                  const Log& log) const {
  // Going on past a singular matrix was asked for: a body held by nothing is a warning.
  const auto report = [this, &log](const SolveError& rigid) {
    if (options_.factor.singularity.stop) throw rigid;
    log.warning("going on as asked with a singular system: " + rigid.message());
  };
  const auto unheld =
      check.geometry ? find_unheld_body(model_, dofs, free_index, check.related, t) : std::optional<SolveError>();
  if (unheld) report(*unheld);
  if (unheld || !check.factorise) return false;
  if (auto rigid = find_rigid_body_mode(model_, dofs, free_index, k_ff_alone(), t, options_.factor.singularity))
    report(*rigid);
  return true;
}

SingularityTest FailureDiagnosis::test() const {
  SingularityTest test;
  if (options_.factor.singularity.digits >= 0) test.digits = options_.factor.singularity.digits;
  return test;
}

}  // namespace lunaster::engine
