#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

Keyword resu() {
  std::vector<Keyword> children = {
      concept_kw("RESULTAT", {"evol_noli"}, "Result to test").required(),
      integer("NUME_ORDRE", "Time step number"),
      real("INST", "Time"),
      text("NOM_CHAM", "Field name, e.g. DEPL, SIGM_NOEU").required(),
      text("NOM_CMP", "Component, e.g. DY, LAGS_C, SIYY").required(),
      text("NOEUD", "Node tested"),
      text("GROUP_NO", "One-node group tested, or the nodes reduced by TYPE_TEST"),
      text("GROUP_MA", "Cells whose nodes are reduced by TYPE_TEST"),
      text("TYPE_TEST", "Reduce the component over the field instead of one point")
          .into_values({"MIN", "MAX", "SOMM", "SOMM_ABS"}),
  };
  for (auto& kw : common::test_reference_keywords()) children.push_back(kw);
  std::vector<Rule> rules = {exactly_one({"NUME_ORDRE", "INST"}), at_least_one({"NOEUD", "GROUP_NO", "TYPE_TEST"}),
                             at_most_one({"NOEUD", "GROUP_NO", "GROUP_MA"}), present_present({"GROUP_MA", "TYPE_TEST"}),
                             present_absent({"NOEUD", "TYPE_TEST"})};
  for (auto& rule : common::test_reference_rules()) rules.push_back(rule);
  return factor("RESU", children, "One check of a result component").required().occurs(1, -1).with_rules(rules);
}

}  // namespace

const CommandSpec& test_resu_spec() {
  static const CommandSpec spec =
      make_command("TEST_RESU", "", "Check computed values against references; prints one OK/NOOK line per check", {resu()});
  return spec;
}

}  // namespace lunaster::catalog
