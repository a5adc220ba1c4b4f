// The .comm -> Lua converter: every Python form of a study file, translated and loaded by
// Lua 5.4 (and run against recording fake commands to read the tables back), every refused
// form (what, line, hint, the line commented out, the line count kept), check_comm against
// the real catalogue, and robustness on random and truncated input.
#include <gtest/gtest.h>

#include <lua.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "lua/comm_convert.hpp"
#include "lua/python_compat.hpp"

using lunaster::lua::check_comm;
using lunaster::lua::CommIssue;
using lunaster::lua::convert_comm;

namespace {

const std::string kMarker = "--[lunaster convert: finish by hand] ";

std::size_t count_lines(const std::string& s) { return std::count(s.begin(), s.end(), '\n') + 1; }

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::size_t b = 0;
  for (;;) {
    std::size_t e = s.find('\n', b);
    out.push_back(s.substr(b, e == std::string::npos ? std::string::npos : e - b));
    if (e == std::string::npos) return out;
    b = e + 1;
  }
}

/// Loads (and, with `run`, runs) Lua text with recording fake commands: every call of an
/// upper-case global appends {name=..., args=...} to CALLS and returns {concept=name};
/// _F returns its table. Then evaluates `expression` and returns it as text (or the error).
class Lua {
 public:
  Lua() : L(luaL_newstate()) {
    luaL_openlibs(L);
    lunaster::lua::open_python_compat(L);
    const char* harness = R"(
      CALLS = {}
      _F = function(t) return t end
      setmetatable(_G, { __index = function(_, name)
        if type(name) == 'string' and name:match('^[A-Z_][A-Z0-9_]*$') then
          return function(t) CALLS[#CALLS + 1] = { name = name, args = t }; return { concept = name } end
        end
      end })
    )";
    luaL_dostring(L, harness);
  }
  ~Lua() { lua_close(L); }
  /// "" if the chunk loads and runs, else Lua's message.
  std::string run(const std::string& text, const char* chunk = "=case.comm") {
    if (luaL_loadbuffer(L, text.data(), text.size(), chunk) != LUA_OK || lua_pcall(L, 0, 0, 0) != LUA_OK) {
      std::string message = lua_tostring(L, -1);
      lua_pop(L, 1);
      return message;
    }
    return "";
  }
  /// The value of a Lua expression as shown by tostring, with its math.type for numbers.
  std::string eval(const std::string& expression) {
    std::string code = "local v = " + expression +
                       "\nif math.type(v) then return math.type(v) .. ':' .. tostring(v) end return tostring(v)";
    if (luaL_dostring(L, code.c_str()) != LUA_OK) {
      std::string message = lua_tostring(L, -1);
      lua_pop(L, 1);
      return "error: " + message;
    }
    std::string v = lua_tostring(L, -1);
    lua_pop(L, 1);
    return v;
  }

 private:
  lua_State* L;
};

/// "" if `text` loads as a Lua chunk (syntax only), else the message.
std::string load_error(const std::string& text) {
  lua_State* L = luaL_newstate();
  std::string message;
  if (luaL_loadbuffer(L, text.data(), text.size(), "=case.comm") != LUA_OK) message = lua_tostring(L, -1);
  lua_close(L);
  return message;
}

/// Converts, checks that nothing was refused, that the lines stay aligned and that Lua runs it.
std::string convert_clean(const std::string& comm, Lua& lua) {
  auto c = convert_comm(comm);
  EXPECT_TRUE(c.refused.empty()) << (c.refused.empty() ? "" : c.refused[0].what) << "\n" << c.lua;
  EXPECT_EQ(count_lines(c.lua), count_lines(comm));
  EXPECT_EQ(lua.run(c.lua), "") << c.lua;
  return c.lua;
}

}  // namespace

TEST(CommConvert, CommandCallsBecomeTableCallsWithTheirKeywords) {
  const std::string comm =
      "DEBUT()\n"
      "MA=LIRE_MAILLAGE(FORMAT='MED',\n"
      "                 UNITE=20)\n"
      "MA=DEFI_GROUP(reuse =MA, MAILLAGE=MA,\n"
      "              CREA_GROUP_NO=(_F(GROUP_MA='AB'), _F(GROUP_MA=('CD', 'EF'),),),)\n"
      "FIN ();\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  const auto l = lines_of(out);
  EXPECT_EQ(l[0], "DEBUT{}");
  EXPECT_EQ(l[1], "MA=LIRE_MAILLAGE{FORMAT='MED',");
  EXPECT_EQ(l[2], "                 UNITE=20}");
  EXPECT_EQ(l[4], "              CREA_GROUP_NO={_F{GROUP_MA='AB'}, _F{GROUP_MA={'CD', 'EF'},},},}");
  EXPECT_EQ(l[5], "FIN {};");
  EXPECT_EQ(lua.eval("#CALLS"), "integer:4");
  EXPECT_EQ(lua.eval("CALLS[1].name"), "DEBUT");
  EXPECT_EQ(lua.eval("CALLS[2].args.UNITE"), "integer:20");
  EXPECT_EQ(lua.eval("CALLS[3].args.reuse.concept"), "LIRE_MAILLAGE");
  EXPECT_EQ(lua.eval("CALLS[3].args.CREA_GROUP_NO[1].GROUP_MA"), "AB");
  EXPECT_EQ(lua.eval("CALLS[3].args.CREA_GROUP_NO[2].GROUP_MA[2]"), "EF");
  EXPECT_EQ(lua.eval("#CALLS[3].args.CREA_GROUP_NO"), "integer:2");
  EXPECT_EQ(lua.eval("CALLS[4].name"), "FIN");
}

TEST(CommConvert, TuplesAndListsBecomeArraysAndParenthesisedValuesStayValues) {
  const std::string comm =
      "A = CMD(ONE=('A',), EMPTY=(), PLAIN=('PLAQUE1'), SUM=(1+2)*3, LIST=[1, [2, 3]], NEST=((1, 2), (3,)))\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  EXPECT_EQ(out, "A = CMD{ONE={'A',}, EMPTY={}, PLAIN=('PLAQUE1'), SUM=(1+2)*3, LIST={1, {2, 3}}, NEST={{1, 2}, {3,}}}\n");
  EXPECT_EQ(lua.eval("CALLS[1].args.ONE[1]"), "A");
  EXPECT_EQ(lua.eval("#CALLS[1].args.ONE"), "integer:1");
  EXPECT_EQ(lua.eval("next(CALLS[1].args.EMPTY)"), "nil");
  EXPECT_EQ(lua.eval("CALLS[1].args.PLAIN"), "PLAQUE1");
  EXPECT_EQ(lua.eval("CALLS[1].args.SUM"), "integer:9");
  EXPECT_EQ(lua.eval("CALLS[1].args.LIST[2][2]"), "integer:3");
  EXPECT_EQ(lua.eval("CALLS[1].args.NEST[2][1]"), "integer:3");
}

TEST(CommConvert, NumbersAsCodeAsterWritesThemReadTheSameInLua) {
  const std::string comm =
      "V = CMD(A=20.0E+05, B=1., C=.5, D=-1.E5, E=1e-3, F=1_000, G=7, H=0x1F, I=0o17, J=0b101, K=1_0.2_5, L=0)\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  EXPECT_EQ(out, "V = CMD{A=20.0E+05, B=1., C=.5, D=-1.E5, E=1e-3, F=1000, G=7, H=0x1F, I=15, J=5, K=10.25, L=0}\n");
  EXPECT_EQ(lua.eval("CALLS[1].args.A"), "float:2000000.0");
  EXPECT_EQ(lua.eval("CALLS[1].args.B"), "float:1.0");
  EXPECT_EQ(lua.eval("CALLS[1].args.C"), "float:0.5");
  EXPECT_EQ(lua.eval("CALLS[1].args.D"), "float:-100000.0");
  EXPECT_EQ(lua.eval("CALLS[1].args.E"), "float:0.001");
  EXPECT_EQ(lua.eval("CALLS[1].args.F"), "integer:1000");
  EXPECT_EQ(lua.eval("CALLS[1].args.G"), "integer:7");
  EXPECT_EQ(lua.eval("CALLS[1].args.H"), "integer:31");
  EXPECT_EQ(lua.eval("CALLS[1].args.I"), "integer:15");
  EXPECT_EQ(lua.eval("CALLS[1].args.J"), "integer:5");
  EXPECT_EQ(lua.eval("CALLS[1].args.K"), "float:10.25");
  EXPECT_EQ(lua.eval("CALLS[1].args.L"), "integer:0");
}

TEST(CommConvert, StringsInBothQuotesWithPythonEscapesTranslated) {
  const std::string comm =
      "S1 = 'it''s'\n"               // adjacent literals
      "S2 = \"say 'hi'\"\n"
      "S3 = 'tab\\there\\n'\n"
      "S4 = '\\u00e9\\x41\\101\\0'\n"  // é (UTF-8), A, A, NUL
      "S5 = 'C:\\data\\d'\n"          // unknown escapes keep their backslash in Python
      "S6 = 'a\\'b' \"c\\\"d\"\n"
      "S7 = 'ab\\\ncd'\n";            // backslash-newline inside a string
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  const auto l = lines_of(out);
  EXPECT_EQ(l[0], "S1 = 'it' .. 's'");
  EXPECT_EQ(l[1], "S2 = \"say 'hi'\"");
  EXPECT_EQ(lua.eval("S1"), "its");
  EXPECT_EQ(lua.eval("S2"), "say 'hi'");
  EXPECT_EQ(lua.eval("S3 == 'tab\\there\\n'"), "true");
  EXPECT_EQ(lua.eval("S4 == '\\xC3\\xA9AA\\0'"), "true");
  EXPECT_EQ(lua.eval("S5"), "C:\\data\\d");
  EXPECT_EQ(lua.eval("S6"), "a'bc\"d");
  EXPECT_EQ(lua.eval("S7"), "abcd");
}

TEST(CommConvert, RawAndTripleQuotedStringsKeepTheirLines) {
  const std::string comm =
      "R = r'\\n\\d'\n"
      "T = \"\"\"first\n"
      "  second ]] 'q'\n"
      "\"\"\"\n"
      "U = '''\n"
      "after a newline'''\n"
      "W = '''x\\ty\n"
      "z'''\n"
      "X = R'''raw\\n\n"
      "two'''\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  const auto l = lines_of(out);
  EXPECT_EQ(l[1], "T = [=[first");  // long bracket with enough '=' for the ']]' inside
  EXPECT_EQ(lua.eval("R"), "\\n\\d");
  EXPECT_EQ(lua.eval("T == 'first\\n  second ]] \\'q\\'\\n'"), "true");
  EXPECT_EQ(lua.eval("U == '\\nafter a newline'"), "true");
  EXPECT_EQ(lua.eval("W == 'x\\ty\\nz'"), "true");
  EXPECT_EQ(lua.eval("X == 'raw\\\\n\\ntwo'"), "true");
}

TEST(CommConvert, CommentsBlankLinesAndIndentationAreKept) {
  const std::string comm =
      "# coding: utf-8\n"
      "\n"
      "A = CMD(VALE='#not a comment',  # real comment\n"
      "        X=1 -# minus, then a comment\n"
      "          2)\n"
      "#[[ not a Lua long comment\n"
      "B = 3\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  const auto l = lines_of(out);
  EXPECT_EQ(l[0], "-- coding: utf-8");
  EXPECT_EQ(l[1], "");
  EXPECT_EQ(l[2], "A = CMD{VALE='#not a comment',  -- real comment");
  EXPECT_EQ(l[5], "-- [[ not a Lua long comment");
  EXPECT_EQ(lua.eval("CALLS[1].args.VALE"), "#not a comment");
  EXPECT_EQ(lua.eval("CALLS[1].args.X"), "integer:-1");
  EXPECT_EQ(lua.eval("B"), "integer:3");
}

TEST(CommConvert, OperatorsAndConstantsTranslate) {
  const std::string comm =
      "A = True; B = False; c = None\n"
      "D = 2**3**2\n"
      "E = 7 // 2; F = 7 % 3; G = 7 / 2\n"
      "H = (1 != 2) and not (3 == 4) or False\n"
      "I = -2**2\n"
      "J = 'N' + 'O'\n"
      "K, L = 1, 2\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  const auto l = lines_of(out);
  EXPECT_EQ(l[0], "A = true; B = false; c = nil");
  EXPECT_EQ(l[1], "D = 2^3^2");
  EXPECT_EQ(l[3], "H = (1 ~= 2) and not (3 == 4) or false");
  EXPECT_EQ(lua.eval("A"), "true");
  EXPECT_EQ(lua.eval("c"), "nil");
  EXPECT_EQ(lua.eval("D"), "float:512.0");
  EXPECT_EQ(lua.eval("E"), "integer:3");
  EXPECT_EQ(lua.eval("F"), "integer:1");
  EXPECT_EQ(lua.eval("G"), "float:3.5");
  EXPECT_EQ(lua.eval("H"), "true");
  EXPECT_EQ(lua.eval("I"), "float:-4.0");
  EXPECT_EQ(lua.eval("J"), "NO");
  EXPECT_EQ(lua.eval("L"), "integer:2");
}

TEST(CommConvert, BackslashContinuationsDropTheBackslashAndKeepTheLine) {
  const std::string comm =
      "A = 1 + \\\n"
      "    2\n"
      "B = CMD(X=A, \\\n"
      "        Y=2)\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  EXPECT_EQ(out, "A = 1 + \n    2\nB = CMD{X=A, \n        Y=2}\n");
  EXPECT_EQ(lua.eval("A"), "integer:3");
  EXPECT_EQ(lua.eval("CALLS[1].args.Y"), "integer:2");
}

TEST(CommConvert, LuaErrorLinesAreCommLines) {
  // A runtime error on .comm line 4 is reported by Lua at line 4 of the chunk named after the .comm.
  const std::string comm =
      "A = '''one\n"
      "two'''\n"
      "B = CMD(X=1,\n"
      "        Y=undefined_value + 1)\n";
  const auto c = convert_comm(comm);
  ASSERT_TRUE(c.refused.empty());
  Lua lua;
  EXPECT_NE(lua.run(c.lua, "=study.comm").find("study.comm:4:"), std::string::npos);
}

namespace {

struct Refusal {
  std::string comm;     ///< the .comm text
  int line;             ///< the issue's line
  std::string what;     ///< a part of the issue's what
  std::string hint;     ///< a part of its hint
  std::vector<int> commented;  ///< lines (1-based) commented out with the marker
};

void expect_refused(const Refusal& r) {
  SCOPED_TRACE(r.comm);
  const auto c = convert_comm(r.comm);
  ASSERT_FALSE(c.refused.empty());
  const auto it = std::find_if(c.refused.begin(), c.refused.end(),
                               [&](const CommIssue& i) { return i.what.find(r.what) != std::string::npos; });
  ASSERT_NE(it, c.refused.end()) << "first issue: " << c.refused[0].what;
  EXPECT_EQ(it->line, r.line);
  EXPECT_NE(it->hint.find(r.hint), std::string::npos) << it->hint;
  EXPECT_EQ(count_lines(c.lua), count_lines(r.comm));
  const auto out = lines_of(c.lua);
  const auto src = lines_of(r.comm);
  for (std::size_t l = 1; l <= out.size(); ++l) {
    const bool commented = std::find(r.commented.begin(), r.commented.end(), static_cast<int>(l)) != r.commented.end();
    if (commented) {
      EXPECT_EQ(out[l - 1].rfind(kMarker, 0), 0u) << "line " << l << ": " << out[l - 1];
      // the original text follows the marker ('#' comments in Lua spelling)
      std::string original = src[l - 1];
      const auto hash = original.find('#');
      if (hash != std::string::npos && original.find('\'') == std::string::npos) original.replace(hash, 1, "--");
      EXPECT_EQ(out[l - 1].substr(kMarker.size()), original);
    } else {
      EXPECT_NE(out[l - 1].rfind(kMarker, 0), 0u) << "line " << l << " should be translated: " << out[l - 1];
    }
  }
  EXPECT_EQ(load_error(c.lua), "") << c.lua;
}

}  // namespace

TEST(CommConvert, RefusedFormsAreReportedAndCommentedOut) {
  const std::vector<Refusal> cases = {
      {"import numpy as NP\nA = 1\n", 1, "import of 'numpy' under another name", "import math", {1}},
      {"A = 1\nfrom Utilitai.partition import *\n", 2, "import of 'Utilitai.partition'", "remove this one", {2}},
      {"def f(x=1):\n    return x*2\n\nA = 1\n", 1, "parameter with a default value", "by hand", {1, 2}},
      {"class C:\n    pass\nA = 1\n", 1, "class definition 'class C'", "by hand", {1, 2}},
      {"for i, j in zip(a, b):\n    X = CMD(A=i)  # body\n    Y = 2\nZ = 1\n", 1, "'for' loop over several names",
       "one name", {1, 2, 3}},
      {"def f(x): return x\nZ = 1\n", 1, "'def' with its body on the same line", "lines below", {1}},
      {"A = 1\nif A > 0:\n    B = 1\nelif A < 0:\n    B = {1: 2}\nelse:\n    B = 3\nC = 4\n", 5, "dict", "_F(...)",
       {2, 3, 4, 5, 6, 7}},
      {"for i in range(2):\n    A = i\nelse:\n    A = 3\nC = 4\n", 3, "'else' block", "branch", {3, 4}},
      {"try:\n    A = 1\nexcept Exception:\n    A = 2\n", 3, "'except' block", "clear error", {1, 2, 3, 4}},
      {"with open('f') as f:\n    A = 1\nB = 2\n", 1, "'with' block", "body", {1, 2}},
      {"A = 1\nreturn A\n", 2, "'return' outside a function", "remove it", {2}},
      {"F = lambda x: x**2\nA = 1\n", 1, "'lambda'", "function (x)", {1}},
      {"L = [i*j for i in range(3) for j in range(2)]\nA = 1\n", 1, "list comprehension in another form", "Lua loop", {1}},
      {"T = f'N{i}'\nA = 1\n", 1, "f-string", "string.format", {1}},
      {"D = {'a': 1}\nA = 1\n", 1, "dict", "_F(...)", {1}},
      {"A = 1\nX = RESU.LIST_PARA()\n", 2, "method call 'RESU.LIST_PARA()'", "no Python methods", {2}},
      {"X = MA.nom\n", 1, "attribute access 'MA.nom'", "finish in Lua", {1}},
      {"A = 1\nV = TAB[1:3]\n", 2, "slice or several indices in 'TAB[...]'", "write the values", {2}},
      {"A = 1\nV = TAB['X', 1, 2]\n", 2, "slice or several indices in 'TAB[...]'", "write the values", {2}},
      {"Y = divmod(7, 2)\n", 1, "Python function call 'divmod'", "compute the value", {1}},
      {"A = CMD(LIST=enumerate(L))\n", 1, "Python function call 'enumerate'", "compute the value", {1}},
      {"print 'done'\n", 1, "neither an assignment nor a command call", "drop it", {1}},
      {"end = 3\nA = 1\n", 1, "identifier 'end' (a Lua reserved word)", "rename", {1}},
      {"A = CMD(X=local)\n", 1, "identifier 'local' (a Lua reserved word)", "rename", {1}},
      {"exec('A = 1')\n", 1, "'exec'", "write out", {1}},
      {"A = eval('1+2')\n", 1, "'eval'", "write out", {1}},
      {"A = DEFI_GROUP(MA,\n               CREA_GROUP_NO=_F(GROUP_MA='AB'))\nB = 1\n", 1,
       "positional argument in DEFI_GROUP(...)", "keywords only", {1, 2}},
      {"A = 1\nA |= 2\n", 2, "augmented assignment '|='", "X = X | value", {2}},
      {"A = B = 1\n", 1, "chained assignment", "one assignment per name", {1}},
      {"A = 1 if B else 2\n", 1, "conditional expression", "c and a or b", {1}},
  };
  for (const auto& r : cases) expect_refused(r);
}

TEST(CommConvert, RefusedStatementIsCommentedOutOnAllItsLinesAndTheRestConverted) {
  const std::string comm =
      "A = CMD(X=1)\n"
      "B = CMD(Y=divmod(2.),\n"
      "        Z=(1, 2))   # note\n"
      "C = CMD(W=[3])\n";
  const auto c = convert_comm(comm);
  ASSERT_EQ(c.refused.size(), 1u);
  EXPECT_EQ(c.refused[0].line, 2);
  const auto l = lines_of(c.lua);
  EXPECT_EQ(l[0], "A = CMD{X=1}");
  EXPECT_EQ(l[1], kMarker + "B = CMD(Y=divmod(2.),");
  EXPECT_EQ(l[2], kMarker + "        Z=(1, 2))   -- note");
  EXPECT_EQ(l[3], "C = CMD{W={3}}");
  Lua lua;
  EXPECT_EQ(lua.run(c.lua), "");
  EXPECT_EQ(lua.eval("#CALLS"), "integer:2");
  EXPECT_EQ(lua.eval("CALLS[2].args.W[1]"), "integer:3");
}

TEST(CommConvert, UnterminatedStringsAndBracketsGiveOneIssueWhereTheyStart) {
  {
    const std::string comm = "A = 1\nB = 'open\nC = 2\n";
    const auto c = convert_comm(comm);
    ASSERT_EQ(c.refused.size(), 1u);
    EXPECT_EQ(c.refused[0].line, 2);
    EXPECT_EQ(c.refused[0].what, "unterminated string");
    EXPECT_EQ(count_lines(c.lua), 4u);
    EXPECT_EQ(lines_of(c.lua)[2], "C = 2");
    EXPECT_EQ(load_error(c.lua), "");
  }
  {
    const std::string comm = "A = 1\nB = CMD(X=(1, 2),\n  Y=3\nC = 2\n";
    const auto c = convert_comm(comm);
    ASSERT_EQ(c.refused.size(), 1u);
    EXPECT_EQ(c.refused[0].line, 2);
    EXPECT_EQ(c.refused[0].what, "unclosed '('");
    EXPECT_EQ(count_lines(c.lua), 5u);
    EXPECT_EQ(lines_of(c.lua)[0], "A = 1");
    EXPECT_EQ(lines_of(c.lua)[3].rfind(kMarker, 0), 0u);
    EXPECT_EQ(load_error(c.lua), "");
  }
  {
    const std::string comm = "A = '''never\nclosed\n";
    const auto c = convert_comm(comm);
    ASSERT_EQ(c.refused.size(), 1u);
    EXPECT_EQ(c.refused[0].line, 1);
    EXPECT_EQ(c.refused[0].what, "unterminated triple-quoted string");
    EXPECT_EQ(count_lines(c.lua), 3u);
  }
}

TEST(CommCheck, UnknownCommandIsReportedWithItsLine) {
  const auto issues = check_comm("DEBUT()\n\nT = POST_ELEM(MASS_INER=_F(TOUT='OUI'))\nR = STAT_NON_LIN(MODELE=MO)\n");
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].line, 3);
  EXPECT_EQ(issues[0].what, "unknown command POST_ELEM");
  EXPECT_EQ(issues[1].line, 4);
  EXPECT_EQ(issues[1].what, "unknown command STAT_NON_LIN (did you mean STAT_NON_LINE?)");
  EXPECT_FALSE(issues[1].hint.empty());
}

TEST(CommCheck, UnknownKeywordsAtEveryFactorDepthWithClosestNames) {
  const std::string comm =
      "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CHMAT,\n"
      "                     EXCIT=(_F(CHARGE=CHA1, FONC_MUL=RAMPE),\n"
      "                            _F(CHARG=CHA2),),\n"
      "                     NEWTON=_F(REAC_ITE=1),\n"
      "                     INCREMENT=_F(LIST_INST=L_INST),\n"
      "                     CONVERGENC=_F(RESI_GLOB_RELA=1.E-6))\n"
      "MAT = DEFI_MATERIAU(ELAS=[_F(E=2.0E6, NUU=0.3)])\n";
  const auto issues = check_comm(comm);
  ASSERT_EQ(issues.size(), 5u);
  EXPECT_EQ(issues[0].line, 2);
  EXPECT_EQ(issues[0].what, "STAT_NON_LINE: unknown keyword EXCIT[1]/FONC_MUL (did you mean FONC_MULT?)");
  EXPECT_EQ(issues[1].line, 3);
  EXPECT_EQ(issues[1].what, "STAT_NON_LINE: unknown keyword EXCIT[2]/CHARG (did you mean CHARGE?)");
  EXPECT_EQ(issues[2].line, 4);
  EXPECT_EQ(issues[2].what, "STAT_NON_LINE: unknown keyword NEWTON/REAC_ITE (did you mean REAC_ITER?)");
  EXPECT_EQ(issues[3].line, 6);
  EXPECT_EQ(issues[3].what, "STAT_NON_LINE: unknown keyword CONVERGENC (did you mean CONVERGENCE?)");
  EXPECT_EQ(issues[4].line, 7);
  EXPECT_EQ(issues[4].what, "DEFI_MATERIAU: unknown keyword ELAS/NUU (did you mean NU?)");
  EXPECT_NE(issues[0].hint.find("lunaster help STAT_NON_LINE"), std::string::npos);
}

TEST(CommCheck, AKnownStudyHasNoIssueAndRefusedFormsAreIncluded) {
  const std::string comm =
      "DEBUT()\n"
      "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
      "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n"
      "MAT = DEFI_MATERIAU(ELAS=_F(E=2.0E6, NU=0.0))\n"
      "L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))\n"
      "FIN()\n";
  EXPECT_TRUE(check_comm(comm).empty());
  const auto issues = check_comm(comm + "import os\n");
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].line, 7);
  EXPECT_EQ(issues[0].what, "import of 'os'");
}

TEST(CommConvert, RandomAndTruncatedInputsReturnWithTheLineCountKept) {
  const std::string study =
      "# study\nDEBUT()\nMA=DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=(_F(GROUP_MA='AB'),),)\n"
      "T = '''a\nb''' \"c\\\"\" r'\\d'\nX = [1., .5, -1.E5, 1_0]; Y = (1,)\nfor i in range(2):\n    Z = sqrt(i)\n"
      "def f(x):\n  return {1: x}\nA = B.c[1] ** 2 != 3 \\\n  + 4\nF = f'{x}' # end\n";
  for (std::size_t n = 0; n <= study.size(); ++n) {
    const std::string part = study.substr(0, n);
    const auto c = convert_comm(part);
    ASSERT_EQ(count_lines(c.lua), count_lines(part)) << part;
    check_comm(part);
  }
  const std::vector<std::string> pieces = {"(", ")", "[", "]", "{", "}", "'", "\"", "'''", "\"\"\"", "\\", "\n",
                                           "\\\n", "#", " ", "\t", "\r", "=", ",", ":", ";", ".", "_F", "CMD", "x",
                                           "r", "f", "1", "1.", ".5", "e5", "**", "!=", "for", "if", "def", "end",
                                           "\\x", "\\u12", "\\N", "0o", "0b2", "1j", "\xc3\xa9", std::string(1, '\0')};
  std::mt19937 random(12345);
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text;
    const int count = 1 + static_cast<int>(random() % 40);
    for (int k = 0; k < count; ++k) text += pieces[random() % pieces.size()];
    const auto c = convert_comm(text);
    ASSERT_EQ(count_lines(c.lua), count_lines(text)) << text;
    for (const auto& issue : c.refused) {
      ASSERT_GE(issue.line, 1);
      ASSERT_LE(static_cast<std::size_t>(issue.line), count_lines(text));
    }
    check_comm(text);
  }
}

// DEFI_CONTACT declares ZONE once per FORMULATION: --check takes the keywords of both, since
// which one applies (DISCRETE by default) is decided at run time.
TEST(CommCheck, AFactorDeclaredInSeveralBlocksTakesTheKeywordsOfAll) {
  const auto issues = check_comm(
      "CONT = DEFI_CONTACT(MODELE=MO, ZONE=_F(GROUP_MA_ESCL='EF', GROUP_MA_MAIT='AB', ALGO_CONT='PENALISATION', "
      "E_N=1.e7))\n"
      "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_ESCL='EF', GROUP_MA_MAIT='AB', "
      "COEF_CONT=100.))\n"
      "CONT = DEFI_CONTACT(MODELE=MO, ZONE=_F(GROUP_MA_ESCL='EF', GROUP_MA_MAIT='AB', E_NN=1.e7))\n");
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].line, 3);
  EXPECT_NE(issues[0].what.find("unknown keyword ZONE[1]/E_NN (did you mean E_N?)"), std::string::npos) << issues[0].what;
}

// code_aster's table cell TAB['PARA', i] is the deck's TAB['PARA'][i] (rows from 1 in both).
TEST(CommConvert, TableCellsBecomeTheDeckSpelling) {
  const auto converted = convert_comm("F = TAB['DY', 1]\nG = -2.0 * TAB[\"DX\", n + 1] / TAB['DY', len]\n");
  ASSERT_TRUE(converted.refused.empty()) << converted.refused.front().what;
  EXPECT_EQ(converted.lua, "F = TAB['DY'][ 1]\nG = -2.0 * TAB[\"DX\"][ n + 1] / TAB['DY'][ len]\n");
}

// The Python around the commands of code_aster's own studies: math imported, built-ins, loops,
// if/elif/else, defs with local names, list comprehensions, %-formatting and str.format, 0-based
// indexing, augmented assignment, list appends. Each line stays on its line, and the values are Python's.
TEST(CommConvert, ThePythonOfStudiesRunsLineForLineWithPythonsValues) {
  const std::string comm =
      "import math\n"
      "from math import *\n"
      "E = 2.0E5 ; nu = 0.3 ; e = 0.5\n"
      "R = sqrt(2.) * cos(pi/4) + math.atan2(1., 1.) * 4 / math.pi\n"
      "N = 3\n"
      "groups = ['G%d' % i for i in range(N)]\n"
      "sizes = [(1./2.**(i+1)) for i in range(N) if i > 0]\n"
      "names = []\n"
      "for i in range(1, N + 1):\n"
      "    names.append('S_%d_%s' % (i, 'x'))\n"
      "    if i == 2:\n"
      "        X2 = i * 10\n"
      "    elif i == 3:\n"
      "        X3 = -1\n"
      "    else:\n"
      "        X1 = 1\n"
      "total = 0\n"
      "for g in groups:\n"
      "    total += len(g)\n"
      "def radius(x, y):\n"
      "    r2 = x*x + y*y\n"
      "    return sqrt(r2)\n"
      "def EPSI_XX(x, y):\n"
      "    return radius(x, y) / 2.\n"
      "label = 'E={} nu={:.2f}'.format(E, nu) + '_' + str(N) + '_' + str(e)\n"
      "first = groups[0] ; last = groups[-1] ; k = 1 ; mid = groups[k]\n"
      "CH = CMD(DDL_IMPO=[_F(GROUP_MA=g, DX=EPSI_XX(3., 4.)) for g in groups], N=int(7.9), P=pow(2, 10))\n"
      "for j in range(10, 0, -4):\n"
      "    last_j = j\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  const auto l = lines_of(out);
  EXPECT_EQ(l[0], "local math = py.math");
  EXPECT_EQ(l[5], "groups = py.comp(function(i) return py.fmt('G%d' , i) end,   py.range(N))");
  EXPECT_EQ(l[8], "for i = 1, (N + 1) - 1 do");
  EXPECT_EQ(l[15], "        X1 = 1 end end");
  EXPECT_EQ(l[19], "function radius(x, y) local r2");
  EXPECT_EQ(l[25], "first = groups[1] ; last = groups[#groups + 1 -1] ; k = 1 ; mid = groups[(k) + 1]");
  EXPECT_EQ(lua.eval("R"), "float:2.0");
  EXPECT_EQ(lua.eval("table.concat(groups, ',')"), "G0,G1,G2");
  EXPECT_EQ(lua.eval("table.concat(sizes, ',')"), "0.25,0.125");
  EXPECT_EQ(lua.eval("table.concat(names, ',')"), "S_1_x,S_2_x,S_3_x");
  EXPECT_EQ(lua.eval("X1 + X2 + X3"), "integer:20");
  EXPECT_EQ(lua.eval("total"), "integer:6");
  EXPECT_EQ(lua.eval("r2"), "nil");  // the def's name is local
  EXPECT_EQ(lua.eval("label"), "E=200000.0 nu=0.30_3_0.5");
  EXPECT_EQ(lua.eval("first .. last .. mid"), "G0G2G1");
  EXPECT_EQ(lua.eval("#CALLS"), "integer:1");
  EXPECT_EQ(lua.eval("CALLS[1].args.DDL_IMPO[3].GROUP_MA"), "G2");
  EXPECT_EQ(lua.eval("CALLS[1].args.DDL_IMPO[1].DX"), "float:2.5");
  EXPECT_EQ(lua.eval("CALLS[1].args.N"), "integer:7");
  EXPECT_EQ(lua.eval("CALLS[1].args.P"), "float:1024.0");  // math's pow after from math import *, as in Python
  EXPECT_EQ(lua.eval("last_j"), "integer:2");
  // a def named like a command is called as a function, and --check does not take it for one
  EXPECT_TRUE(check_comm("def EPSI_XX(x):\n    return x\nA = EPSI_XX(1.)\n").empty());
}

// py.fmt and py.str write what Python's % and str write.
TEST(CommConvert, PythonFormattingOfNumbers) {
  Lua lua;
  EXPECT_EQ(lua.eval("py.str(1.0) .. ' ' .. py.str(0.1) .. ' ' .. py.str(2.1e11) .. ' ' .. py.str(1e16) .. ' ' .. py.str(1e-5)"),
            "1.0 0.1 210000000000.0 1e+16 1e-05");
  EXPECT_EQ(lua.eval("py.fmt('%5.2f|%-4d|%e|%%|%i|%s|%r', {3.14159, 2.0, 1500.0, 7.9, 1.5, 'a'})"),
            " 3.14|2   |1.500000e+03|%|7|1.5|'a'");
  EXPECT_EQ(lua.eval("py.format('{}-{:.3f}-{0}|{:>5}|{:05.1f}', 1, 2.5, 'ab', -2.5)"), "1-2.500-1|   ab|-02.5");
  EXPECT_EQ(lua.eval("select(2, pcall(py.math.sqrt, -1))"), "math.sqrt: math domain error");
  EXPECT_EQ(lua.eval("select(2, pcall(py.fmt, '%d %d', 1))"), "not enough arguments for format string");
}

// One-line bodies (`if c: return x`) and docstrings, as code_aster's files write small helpers.
TEST(CommConvert, OneLineBodiesAndDocstrings) {
  const std::string comm =
      "def pr(y) :\n"
      "   \"\"\" the pressure\n"
      "       by parts \"\"\"\n"
      "   if y < 1.e-15 : return 0.E07\n"
      "   if y > 1.e-15 : return 15.E07\n"
      "   return 0.\n"
      "for i in range(3): last = i\n"
      "if last == 2: ok = 1\n"
      "else: ok = 0\n"
      "A = CMD(P=[pr(y) for y in (0., 1.)], L=last, OK=ok)\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  EXPECT_EQ(lines_of(out)[3], "   if y < 1.e-15  then return 0.E07 end");
  EXPECT_EQ(lua.eval("CALLS[1].args.P[2]"), "float:150000000.0");
  EXPECT_EQ(lua.eval("CALLS[1].args.L + CALLS[1].args.OK"), "integer:3");
  const auto refused = convert_comm("if A: for i in B: pass\n").refused;
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_EQ(refused[0].what, "a block inside a one-line 'if'");
}

// Unary plus (VALE=+1.0), text repeated by '*', and '+' joining a number's text: Lua spellings.
TEST(CommConvert, UnaryPlusAndTextRepetition) {
  const std::string comm =
      "A = +2.0E-5\n"
      "B = CMD(V=+1.0, W=(+1, -2), X=2 + +3)\n"
      "S = '-'*3+\"\"\"x\"\"\"\n"
      "N = str(80)+'!'\n";
  Lua lua;
  const std::string out = convert_clean(comm, lua);
  EXPECT_EQ(lines_of(out)[0], "A = 2.0E-5");
  EXPECT_EQ(lua.eval("CALLS[1].args.V"), "float:1.0");
  EXPECT_EQ(lua.eval("CALLS[1].args.X"), "integer:5");
  EXPECT_EQ(lua.eval("S"), "---x");
  EXPECT_EQ(lua.eval("N"), "80!");
}
