#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

Keyword filtre() {
  std::vector<Block> blocks = {
      Block{"CRIT_COMP", {"EQ", "NE", "LT", "GT", "LE", "GE"},
            {real("VALE", "Real value compared with"), integer("VALE_I", "Integer value compared with"),
             text("VALE_K", "Text value compared with")},
            {exactly_one({"VALE", "VALE_I", "VALE_K"})}},
      Block{"CRIT_COMP", {"EQ", "NE"},
            {text("CRITERE", "Relative or absolute equality of reals").into_values({"RELATIF", "ABSOLU"}).def("RELATIF"),
             real("PRECISION", "Tolerance of the equality of reals").def(1e-3).range(0.0, std::nullopt)},
            {}},
  };
  return factor("FILTRE",
                {text("NOM_PARA", "Parameter the filter reads").required(),
                 text("CRIT_COMP", "Comparison: keep the rows where NOM_PARA compares so with the value; MAXI/MINI "
                                   "(_ABS) keep the row(s) of the largest/smallest value; VIDE/NON_VIDE the empty "
                                   "or filled cells")
                     .into_values({"EQ", "NE", "LT", "GT", "LE", "GE", "MAXI", "MAXI_ABS", "MINI", "MINI_ABS", "VIDE",
                                   "NON_VIDE"})
                     .def("EQ")},
                "Keep only the rows that pass (filters apply in order)")
      .occurs(0, -1)
      .with_blocks(blocks);
}

}  // namespace

const CommandSpec& test_table_spec() {
  std::vector<Keyword> keywords = {
      concept_kw("TABLE", {"table"}, "Table to test").required(),
      text("NOM_PARA", "Parameter (column) tested").required(),
      filtre(),
      text("TYPE_TEST", "Reduce the column over the remaining rows instead of testing one cell")
          .into_values({"SOMM", "SOMM_ABS", "MAX", "MIN"}),
  };
  for (auto& kw : common::test_reference_keywords(true)) keywords.push_back(kw);
  keywords.push_back(common::info());
  static const CommandSpec spec =
      make_command("TEST_TABLE", "", "Check one cell (or a reduction of a column) of a table; prints OK/NOOK lines",
                   keywords, common::test_reference_rules(true));
  return spec;
}

}  // namespace lunaster::catalog
