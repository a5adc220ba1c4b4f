#include "engine/nonlinear/solve_log.hpp"

#include <cstdio>

#include "engine/nonlinear/sci.hpp"
#include "engine/assembly/equation_name.hpp"

namespace lunaster::engine {

void SolveLog::backend(const LinearSolve::Backend& chosen, MatrixKind kind, int n_free) const {
  using Note = LinearSolve::BackendNote;
  const std::string fallback = chosen.fallback == SolverKind::Umfpack ? "UMFPACK" : "MUMPS";
  switch (chosen.note) {
    case Note::None: break;
    case Note::AutoIterative:
    case Note::AutoMumps:
      log_.info("solver chosen automatically: " +
                std::string(chosen.note == Note::AutoIterative
                                ? "PETSc CG + BoomerAMG (relative residual 1e-12, MUMPS if it does not converge)"
                                : "MUMPS") +
                " for a 3D system of " + std::to_string(n_free) +
                " unknowns (a factorisation fills too much at this size)");
      break;
    case Note::SaddleSchur:
    case Note::Umfpack:
    case Note::Mumps:
      log_.info(std::string("CHOLMOD cannot factorise ") +
                (kind == MatrixKind::SymmetricIndefinite ? "an indefinite" : "a non-symmetric") +
                (chosen.note == Note::SaddleSchur
                     ? " system; CHOLMOD factorises the Schur complement of its multipliers and GMRES solves it (" +
                           fallback + " if that gives way)"
                 : chosen.note == Note::Umfpack ? " system; using UMFPACK (MUMPS from 10000 unknowns)"
                                                : " system; using MUMPS"));
      break;
  }
}

void SolveLog::event(const LinearSolve::Event& e, const Where& at) {
  using W = LinearSolve::Event::What;
  const std::string its = std::to_string(e.iterations);
  switch (e.what) {
    case W::SinglePrecision:
      log_.info("  linear solver: MUMPS in single precision, each solve refined in double precision");
      break;
    case W::FactorsReused:
      log_.info("         (factorisation of iteration " + std::to_string(e.iteration) + " reused)");
      break;
    case W::KrylovOnPrevious:
      if (e.converged)
        log_.info("  linear solve: previous factorisation as preconditioner, " + its +
                  " GMRES iteration(s), relative residual " + sci(e.residual));
      else
        log_.info("  linear solve: " + its + " GMRES iteration(s) with the previous factorisation did not converge "
                  "(relative residual " + sci(e.residual) + "); refactorising");
      break;
    case W::Factorised: factorised(*e.solver, at); break;
    case W::SameMatrix:
      log_.info(options_.elastic_matrix ? std::string("         (factorisation of the elastic matrix reused)")
                : e.solver->iterative() ? std::string("         (same matrix as the last solve: preconditioner reused)")
                                        : std::string("         (same matrix as the last factorisation: factors reused)"));
      break;
    case W::IterativeSolved:
    case W::DirectIterated:
      log_.info("  linear solve: " + e.solver->name() + ", " + its + " iteration(s), relative residual " +
                sci(e.residual));
      break;
  }
}

void SolveLog::factorised(const LinearSolver& solver, const Where& at) {
  // A singular matrix that the run goes past, as asked: said once for each instant and
  // pivot (the Newton iterations and contact passes of an instant refactorise it alike).
  if (const std::string note = solver.singular_note(); !note.empty()) {
    std::string where;
    if (const int column = solver.singular_column(); column >= 0)
      for (int eq = 0; eq < at.dofs->n_dofs() && where.empty(); ++eq)
        if ((*at.free_index)[eq] == column) where = " at " + describe_equation(*at.mesh, *at.dofs, eq);
    const std::string said = "singular matrix at instant " + sci(at.t) + where;
    if (said != singular_said_) log_.warning(said + ", going on as asked: " + solver.name() + ": " + note);
    singular_said_ = said;
  }
  // What an asked-for ordering and out-of-core factors came to, said once while it holds.
  const auto say_once = [this](const std::string& line, std::string& said) {
    if (line != said) log_.info(line);
    said = line;
  };
  if (options_.factor.ordering != FactorOrdering::Auto)
    say_once("  " + solver.name() + " ordering: " + solver.ordering_used(), ordering_logged_);
  if (const std::string f = solver.factorisation_used(); !f.empty())
    say_once("  " + solver.name() + " factorisation: " + f, factorisation_logged_);
  if (const std::string analysis = solver.analysis_note(); !analysis.empty() && analysis != analysis_logged_)
    log_.debug("  " + analysis);
  analysis_logged_ = solver.analysis_note();
  if (const std::string memory = solver.memory_used(); !memory.empty())
    say_once("  " + solver.name() + " factors: " + memory, memory_logged_);
  if (const std::string approximate = solver.approximation_note(); !approximate.empty())
    say_once("  " + solver.name() + ": " + approximate, approximation_logged_);
  if (at.interface_equations > 0)
    log_.info("  linear solve: Schur complement of the " + std::to_string(at.interface_equations) +
              " surface equations factorised on the kept elastic factorisation");
}

}  // namespace lunaster::engine
