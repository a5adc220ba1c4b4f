// The Lua bridge: conversion of tables, locations in messages, strict globals,
// sandbox, typed userdata and the exception -> Lua error -> typed Error round trip.
// Handlers are injected fakes; the real ones live in commands/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "catalog/args.hpp"
#include "lua/bridge.hpp"
#include "lua/runner.hpp"

using namespace lunaster;
using catalog::Args;
using catalog::ConceptPtr;
using catalog::KwNode;

namespace {

struct FakeConcept : catalog::Concept {
  explicit FakeConcept(std::string type) : type_(std::move(type)) {}
  std::string type_name() const override { return type_; }
  std::string type_;
};

/// What the fake handlers saw (handlers are plain function pointers, so this is file-static).
struct Recorder {
  std::vector<std::string> commands;
  std::vector<int> lines;
  KwNode last;
  std::vector<ConceptPtr> results;
};
Recorder recorder;

ConceptPtr generic_handler(const Args& args, cmd::Session& session) {
  recorder.commands.push_back(session.current.command);
  recorder.lines.push_back(session.current.line);
  recorder.last = args.node();
  const auto* spec = catalog::find_command(session.current.command);
  if (spec->result_type.empty()) return nullptr;
  auto result = std::make_shared<FakeConcept>(spec->result_type);
  recorder.results.push_back(result);
  return result;
}

ConceptPtr solve_error_handler(const Args&, cmd::Session&) { throw SolveError("Newton did not converge"); }
ConceptPtr std_error_handler(const Args&, cmd::Session&) { throw std::out_of_range("vector::at"); }
ConceptPtr wrong_type_handler(const Args&, cmd::Session&) { return std::make_shared<FakeConcept>("modele"); }
ConceptPtr group_error_handler(const Args& args, cmd::Session&) {
  throw args.factor("AFFE").error("GROUP_MA", "a cell group of the mesh", "'PLAK'");
}

/// TEST_RESU fake: a check passes when VALE_CALC is not negative.
ConceptPtr test_resu_handler(const Args& args, cmd::Session& session) {
  for (const auto& check : args.factors("RESU")) {
    bool ok = check.real("VALE_CALC") >= 0.0;
    std::string line = std::string(ok ? " OK " : "NOOK ") + " fake";
    session.tests.push_back({ok, line});
    session.log().always(line);
  }
  return nullptr;
}

lua::HandlerLookup with(const std::string& command, cmd::Handler special) {
  return [command, special](const std::string& name) -> cmd::Handler {
    return name == command ? special : generic_handler;
  };
}
lua::HandlerLookup generic() { return [](const std::string&) -> cmd::Handler { return generic_handler; }; }

class RunnerTest : public ::testing::Test {
 protected:
  void SetUp() override { recorder = Recorder{}; }
  /// Runs `code` as deck "t.lua"; returns the error text ("" if none).
  std::string run(const std::string& code, lua::HandlerLookup lookup = generic()) {
    lua::Runner runner(session, std::move(lookup));
    try {
      runner.run_string(code, "t.lua");
    } catch (const Error& e) {
      kind = e.kind();
      return e.what();
    }
    return "";
  }
  std::ostringstream out;
  Log log{out, 1};
  cmd::Session session{log};
  ErrorKind kind = ErrorKind::Deck;
};

const char* kMesh = "MA = LIRE_MAILLAGE{ FORMAT = 'MED' }\n";

}  // namespace

TEST_F(RunnerTest, ConvertsTablesKeepingIntegersAndFloatsApart) {
  lua::Runner runner(session, generic());
  lua_State* L = runner.state();
  ASSERT_EQ(luaL_dostring(L, "return { A = 1, B = 1.5, C = 'x', L = {1, 2.5}, F = _F{ X = 2 },"
                             " M = { _F{ Y = 1 }, _F{ Y = 2 } }, E = {} }"),
            LUA_OK);
  catalog::Value reuse;
  bool has_reuse = false;
  KwNode node = lua::to_node(L, -1, "", &reuse, &has_reuse);
  EXPECT_EQ(std::get<long long>(node.simple.at("A")[0]), 1);
  EXPECT_DOUBLE_EQ(std::get<double>(node.simple.at("B")[0]), 1.5);
  EXPECT_EQ(std::get<std::string>(node.simple.at("C")[0]), "x");
  ASSERT_EQ(node.simple.at("L").size(), 2u);
  EXPECT_TRUE(std::holds_alternative<long long>(node.simple.at("L")[0]));
  EXPECT_TRUE(std::holds_alternative<double>(node.simple.at("L")[1]));
  ASSERT_EQ(node.factors.at("F").size(), 1u);
  EXPECT_EQ(std::get<long long>(node.factors.at("F")[0].simple.at("X")[0]), 2);
  ASSERT_EQ(node.factors.at("M").size(), 2u);
  EXPECT_EQ(std::get<long long>(node.factors.at("M")[1].simple.at("Y")[0]), 2);
  EXPECT_EQ(node.factors.at("E").size(), 1u);  // an empty table: the validator decides
  EXPECT_FALSE(has_reuse);
}

TEST_F(RunnerTest, MixedTablesAreDeckErrors) {
  lua::Runner runner(session, generic());
  lua_State* L = runner.state();
  ASSERT_EQ(luaL_dostring(L, "return { L = { 1, _F{ X = 1 } } }"), LUA_OK);
  try {
    lua::to_node(L, -1, "", nullptr, nullptr);
    FAIL();
  } catch (const DeckError& e) {
    EXPECT_STREQ(e.what(), "L: expected a list of values or a list of _F{...}, got a list mixing tables and values");
  }
}

TEST_F(RunnerTest, BooleanAndFunctionValuesNameTheKeyword) {
  std::string err = run("DEBUT()\n" + std::string(kMesh) + "MAT = DEFI_MATERIAU{ ELAS = _F{ E = true, NU = 0.3 } }\n");
  EXPECT_EQ(err, "t.lua:3: DEFI_MATERIAU: ELAS.E: expected a real, an integer, a text or a concept, got a boolean");
  // A Lua function is a deck function now (FORMULE's kind), which a real keyword does not take.
  err = run("DEFI_MATERIAU{ ELAS = _F{ E = print, NU = 0.3 } }\n");
  EXPECT_EQ(err, "t.lua:1: DEFI_MATERIAU: ELAS.E: expected real > 0, got function");
}

TEST_F(RunnerTest, ValidationErrorsCarryFileLineAndCommand) {
  std::string err = run(std::string(kMesh) + "\nMO = AFFE_MODELE{ MAILLAGE = MA,\n"
                        "  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLN' } }\n");
  EXPECT_EQ(err, "t.lua:3: AFFE_MODELE: AFFE[1].MODELISATION: expected one of 'D_PLAN', 'C_PLAN', '3D', 'AXIS', got 'D_PLN'\n"
                 "    did you mean 'D_PLAN'?");
  EXPECT_EQ(kind, ErrorKind::Deck);
  EXPECT_EQ(recorder.commands, std::vector<std::string>{"LIRE_MAILLAGE"});  // AFFE_MODELE's handler never ran
}

TEST_F(RunnerTest, ConceptOfTheWrongTypeIsRejected) {
  std::string err = run(std::string(kMesh) + "MAT = DEFI_MATERIAU{ ELAS = _F{ E = 1.0, NU = 0.0 } }\n"
                        "CH = AFFE_MATERIAU{ MAILLAGE = MAT, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }\n");
  EXPECT_EQ(err, "t.lua:3: AFFE_MATERIAU: MAILLAGE: expected maillage concept, got mater MAT");
}

TEST_F(RunnerTest, HandlersReceiveValidatedArgsWithDefaults) {
  ASSERT_EQ(run("MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2, NU = 0.3 } }"), "");
  const KwNode& elas = recorder.last.factors.at("ELAS")[0];
  EXPECT_DOUBLE_EQ(std::get<double>(elas.simple.at("E")[0]), 2.0);  // Int accepted for Real, converted
  EXPECT_EQ(recorder.lines, std::vector<int>{1});
  EXPECT_NE(out.str().find("t.lua:1: DEFI_MATERIAU{ INFO=1, ELAS=_F{ E=2, NU=0.3 } }"), std::string::npos) << out.str();
  ASSERT_EQ(run("MA = LIRE_MAILLAGE{}"), "");
  EXPECT_EQ(std::get<long long>(recorder.last.simple.at("UNITE")[0]), 20);
  EXPECT_EQ(std::get<std::string>(recorder.last.simple.at("FORMAT")[0]), "MED");
}

TEST_F(RunnerTest, ConceptsAreTypedUserdataNamedByTheirVariable) {
  ASSERT_EQ(run(std::string(kMesh) +
                "assert(tostring(MA) == '<maillage MA>', tostring(MA))\n"
                "assert(getmetatable(MA).__name == 'maillage')\n"
                "local t = MA\n"
                "assert(type(MA) == 'userdata')\n"),
            "");
  ASSERT_EQ(recorder.results.size(), 1u);
  EXPECT_EQ(recorder.results[0]->user_name, "MA");
}

TEST_F(RunnerTest, StrictGlobalsSuggestTheClosestName) {
  std::string err = run(std::string(kMesh) + "MO = AFFE_MODEL{ MAILLAGE = MA }\n");
  EXPECT_EQ(err, "t.lua:2: unknown name 'AFFE_MODEL' (did you mean AFFE_MODELE?)");
  err = run("x = 1\nlocal y = xx + 1\n");
  EXPECT_EQ(err, "t.lua:2: unknown name 'xx' (did you mean x?)");
  EXPECT_EQ(run("x = nil\nassert(x == nil)\nfor i = 1, 3 do y = i end\nassert(y == 3)\n"), "");
}

TEST_F(RunnerTest, SandboxHasNoProcessFileOrDebugAccess) {
  EXPECT_EQ(run("os.execute('true')"), "t.lua:1: unknown name 'os'");
  EXPECT_EQ(run("local f = io.popen('ls')"), "t.lua:1: unknown name 'io'");
  EXPECT_EQ(run("debug.traceback()").substr(0, 29), "t.lua:1: unknown name 'debug'");
  EXPECT_EQ(run("assert(rawget(_G, 'dofile') == nil and rawget(_G, 'loadfile') == nil and string.dump == nil)\n"
                "assert(rawget(_G, 'package') == nil)\n"),
            "");
  // load accepts text only: a precompiled chunk (starting with ESC) is refused.
  EXPECT_EQ(run("local f, err = load('\\27Lua')\nassert(f == nil and err:find('binary'), err)\n"
                "assert(load('return 1 + 1')() == 2)\n"),
            "");
  EXPECT_EQ(run("load(function() return nil end)"),
            "t.lua:1: load: only text chunks given as strings are allowed in decks");
}

TEST_F(RunnerTest, TypedErrorsRoundTripThroughLua) {
  std::string err = run(std::string(kMesh) + "R = STAT_NON_LINE{}\n", with("LIRE_MAILLAGE", solve_error_handler));
  EXPECT_EQ(err, "t.lua:1: LIRE_MAILLAGE: Newton did not converge");
  EXPECT_EQ(kind, ErrorKind::Solve);
  err = run(kMesh, with("LIRE_MAILLAGE", std_error_handler));
  EXPECT_EQ(err, "t.lua:1: LIRE_MAILLAGE: unexpected exception: vector::at");
  EXPECT_EQ(kind, ErrorKind::Internal);
  err = run(kMesh, with("LIRE_MAILLAGE", wrong_type_handler));
  EXPECT_EQ(kind, ErrorKind::Internal);
  EXPECT_EQ(err, "t.lua:1: LIRE_MAILLAGE: the handler returned a modele concept instead of a maillage");
  err = run(kMesh, [](const std::string&) -> cmd::Handler { return nullptr; });
  EXPECT_EQ(err, "t.lua:1: LIRE_MAILLAGE: command LIRE_MAILLAGE has no handler");
  EXPECT_EQ(kind, ErrorKind::Internal);
}

TEST_F(RunnerTest, HandlerErrorsKeepTheirKeywordPath) {
  std::string err = run(std::string(kMesh) + "MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = 'PLAK',"
                        " PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }\n",
                        with("AFFE_MODELE", group_error_handler));
  EXPECT_EQ(err, "t.lua:2: AFFE_MODELE: AFFE[1].GROUP_MA: expected a cell group of the mesh, got 'PLAK'");
}

TEST_F(RunnerTest, ErrorsInsideUserFunctionsPointAtTheCall) {
  std::string err = run("local function mesh()\n  return LIRE_MAILLAGE{ FORMAT = 'MEDD' }\nend\nMA = mesh()\n");
  EXPECT_EQ(err, "t.lua:2: LIRE_MAILLAGE: FORMAT: expected one of 'MED', 'GMSH', 'ASTER', got 'MEDD'\n    did you mean 'MED'?");
  err = run("local function f(x)\n  return x.y + 1\nend\nf({})\n");
  EXPECT_EQ(err.substr(0, 45), "t.lua:2: attempt to perform arithmetic on a n");
  EXPECT_EQ(kind, ErrorKind::Deck);
}

TEST_F(RunnerTest, LuaSyntaxErrorIsDeckError) {
  std::string err = run("DEBUT()\nMA = = LIRE_MAILLAGE{}\n");
  EXPECT_EQ(err.substr(0, 9), "t.lua:2: ");
  EXPECT_EQ(kind, ErrorKind::Deck);
}

TEST_F(RunnerTest, ReuseOnlyWhereAllowed) {
  std::string err = run(std::string(kMesh) + "MAT = DEFI_MATERIAU{ reuse = MA, ELAS = _F{ E = 1.0, NU = 0.0 } }\n");
  EXPECT_EQ(err, "t.lua:2: DEFI_MATERIAU: reuse: expected no reuse (DEFI_MATERIAU always creates a new concept), "
                 "got maillage MA");
  EXPECT_EQ(run(std::string(kMesh) +
                "MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA, CREA_GROUP_NO = _F{ GROUP_MA = 'AB' } }\n"),
            "");
}

TEST_F(RunnerTest, ErrorCaughtByPcallDoesNotStopTheDeck) {
  EXPECT_EQ(run("local ok, msg = pcall(LIRE_MAILLAGE, { FORMAT = 'X' })\nassert(not ok and msg:find('FORMAT'))\n" +
                std::string(kMesh)),
            "");
  EXPECT_EQ(recorder.commands, std::vector<std::string>{"LIRE_MAILLAGE"});
}

TEST_F(RunnerTest, TheDeckContractExampleValidates) {
  const std::string deck = R"(
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED' }
MA = DEFI_GROUP{ reuse = MA, MAILLAGE = MA,
                 CREA_GROUP_NO = { _F{ GROUP_MA = 'AB' }, _F{ GROUP_MA = 'CD' } } }
MO = AFFE_MODELE{ MAILLAGE = MA,
                  AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = {'PLAQUE1', 'PLAQUE2'}, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 },
                                    _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } } }
CHA2 = AFFE_CHAR_MECA{ MODELE = MO,
                       CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                                     INTEGRATION = 'SIMPSON2', COEF_REGU_CONT = 1000.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'CONTINUE',
                     ZONE = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', INTEGRATION = 'SIMPSON', ORDRE_INT = 4,
                                CONTACT_INIT = 'NON', COEF_CONT = 1000.0 },
                     ALGO_RESO_CONT = 'POINT_FIXE', ALGO_RESO_GEOM = 'POINT_FIXE', REAC_GEOM = 'CONTROLE',
                     NB_ITER_GEOM = 2 }
RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                      EXCIT = { _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, _F{ CHARGE = CHA2 } },
                      COMP_ELAS = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST } }
RESU = CALC_CHAMP{ reuse = RESU, RESULTAT = RESU, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
TEST_RESU{ RESU = {
  _F{ RESULTAT = RESU, NUME_ORDRE = 1, GROUP_NO = 'A', NOM_CHAM = 'DEPL', NOM_CMP = 'LAGS_C',
      VALE_CALC = -1.0e5, REFERENCE = 'ANALYTIQUE', VALE_REFE = -1.0e5, CRITERE = 'RELATIF', PRECISION = 1.0e-2 },
} }
IMPR_RESU{ FORMAT = 'MED', RESU = _F{ RESULTAT = RESU } }
FIN()
)";
  ASSERT_EQ(run(deck), "");
  EXPECT_EQ(recorder.commands.size(), 16u);
  EXPECT_EQ(recorder.commands.back(), "FIN");
}

TEST(RunDeck, ExitCodesFollowTheOutcome) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-lua-decks";
  fs::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const std::string check = "TEST_RESU{ RESU = _F{ RESULTAT = R, NUME_ORDRE = 1, NOEUD = 'N1', NOM_CHAM = 'DEPL', "
                            "NOM_CMP = 'DX', VALE_CALC = %s } }\n";
  const std::string head = "MA = LIRE_MAILLAGE{}\nR = CALC_CHAMP{ RESULTAT = MA, CONTRAINTE = 'SIGM_NOEU' }\n";
  auto lookup = with("TEST_RESU", test_resu_handler);
  auto code_of = [&](const fs::path& deck) {
    std::ostringstream out, err;
    Log log(out, 0);
    cmd::Session session(log);
    return lua::run_deck(deck, session, lookup, err);
  };
  // R is a maillage here: CALC_CHAMP rejects it before any handler runs -> 2.
  EXPECT_EQ(code_of(write("bad.lua", head)), 2);
  auto deck_with = [&](const std::string& value) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, check.c_str(), value.c_str());
    return "R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, INCREMENT = _F{ LIST_INST = L } }\n" + std::string(buffer);
  };
  const std::string setup = "MA = LIRE_MAILLAGE{}\nMO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', "
                            "PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }\n"
                            "M = DEFI_MATERIAU{ ELAS = _F{ E = 1, NU = 0 } }\n"
                            "CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = M } }\n"
                            "L = DEFI_LIST_REEL{ VALE = { 0, 1 } }\n";
  EXPECT_EQ(code_of(write("ok.lua", setup + deck_with("1.0"))), 0);
  EXPECT_EQ(code_of(write("nook.lua", setup + deck_with("-1.0"))), 1);
  EXPECT_EQ(code_of(dir / "missing.lua"), 2);
  auto code_with = [&](const fs::path& deck, lua::HandlerLookup special) {
    std::ostringstream out, err;
    Log log(out, 0);
    cmd::Session session(log);
    return lua::run_deck(deck, session, std::move(special), err);
  };
  const fs::path mesh_only = write("mesh.lua", "MA = LIRE_MAILLAGE{}\n");
  EXPECT_EQ(code_with(mesh_only, generic()), 0);
  EXPECT_EQ(code_with(mesh_only, with("LIRE_MAILLAGE", solve_error_handler)), 3);
  EXPECT_EQ(code_with(mesh_only, with("LIRE_MAILLAGE", std_error_handler)), 4);
}

TEST(RunDeck, RequireLoadsModulesBesideTheDeck) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-lua-require";
  fs::create_directories(dir / "lib");
  std::ofstream(dir / "lib" / "params.lua") << "return { young = 2.0e6 }\n";
  std::ofstream(dir / "main.lua") << "local p = require('lib.params')\nassert(p.young == 2.0e6)\n"
                                  << "assert(require('lib.params') == p)\n";
  std::ostringstream out, err;
  Log log(out, 0);
  cmd::Session session(log);
  EXPECT_EQ(lua::run_deck(dir / "main.lua", session, generic(), err), 0) << err.str();
}
