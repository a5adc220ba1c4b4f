#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

Keyword erreur() {
  return factor("ERREUR",
                {text("NOM", "Column name in the CSV file, e.g. 'err_p'").required(),
                 text("NOM_CHAM", "Field, e.g. DEPL, SIGM_NOEU, CONT_NOEU").required(),
                 text("NOM_CMP", "Component, e.g. DY, LAGS_C, SIYY, PRES").required(),
                 text("GROUP_NO", "Nodes over which the largest error is taken").many(),
                 text("GROUP_MA", "Cells whose nodes are used").many(),
                 real("VALE_REFE", "Exact value the component should have at every selected node").required(),
                 integer("NUME_ORDRE", "Time step (default: the last one)")},
                "One error column: max over the selected nodes of |value - VALE_REFE| / |VALE_REFE| "
                "(absolute when VALE_REFE = 0); nodes where the component is undefined are skipped")
      .occurs(0, -1)
      .with_rules({exactly_one({"GROUP_NO", "GROUP_MA"})});
}

}  // namespace

const CommandSpec& impr_mesure_spec() {
  static const CommandSpec spec = make_command(
      "IMPR_MESURE", "",
      "Append one CSV row: the cost of a STAT_NON_LINE result (unknowns, iterations, wall time per phase since "
      "the previous IMPR_MESURE, peak memory), the accuracy of its solves (RESI_GLOB_RELA reached; largest "
      "relative residual of one linear solve before and after iterative refinement, and the refinement steps) "
      "and its errors against exact values. Each row starts a new peak-memory window: the process's peak "
      "resident memory (Linux VmHWM) is reset, so a whole-process peak read from outside (/usr/bin/time) "
      "covers only what followed the last IMPR_MESURE. On a result in parts (LIRE_MAILLAGE PARTITIONNEUR): the "
      "whole mesh's nodes, the unknowns over the ranks, and the times, the peak memory and each ERREUR the "
      "largest over the ranks",
      {concept_kw("RESULTAT", {"evol_noli"},
                  "Result measured; without it (a run that failed under pcall) only your columns, the phase "
                  "times and t_total are written (other columns left empty)"),
       text("FICHIER", "CSV file in the output folder; created with a header line, then appended to").required(),
       text("PARA", "Names of your own leading columns, e.g. {'method', 'k'}").many(),
       text("VALE_K", "Values of those columns, one per PARA").many(),
       erreur()},
      {together({"PARA", "VALE_K"})});
  return spec;
}

}  // namespace lunaster::catalog
