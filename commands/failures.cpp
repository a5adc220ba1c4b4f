#include "commands/failures.hpp"

#include <regex>
#include <string>
#include <vector>

namespace lunaster::cmd {

namespace {

/// The engine's "last residuals: relative X, absolute Y N" in code_aster's names.
std::string residual_keywords(const std::string& hint) {
  static const std::regex engine_words("last residuals: relative ([^,]+), absolute ([^ ]+) N");
  return std::regex_replace(hint, engine_words, "last residuals: RESI_GLOB_RELA = $1, RESI_GLOB_MAXI = $2");
}

/// The engine's "(stored step N)" as the result's index is named in a deck (NUME_ORDRE).
std::string step_keywords(const std::string& hint) {
  static const std::regex engine_words("\\(stored step ([0-9]+)\\)");
  return std::regex_replace(hint, engine_words, "(NUME_ORDRE $1)");
}

}  // namespace

void say_in_keywords(Error& err) {
  const Failure& f = err.failure();
  std::string message = err.message();
  std::vector<std::string> hints = err.hints();
  const std::string limit = std::to_string(f.limit);
  auto replace = [&message](const std::string& from, const std::string& to) {
    const auto at = message.find(from);
    if (at != std::string::npos) message.replace(at, from.size(), to);
  };
  switch (f.what) {
    case Failure::What::Unspecified: break;
    case Failure::What::NewtonIterations:
      replace(" within " + limit + " iterations", " within ITER_GLOB_MAXI = " + limit + " iterations");
      break;
    case Failure::What::StatusLoop:
      if (f.per_point > 0)
        replace("after " + limit + " iterations:", "after " + limit + " iterations (ITER_CONT_MULT = " +
                                                        std::to_string(f.per_point) + " per contact point, " +
                                                        std::to_string(f.limit / f.per_point) + " points):");
      else
        replace("after " + limit + " iterations:", "after " + limit + " iterations (ITER_CONT_MAXI):");
      for (auto& h : hints) {
        if (h.rfind("points cycling", 0) == 0)
          h = "points cycling between contact and no contact: try ALGO_RESO_CONT='NEWTON', a different COEF_CONT, "
              "or a finer/compatible mesh";
        else if (h.rfind("the active set changes one contact point", 0) == 0)
          h = "the active set (discrete formulation) changes one contact point per iteration: raise ITER_CONT_MULT "
              "or ITER_CONT_MAXI, or start with fewer points active (CONTACT_INIT of AFFE_CHAR_MECA's CONTACT)";
      }
      break;
    case Failure::What::GeometryLoop:
      replace("after " + limit + " re-pairings:", "after " + limit + " iterations (ITER_GEOM_MAXI):");
      replace("> tolerance", "> RESI_GEOM");
      for (auto& h : hints)
        if (h.rfind("more re-pairings", 0) == 0)
          h = "increase ITER_GEOM_MAXI, use smaller load increments or ALGO_RESO_GEOM='NEWTON'";
      break;
    case Failure::What::RigidBodyMode:
      for (auto& h : hints) {
        if (h.rfind("nothing holds this body", 0) == 0)
          h = "nothing holds this body in that direction: add DDL_IMPO on it (AFFE_CHAR_MECA),";
        else if (h.rfind("or, if only contact holds it", 0) == 0)
          h = "or, if only contact holds it, activate contact from the start with CONTACT_INIT='OUI' (DEFI_CONT, "
              "DEFI_CONTACT FORMULATION='CONTINUE', or the CONTACT of AFFE_CHAR_MECA; DEFI_CONTACT "
              "FORMULATION='DISCRETE' has no CONTACT_INIT)";
        else if (h.rfind("so that the contact pressure", 0) == 0)
          h = "so that the contact pressure carries the load from the first iteration";
        else if (h.rfind("if a much softer part holds it", 0) == 0)
          h = "if a much softer part holds it (a stiffness ratio near 1e-" + limit +
              "), raise SOLVEUR NPREC above " + limit + " or set STOP_SINGULIER='NON'";
      }
      replace("more than the " + limit + " allowed", "more than NPREC = " + limit);
      break;
    case Failure::What::ContactConditioning:
      for (auto& h : hints)
        if (h.rfind("check that the contact surfaces", 0) == 0)
          h = "check that the contact surfaces face each other, and that E_N (PENALISATION) or COEF_CONT "
              "(CONTINUE) is not many orders of magnitude above the material stiffness E / h: the condition "
              "number grows with it until double precision cannot resolve the system";
        else if (h.rfind("or allow more than", 0) == 0)
          h = "or raise SOLVEUR NPREC above " + limit + " (the digits a pivot may lose): the solve's accuracy is "
              "still checked";
      break;
    case Failure::What::SolveAccuracy:
      for (auto& h : hints)
        if (h.rfind("the stiffness is regular", 0) == 0)
          h = "the stiffness is regular (no rigid-body mode) but its solve did not reach the accuracy asked (SOLVEUR "
              "RESI_RELA of MUMPS; 1e-6 for every direct solve otherwise): a part far softer than another, or a "
              "RESI_RELA below round-off; a negative RESI_RELA leaves the judgement to Newton's residual";
      break;
    case Failure::What::OutOfMemory:
      for (auto& h : hints)
        if (h.rfind("the factors do not fit", 0) == 0)
          h = "the factors do not fit in this machine's memory: use SOLVEUR=_F(METHODE='MUMPS') (least fill-in on "
              "contact systems), a coarser mesh, or a larger machine";
      break;
    case Failure::What::IterativeSolve:
      for (auto& h : hints) {
        if (h.rfind("a saddle-point system", 0) == 0)
          h = "a saddle-point system (contact multipliers) needs PRE_COND='LDLT_SP' with ALGORITHME='FGMRES' or "
              "'GMRES' (SOLVEUR METHODE='PETSC'), or a direct solver: METHODE='MUMPS'";
        else if (h.rfind("allow more iterations", 0) == 0)
          h = "raise NMAX_ITER or RESI_RELA, choose another PRE_COND, or use a direct solver: METHODE='MUMPS'";
      }
      break;
    case Failure::What::NotInParts: {
      // A linear solver's option that a mesh in parts cannot take, by its keyword.
      static const std::regex ordering("MUMPS: the (.*) ordering, computed from the whole matrix's pattern on one "
                                       "process, is not available on a mesh in parts");
      std::smatch m;
      if (message.rfind("MUMPS: filtering the matrix's small entries", 0) == 0) {
        message = "MUMPS: FILTRAGE_MATRICE is not available on a mesh in parts";
        hints = {"leave FILTRAGE_MATRICE out, or read the mesh whole (LIRE_MAILLAGE without PARTITIONNEUR)"};
      } else if (std::regex_match(message, m, ordering)) {
        message = "MUMPS: the " + m[1].str() + " ordering asked for (RENUM) is computed from the whole matrix's "
                  "pattern on one process, which a mesh in parts does not gather";
        hints = {"choose RENUM = 'AMD', 'AMF', 'QAMD', 'PORD' or 'AUTO', or read the mesh whole"};
      } else if (message.rfind("PETSc: a single-precision factorisation as preconditioner", 0) == 0) {
        message = "PRE_COND='LDLT_SP' is not available on a mesh in parts: it gathers the whole system on one rank; "
                  "use an algebraic multigrid (GAMG, ML, BOOMER), JACOBI or SOR";
        hints.clear();
      }
      break;
    }
    case Failure::What::PartsBackend:
      message = "on a mesh in parts MUMPS or PETSc solves (SOLVEUR=_F{METHODE='MUMPS'} or 'PETSC'), not " +
                std::string(f.count == 1 ? "METHODE='AUTO'" : "a solver of one process");
      break;
    case Failure::What::PartsMultipliers:
      message = "contact or linear relations with multipliers (LAGS_C, LAGR_DX..) on a mesh in parts are solved by "
                "MUMPS, not PETSc";
      hints = {"SOLVEUR=_F{ METHODE = 'MUMPS' }, or no multipliers: contact by the discrete formulation's "
               "PENALISATION or by mortar (DEFI_CONT), linear relations with SOLVEUR ELIM_LAGR = 'OUI'"};
      break;
    case Failure::What::BehaviourIntegration:
      for (auto& h : hints)
        if (h.rfind("no admissible state at the step's end", 0) == 0)
          h = "no admissible state at the step's end: smaller load increments (DEFI_LIST_INST), or let the step be "
              "subdivided (ECHEC SUBD_NIVEAU, SUBD_PAS)";
      break;
    case Failure::What::SharedBehaviour:
      message = "a nonlinear behaviour (COMPORTEMENT) is integrated on a model whole on each rank, not " +
                std::string(f.count == 1 ? "on a mesh in parts (LIRE_MAILLAGE PARTITIONNEUR)"
                                         : "on a model shared among the ranks (SOLVEUR MATR_DISTRIBUEE='OUI' or "
                                           "METHODE='PETSC')");
      hints = {f.count == 1 ? "read the mesh whole (LIRE_MAILLAGE without PARTITIONNEUR)"
                            : "SOLVEUR=_F{ METHODE = 'MUMPS', MATR_DISTRIBUEE = 'NON' }, or run on one process"};
      break;
    case Failure::What::NotAMedFile:
      for (auto& h : hints)
        if (h.rfind("this reader reads MED files", 0) == 0) h = "LIRE_MAILLAGE reads MED files; use FORMAT='GMSH' for .msh";
      break;
  }
  // Whatever the failure: an axisymmetric cell is an AXIS one (AFFE_MODELE MODELISATION).
  replace(" (axisymmetric): integration point at radius", " (AXIS): integration point at radius");
  // Whatever the failure: MUMPS settings the system did not fit (TYPE_RESOL, PRETRAITEMENTS,
  // ACCELERATION, MIXER_PRECISION, FILTRAGE_MATRICE).
  for (auto& h : hints) {
    if (h.rfind("ask for a symmetric indefinite or general factorisation", 0) == 0)
      h = "use SOLVEUR TYPE_RESOL='SYMGEN' or 'NONSYM', or 'AUTO' (the default: by the system)";
    else if (h.rfind("ask for a general (LU) factorisation", 0) == 0)
      h = "use SOLVEUR TYPE_RESOL='NONSYM', or 'AUTO' (the default: by the system)";
    else if (h.rfind("the factors were compressed in block low rank", 0) == 0)
      h = "SOLVEUR ACCELERATION='LR' compressed the factors too coarsely for this system: lower LOW_RANK_SEUIL "
          "(1e-9 to 1e-12 are usual), use POSTTRAITEMENTS='FORCE', or ACCELERATION='FR' (full rank)";
    else if (h.rfind("the matrix was factorised without its smallest entries", 0) == 0)
      h = std::string("SOLVEUR FILTRAGE_MATRICE left out entries this system needs") +
          (h.find("contact couplings") != std::string::npos
               ? " (its contact couplings are small beside the stiffness's diagonal)"
               : "") +
          ": lower it, or remove it (the default, -1, keeps every entry)";
    else if (h.rfind("the factors were computed in single precision", 0) == 0)
      h = "SOLVEUR MIXER_PRECISION='OUI' factorised in single precision, too coarse for this system's "
          "conditioning: use POSTTRAITEMENTS='FORCE', or MIXER_PRECISION='NON' (the default)";
    else if (h.rfind("the matrix was factorised as assembled", 0) == 0)
      h = "the matrix was factorised as assembled (SOLVEUR PRETRAITEMENTS='SANS'), so NPREC tested its pivots "
          "unscaled: a multiplier's pivot, small in absolute terms, counts as null; use PRETRAITEMENTS='AUTO' (the "
          "default), or NPREC=-1 to turn the test off";
  }
  if (f.residuals_known)
    for (auto& h : hints) h = residual_keywords(h);
  for (auto& h : hints) h = step_keywords(h);
  if (f.subdivision_levels > 0)
    for (auto& h : hints) {
      const std::string levels = "subdivision level(s)";
      const auto at = h.rfind(levels);
      if (at != std::string::npos && at + levels.size() == h.size()) h += " (SUBD_NIVEAU)";
    }
  err.set_message(message);
  err.set_hints(hints);
}

}  // namespace lunaster::cmd
