// Tables seen from a deck: TAB['PARA'][i] and #TAB, errors naming the line, and the real
// TEST_TABLE and IMPR_TABLE handlers on a table of known cells.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "commands/commands.hpp"
#include "catalog/spec.hpp"
#include "commands/table.hpp"
#include "lua/runner.hpp"

using namespace lunaster;

namespace {

/// POST_RELEVE_T fake: three rows of known cells (the third has no DY).
catalog::ConceptPtr fake_table(const catalog::Args&, cmd::Session&) {
  auto t = std::make_shared<cmd::Table>();
  t->add_row({{"NOEUD", std::string("N1")}, {"NUME_ORDRE", 1LL}, {"DY", -1.5}});
  t->add_row({{"NOEUD", std::string("N2")}, {"NUME_ORDRE", 1LL}, {"DY", 2.5}});
  t->add_row({{"NOEUD", std::string("N3, end")}, {"NUME_ORDRE", 7LL}});
  return t;
}

/// Every other command: a concept of its result type, holding nothing.
struct FakeTableConcept : catalog::Concept {
  explicit FakeTableConcept(std::string type) : type_(std::move(type)) {}
  std::string type_name() const override { return type_; }
  std::string type_;
};
catalog::ConceptPtr fake(const catalog::Args&, cmd::Session& session) {
  const auto* spec = catalog::find_command(session.current.command);
  if (spec->result_type.empty()) return nullptr;
  return std::make_shared<FakeTableConcept>(spec->result_type);
}

class TableAccess : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = std::filesystem::temp_directory_path() / ("lunaster_table_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    session.output_dir = dir;
    session.deck_path = dir / "t.lua";
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string run(const std::string& code) {
    lua::Runner runner(session, [](const std::string& name) -> cmd::Handler {
      if (name == "POST_RELEVE_T") return fake_table;
      if (name == "TEST_TABLE") return cmd::test_table;
      if (name == "IMPR_TABLE") return cmd::impr_table;
      return fake;
    });
    try {
      runner.run_string(code, "t.lua");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  std::string read(const std::string& name) {
    std::ifstream in(dir / name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::filesystem::path dir;
  std::ostringstream out;
  Log log{out, 1};
  cmd::Session session{log};
};

/// One line: a (fake) result, then the table read from it.
const char* kTable =
    "MA = LIRE_MAILLAGE{ FORMAT = 'MED' } "
    "MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } } "
    "MAT = DEFI_MATERIAU{ ELAS = _F{ E = 1.0, NU = 0.0 } } "
    "CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } } "
    "CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'A', DX = 0.0 } } "
    "L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } } "
    "R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, INCREMENT = _F{ LIST_INST = L } } "
    "T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'X', RESULTAT = R, "
    "NOM_CHAM = 'DEPL', NOEUD = 'N1', NOM_CMP = 'DY' } }\n";

}  // namespace

TEST_F(TableAccess, CellsAreLuaValuesAndLengthIsTheRowCount) {
  EXPECT_EQ(run(std::string(kTable) +
                "assert(#T == 3 and #T['DY'] == 3)\n"
                "assert(T['DY'][2] == 2.5 and T['NOEUD'][1] == 'N1')\n"
                "assert(math.type(T['NUME_ORDRE'][3]) == 'integer' and T['NUME_ORDRE'][3] == 7)\n"),
            "");
}

TEST_F(TableAccess, UnknownParameterEmptyCellAndRangeNameTheLine) {
  EXPECT_NE(run(std::string(kTable) + "local x = T['DZ'][1]\n")
                .find("t.lua:2: table T: no parameter 'DZ'; its parameters: NOEUD, NUME_ORDRE, DY"),
            std::string::npos);
  EXPECT_NE(run(std::string(kTable) + "\nlocal x = T['DY'][4]\n")
                .find("t.lua:3: table T['DY']: row 4 out of range (the table has 3 row(s): 1..3)"),
            std::string::npos);
  EXPECT_NE(run(std::string(kTable) + "local x = T['DY'][3]\n").find("t.lua:2: table T['DY'][3]: the cell is empty"),
            std::string::npos);
  EXPECT_NE(run(std::string(kTable) + "local x = T['DY', 1]\n").find("t.lua:2:"), std::string::npos);  // Lua syntax
}

TEST_F(TableAccess, TestTableFiltersAndReducesThroughTheSharedReport) {
  EXPECT_EQ(run(std::string(kTable) +
                "TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'NOEUD', VALE_K = 'N2' }, "
                "VALE_CALC = 2.5 }\n"
                "TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'DY', CRIT_COMP = 'MAXI_ABS' }, "
                "REFERENCE = 'ANALYTIQUE', VALE_REFE = 2.5 }\n"
                "TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', TYPE_TEST = 'SOMM_ABS', VALE_CALC = 4.0 }\n"
                "TEST_TABLE{ TABLE = T, NOM_PARA = 'DY', FILTRE = _F{ NOM_PARA = 'NUME_ORDRE', VALE_I = 1 }, "
                "TYPE_TEST = 'MIN', VALE_CALC = -1.0 }\n"),
            "");
  ASSERT_EQ(session.tests.size(), 4u);
  EXPECT_EQ(session.n_ok(), 3);
  EXPECT_EQ(session.tests[3].text.rfind("NOOK ", 0), 0u);  // MIN is -1.5, not -1.0
}

TEST_F(TableAccess, ImprTableWritesAlignedTextAndCsvAndAppendsOnOneUnit) {
  ASSERT_EQ(run(std::string(kTable) +
                "IMPR_TABLE{ TABLE = T, NOM_PARA = { 'NOEUD', 'DY' }, FORMAT_R = 'F6.2' }\n"
                "IMPR_TABLE{ TABLE = T, NOM_PARA = 'NOEUD' }\n"
                "IMPR_TABLE{ TABLE = T, FICHIER = 't.csv', SEPARATEUR = ',', COMMENTAIRE = '%' }\n"),
            "");
  const std::string rule = std::string(79, '-');
  EXPECT_EQ(read("t_8.tab"), "#" + rule + "\n#TABLE T: 3 row(s), 2 parameter(s)\n"
                             "NOEUD       DY\n"
                             "N1       -1.50\n"
                             "N2        2.50\n"
                             "N3, end      -\n" +
                             "#" + rule + "\n#TABLE T: 3 row(s), 1 parameter(s)\nNOEUD\nN1\nN2\nN3, end\n");
  EXPECT_EQ(read("t.csv"), "%" + rule + "\n%TABLE T: 3 row(s), 3 parameter(s)\n"
                           "NOEUD,NUME_ORDRE,DY\n"
                           "N1,1,-1.50000E+00\n"
                           "N2,1,2.50000E+00\n"
                           "\"N3, end\",7,\n");
}
