#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

Keyword resu() {
  const std::string not_stored =
      "not stored: a lunaster result keeps fields and instants per NUME_ORDRE, not each step's iterations, "
      "residuals or pilot parameters";
  Keyword para = text("PARA", "A parameter of the result at the step instead of a field's component: 'INST', the "
                              "step's time. code_aster's other parameters (ITER_GLOB, ITER_LINE, RESI_GLOB_RELA, "
                              "RESI_GLOB_MAXI, ETA_PILOTAGE, CHAR_MINI) are refused by name (IMPR_MESURE gives the run's totals)")
                     .into_values({"INST"});
  for (const char* p : {"ITER_GLOB", "ITER_LINE", "RESI_GLOB_RELA", "RESI_GLOB_MAXI", "ETA_PILOTAGE", "CHAR_MINI"})
    para = para.refuse(p, not_stored);
  std::vector<Keyword> children = {
      concept_kw("RESULTAT", {"evol_noli"}, "Result to test").required(),
      integer("NUME_ORDRE", "Time step number"),
      real("INST", "Time"),
      text("NOM_CHAM", "Field name, e.g. DEPL, SIGM_NOEU"),
      text("NOM_CMP", "Component, e.g. DY, LAGS_C, SIYY"),
      para,
      text("NOEUD", "Node tested"),
      text("GROUP_NO", "One-node group tested, or the nodes reduced by TYPE_TEST"),
      text("GROUP_MA", "Cells whose nodes are reduced by TYPE_TEST"),
      text("MAILLE", "Cell tested, with a field per cell: at its node NOEUD/GROUP_NO (ELNO) or integration point "
                     "POINT (ELGA)"),
      integer("POINT", "Integration point of MAILLE tested (1-based, in the order of the cell's scheme; ELGA)")
          .range(1, std::nullopt),
      text("TYPE_TEST", "Reduce the component over the field instead of one point")
          .into_values({"MIN", "MAX", "SOMM", "SOMM_ABS"}),
  };
  for (auto& kw : common::test_reference_keywords()) children.push_back(kw);
  std::vector<Rule> rules = {exactly_one({"NUME_ORDRE", "INST"}), exactly_one({"NOM_CHAM", "PARA"}),
                             present_present({"NOM_CHAM", "NOM_CMP"}),
                             present_absent({"PARA", "NOM_CMP", "NOEUD", "GROUP_NO", "GROUP_MA", "TYPE_TEST", "MAILLE"}),
                             at_most_one({"NOEUD", "GROUP_NO", "GROUP_MA"}), present_present({"GROUP_MA", "TYPE_TEST"}),
                             present_absent({"NOEUD", "TYPE_TEST"}), present_absent({"MAILLE", "TYPE_TEST", "GROUP_MA"}),
                             present_present({"POINT", "MAILLE"}), present_absent({"POINT", "NOEUD", "GROUP_NO"})};
  for (auto& rule : common::test_reference_rules()) rules.push_back(rule);
  // A field's component is tested at one node or point, or reduced over the field.
  const std::vector<Block> blocks = {
      Block{"NOM_CHAM", {}, {}, {at_least_one({"NOEUD", "GROUP_NO", "TYPE_TEST", "POINT"})}}};
  return factor("RESU", children, "One check of a result component, or of a parameter of the result (PARA)")
      .occurs(0, -1)
      .with_rules(rules)
      .with_blocks(blocks);
}

/// CHAM_NO / CHAM_ELEM: one check of a field made by CREA_CHAMP.
Keyword field(bool at_nodes) {
  std::vector<Keyword> children = {
      concept_kw("CHAM_GD", {"cham_gd"}, at_nodes ? "Field at nodes (CREA_CHAMP, TYPE_CHAM NOEU_*)"
                                                  : "Field per cell (CREA_CHAMP, TYPE_CHAM ELNO_* or ELGA_*)")
          .required(),
      text("NOM_CMP", "Component, e.g. DY, SIYY").required(),
      text("TYPE_TEST", "Reduce the component over the field instead of one point")
          .into_values({"MIN", "MAX", "SOMM", "SOMM_ABS"})};
  std::vector<Rule> rules;
  std::vector<Block> blocks;
  if (at_nodes) {
    children.push_back(text("NOEUD", "Node tested"));
    children.push_back(text("GROUP_NO", "One-node group tested, or the nodes reduced by TYPE_TEST"));
    rules = {at_least_one({"NOEUD", "GROUP_NO", "TYPE_TEST"}), at_most_one({"NOEUD", "GROUP_NO"}),
             present_absent({"NOEUD", "TYPE_TEST"})};
  } else {
    children.push_back(text("MAILLE", "Cell tested"));
    children.push_back(text("NOEUD", "Node of MAILLE tested (ELNO field)"));
    children.push_back(text("GROUP_NO", "One-node group: the node of MAILLE tested, instead of NOEUD"));
    children.push_back(integer("POINT", "Integration point of MAILLE tested (1-based; ELGA field)").range(1, std::nullopt));
    rules = {exactly_one({"MAILLE", "TYPE_TEST"}), present_absent({"TYPE_TEST", "NOEUD", "GROUP_NO", "POINT"})};
    blocks.push_back(Block{"MAILLE", {}, {}, {exactly_one({"NOEUD", "GROUP_NO", "POINT"})}});
  }
  for (auto& kw : common::test_reference_keywords()) children.push_back(kw);
  for (auto& rule : common::test_reference_rules()) rules.push_back(rule);
  return factor(at_nodes ? "CHAM_NO" : "CHAM_ELEM", children,
                at_nodes ? "One check of a component of a field at nodes"
                         : "One check of a component of a field per cell")
      .occurs(0, -1)
      .with_rules(rules)
      .with_blocks(blocks);
}

}  // namespace

const CommandSpec& test_resu_spec() {
  static const CommandSpec spec =
      make_command("TEST_RESU", "", "Check computed values against references; prints one OK/NOOK line per check",
                   {resu(), field(true), field(false)}, {at_least_one({"RESU", "CHAM_NO", "CHAM_ELEM"})});
  return spec;
}

}  // namespace lunaster::catalog
