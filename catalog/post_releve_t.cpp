#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

/// Nodes and components of one ACTION; RESULTANTE only with EXTRACTION, as code_aster.
std::vector<Keyword> selection(bool resultant) {
  std::vector<Keyword> out = {
      common::group_no("Node groups whose nodes are read"),
      common::noeud("Nodes read"),
      text("TOUT_CMP", "Every component of NOM_CHAM").into_values({"OUI"}),
      text("NOM_CMP", "Components read, e.g. DX DY").many(),
  };
  if (resultant)
    out.push_back(text("RESULTANTE", "Components summed over the nodes: one row per step (resultant force)")
                      .into_values({"DX", "DY", "DZ"})
                      .many());
  return out;
}

Keyword action() {
  const std::vector<std::string> components = {"TOUT_CMP", "NOM_CMP"};
  std::vector<Block> blocks = {
      Block{"OPERATION", {"EXTRACTION"}, selection(true),
            {at_least_one({"GROUP_NO", "NOEUD"}), exactly_one({"TOUT_CMP", "NOM_CMP", "RESULTANTE"})}},
      Block{"OPERATION", {"MOYENNE_ARITH"}, selection(false),
            {at_least_one({"GROUP_NO", "NOEUD"}), exactly_one({"TOUT_CMP", "NOM_CMP"})}},
  };
  return factor("ACTION",
                {text("OPERATION",
                      "EXTRACTION: one row per node and step (or, with RESULTANTE, the sum over the nodes); "
                      "MOYENNE_ARITH: the arithmetic mean over the nodes, one row per step")
                     .into_values({"EXTRACTION", "MOYENNE_ARITH"})
                     .refuse("MOYENNE",
                             "code_aster's MOYENNE averages along an ordered line of nodes (rows MOMENT_0, MOMENT_1, "
                             "...), which lunaster does not compute; MOYENNE_ARITH gives the mean over the nodes")
                     .required(),
                 text("INTITULE", "Label of the rows of this action (column INTITULE)").required(),
                 concept_kw("RESULTAT", {"evol_noli"}, "Result read").required(),
                 text("NOM_CHAM", "Nodal field read, e.g. DEPL, REAC_NODA, FORC_NODA, SIGM_NOEU").required(),
                 text("TOUT_ORDRE", "Every stored step (default)").into_values({"OUI"}),
                 integer("NUME_ORDRE", "Step numbers read").many(),
                 real("INST", "Instants read").many()},
                "One extraction; the rows of every ACTION go into one table")
      .required()
      .occurs(1, -1)
      .with_rules({at_most_one({"TOUT_ORDRE", "NUME_ORDRE", "INST"})})
      .with_blocks(blocks);
}

}  // namespace

const CommandSpec& post_releve_t_spec() {
  static const CommandSpec spec = make_command(
      "POST_RELEVE_T", "table", "Read nodal field values of a result into a table (values, means, resultants)",
      {action(), common::info()});
  return spec;
}

}  // namespace lunaster::catalog
