// One test per validator rule and message shape (STYLE.md §3).
#include <gtest/gtest.h>

#include <limits>

#include "catalog/args.hpp"
#include "catalog/spec.hpp"

using namespace lunaster;
using namespace lunaster::catalog;

namespace {

struct FakeConcept : Concept {
  explicit FakeConcept(std::string type, std::string name = {}) : type_(std::move(type)) { user_name = std::move(name); }
  std::string type_name() const override { return type_; }
  std::string type_;
};

/// A small command exercising every feature of the validator.
CommandSpec test_spec() {
  CommandSpec spec;
  spec.name = "TEST_CMD";
  spec.result_type = "modele";
  spec.body = factor("TEST_CMD",
                     {concept_kw("MAILLAGE", {"maillage"}, "mesh").required(),
                      real("COEF", "a real").range(0.0, 1.0),
                      integer("NB", "an int").def(3LL).range(1, 10),
                      text("MODE", "a choice").into_values({"D_PLAN", "C_PLAN", "3D"}).def("D_PLAN"),
                      text("GROUP_MA", "groups").many(),
                      text("TOUT", "all").into_values({"OUI"}),
                      real("PAIR", "two reals").count(2, 2),
                      factor("EXCIT", {concept_kw("CHARGE", {"char_meca"}, "load").required(), real("MULT", "m").def(1.0)},
                             "loads")
                          .occurs(1, -1),
                      factor("CONVERGENCE", {real("RESI", "r").def(1e-6).range(0.0, 1.0), integer("ITER", "i").def(10LL)},
                             "conv")
                          .by_default(),
                      text("INTEGRATION", "scheme").into_values({"AUTO", "GAUSS", "SIMPSON"}).def("AUTO"),
                      real("A", "a"), real("B", "b"), real("C", "c"),
                      real("STIFF", "open lower bound").above(0.0),
                      real("RATIO", "open bounds").above(-1.0).below(0.5),
                      real("MIXED", "closed lower, open upper").range(0.0, std::nullopt).below(1.0),
                      real("VALUES", "any reals").many(),
                      text("AXIS", "refused value").into_values({"NON"}).refuse("OUI", "not supported yet")},
                     "")
                  .with_rules({exactly_one({"TOUT", "GROUP_MA"}), at_most_one({"A", "B"})})
                  .with_blocks({Block{"INTEGRATION", {"GAUSS"}, {integer("ORDRE_INT", "n").def(3LL).range(1, 6)}, {}},
                                Block{"INTEGRATION", {"SIMPSON"}, {integer("ORDRE_INT", "n").def(1LL).range(1, 4)}, {}}});
  return spec;
}

KwNode valid_node() {
  KwNode node;
  node.simple["MAILLAGE"] = {ConceptPtr(std::make_shared<FakeConcept>("maillage", "MA"))};
  node.simple["TOUT"] = {std::string("OUI")};
  KwNode excit;
  excit.simple["CHARGE"] = {ConceptPtr(std::make_shared<FakeConcept>("char_meca", "CH"))};
  node.factors["EXCIT"] = {excit};
  return node;
}

/// The formatted error of validating `node`, or "" if it is valid.
std::string message_of(KwNode node) {
  try {
    validate(test_spec(), node);
  } catch (const DeckError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Validate, AcceptsValidNodeAndFillsDefaults) {
  KwNode node = valid_node();
  const CommandSpec spec = test_spec();
  ASSERT_NO_THROW(validate(spec, node));
  Args args(node, spec.body);
  EXPECT_EQ(args.integer("NB"), 3);
  EXPECT_EQ(args.text("MODE"), "D_PLAN");
  EXPECT_FALSE(args.has("COEF"));
  EXPECT_DOUBLE_EQ(args.factor("EXCIT").real("MULT"), 1.0);
  // CONVERGENCE is present by default, filled with its defaults.
  ASSERT_EQ(args.count("CONVERGENCE"), 1);
  EXPECT_DOUBLE_EQ(args.factor("CONVERGENCE").real("RESI"), 1e-6);
  EXPECT_EQ(args.factor("CONVERGENCE").integer("ITER"), 10);
}

TEST(Validate, UnknownKeywordSuggestsClosest) {
  KwNode node = valid_node();
  node.simple["MOED"] = {std::string("D_PLAN")};
  EXPECT_EQ(message_of(node),
            "TEST_CMD: MOED: expected a keyword of TEST_CMD, got unknown keyword 'MOED'\n    did you mean 'MODE'?");
}

TEST(Validate, UnknownKeywordInFactorHasOccurrencePath) {
  KwNode node = valid_node();
  KwNode second;
  second.simple["CHARGE"] = {ConceptPtr(std::make_shared<FakeConcept>("char_meca"))};
  second.simple["MULTT"] = {1.0};
  node.factors["EXCIT"].push_back(second);
  EXPECT_EQ(message_of(node), "TEST_CMD: EXCIT[2].MULTT: expected a keyword of EXCIT[2], got unknown keyword 'MULTT'\n"
                              "    did you mean 'MULT'?");
}

TEST(Validate, WrongTypeText) {
  KwNode node = valid_node();
  node.simple["COEF"] = {std::string("x")};
  EXPECT_EQ(message_of(node), "TEST_CMD: COEF: expected real in [0, 1], got 'x'");
}

TEST(Validate, WrongConceptType) {
  KwNode node = valid_node();
  node.simple["MAILLAGE"] = {ConceptPtr(std::make_shared<FakeConcept>("modele", "MO"))};
  EXPECT_EQ(message_of(node), "TEST_CMD: MAILLAGE: expected maillage concept, got modele MO");
}

TEST(Validate, IntAcceptedForRealAndConverted) {
  KwNode node = valid_node();
  node.simple["COEF"] = {1LL};
  const CommandSpec spec = test_spec();
  validate(spec, node);
  ASSERT_TRUE(std::holds_alternative<double>(node.simple["COEF"][0]));
  EXPECT_DOUBLE_EQ(Args(node, spec.body).real("COEF"), 1.0);
}

TEST(Validate, IntegralRealAcceptedForIntNonIntegralRejected) {
  KwNode node = valid_node();
  node.simple["NB"] = {4.0};
  const CommandSpec spec = test_spec();
  validate(spec, node);
  EXPECT_EQ(Args(node, spec.body).integer("NB"), 4);
  KwNode bad = valid_node();
  bad.simple["NB"] = {2.5};
  EXPECT_EQ(message_of(bad), "TEST_CMD: NB: expected integer in [1, 10], got 2.5");
}

TEST(Validate, IntoSuggestsClosestValue) {
  KwNode node = valid_node();
  node.simple["MODE"] = {std::string("D_PLN")};
  EXPECT_EQ(message_of(node),
            "TEST_CMD: MODE: expected one of 'D_PLAN', 'C_PLAN', '3D', got 'D_PLN'\n    did you mean 'D_PLAN'?");
}

TEST(Validate, RangeMinAndMax) {
  KwNode node = valid_node();
  node.simple["COEF"] = {-1e-06};
  EXPECT_EQ(message_of(node), "TEST_CMD: COEF: expected real in [0, 1], got -1e-06");
  node.simple["COEF"] = {2.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: COEF: expected real in [0, 1], got 2");
}

TEST(Validate, OpenBoundsExcludeTheirEnds) {
  KwNode node = valid_node();
  node.simple["STIFF"] = {0.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: STIFF: expected real > 0, got 0");
  node.simple["STIFF"] = {1e-300};
  EXPECT_EQ(message_of(node), "");
  node.simple["RATIO"] = {0.5};
  EXPECT_EQ(message_of(node), "TEST_CMD: RATIO: expected real in (-1, 0.5), got 0.5");
  node.simple["RATIO"] = {-1.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: RATIO: expected real in (-1, 0.5), got -1");
  node.simple["RATIO"] = {0.4999};
  EXPECT_EQ(message_of(node), "");
  node.simple["MIXED"] = {1.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: MIXED: expected real in [0, 1), got 1");
  node.simple["MIXED"] = {0.0};
  EXPECT_EQ(message_of(node), "");
}

TEST(Validate, NonFiniteRealsAreRefusedEverywhere) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  KwNode node = valid_node();
  // NaN compares false with every bound: without the finiteness check it would pass them all.
  node.simple["STIFF"] = {-nan};
  EXPECT_EQ(message_of(node), "TEST_CMD: STIFF: expected a finite real > 0, got nan");
  node.simple["STIFF"] = {inf};
  EXPECT_EQ(message_of(node), "TEST_CMD: STIFF: expected a finite real > 0, got inf");
  node.simple.erase("STIFF");
  node.simple["A"] = {-inf};  // a real without bounds
  EXPECT_EQ(message_of(node), "TEST_CMD: A: expected a finite real, got -inf");
  node.simple.erase("A");
  node.simple["VALUES"] = {0.0, 1.0, nan};  // each value of a list
  EXPECT_EQ(message_of(node), "TEST_CMD: VALUES: expected a finite real, got nan");
  node.simple.erase("VALUES");
  node.simple["NB"] = {inf};  // an integer keyword
  EXPECT_EQ(message_of(node), "TEST_CMD: NB: expected integer in [1, 10], got inf");
}

TEST(Validate, RefusedValueNamesTheReason) {
  KwNode node = valid_node();
  node.simple["AXIS"] = {std::string("OUI")};
  EXPECT_EQ(message_of(node), "TEST_CMD: AXIS: expected 'NON' (not supported yet), got 'OUI'");
  node.simple["AXIS"] = {std::string("NON")};
  EXPECT_EQ(message_of(node), "");
}

TEST(Validate, ValueCounts) {
  KwNode node = valid_node();
  node.simple["PAIR"] = {1.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: PAIR: expected at least 2 values (real), got 1 value");
  node.simple["PAIR"] = {1.0, 2.0, 3.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: PAIR: expected at most 2 values, got a list of 3 values");
  node.simple.erase("PAIR");
  node.simple["NB"] = {1LL, 2LL};
  EXPECT_EQ(message_of(node), "TEST_CMD: NB: expected a single value (integer in [1, 10]), got a list of 2 values");
}

TEST(Validate, FactorOccurrences) {
  KwNode node = valid_node();
  node.factors["CONVERGENCE"] = {KwNode{}, KwNode{}};
  EXPECT_EQ(message_of(node), "TEST_CMD: CONVERGENCE: expected at most 1 occurrence, got 2 occurrences");
}

TEST(Validate, MissingRequiredKeywords) {
  KwNode node = valid_node();
  node.simple.erase("MAILLAGE");
  EXPECT_EQ(message_of(node), "TEST_CMD: MAILLAGE: expected maillage concept (mandatory keyword), got nothing");
  KwNode no_excit = valid_node();
  no_excit.factors.erase("EXCIT");
  EXPECT_EQ(message_of(no_excit), "TEST_CMD: EXCIT: expected _F{...} (mandatory factor keyword), got nothing");
}

TEST(Validate, ValueGivenForFactorAndTableForSimple) {
  KwNode node = valid_node();
  node.simple["CONVERGENCE"] = {1.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: CONVERGENCE: expected _F{...} (factor keyword), got 1");
  KwNode table = valid_node();
  KwNode inner;
  inner.simple["X"] = {1.0};
  table.factors["COEF"] = {inner};
  EXPECT_EQ(message_of(table), "TEST_CMD: COEF: expected real in [0, 1], got a table of keywords");
}

TEST(Validate, RuleExactlyOne) {
  KwNode node = valid_node();
  node.simple["GROUP_MA"] = {std::string("G")};
  EXPECT_EQ(message_of(node), "TEST_CMD: expected exactly one of TOUT, GROUP_MA, got TOUT and GROUP_MA");
  node.simple.erase("TOUT");
  node.simple.erase("GROUP_MA");
  EXPECT_EQ(message_of(node), "TEST_CMD: expected exactly one of TOUT, GROUP_MA, got none");
}

TEST(Validate, RuleAtMostOne) {
  KwNode node = valid_node();
  node.simple["A"] = {1.0};
  node.simple["B"] = {1.0};
  EXPECT_EQ(message_of(node), "TEST_CMD: expected at most one of A, B, got A and B");
}

namespace {
std::string rule_message(Rule rule, std::vector<std::string> given) {
  CommandSpec spec;
  spec.name = "R";
  spec.body = factor("R", {real("A"), real("B"), real("C")}).with_rules({std::move(rule)});
  KwNode node;
  for (const auto& name : given) node.simple[name] = {1.0};
  try {
    validate(spec, node);
  } catch (const DeckError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Validate, RuleAtLeastOne) {
  EXPECT_EQ(rule_message(at_least_one({"A", "B"}), {}), "R: expected at least one of A, B, got none");
  EXPECT_EQ(rule_message(at_least_one({"A", "B"}), {"B"}), "");
}

TEST(Validate, RuleTogether) {
  EXPECT_EQ(rule_message(together({"A", "B", "C"}), {"A", "C"}), "R: expected all or none of A, B, C, got only A and C");
  EXPECT_EQ(rule_message(together({"A", "B", "C"}), {}), "");
  EXPECT_EQ(rule_message(together({"A", "B", "C"}), {"A", "B", "C"}), "");
}

TEST(Validate, RulePresentAbsent) {
  EXPECT_EQ(rule_message(present_absent({"A", "B", "C"}), {"A", "C"}),
            "R: expected none of B, C when A is given, got A with C");
  EXPECT_EQ(rule_message(present_absent({"A", "B", "C"}), {"B", "C"}), "");
}

TEST(Validate, RulePresentPresent) {
  EXPECT_EQ(rule_message(present_present({"A", "B", "C"}), {"A", "B"}), "R: expected C together with A, got A alone");
  EXPECT_EQ(rule_message(present_present({"A", "B", "C"}), {"B"}), "");
}

TEST(Validate, BlockKeywordOnlyValidWhenActive) {
  KwNode node = valid_node();
  node.simple["ORDRE_INT"] = {2LL};
  EXPECT_EQ(message_of(node), "TEST_CMD: ORDRE_INT: expected no ORDRE_INT here (only valid when INTEGRATION = "
                              "'GAUSS' or 'SIMPSON'), got ORDRE_INT = 2");
}

TEST(Validate, BlockSelectsRangeAndDefault) {
  const CommandSpec spec = test_spec();
  KwNode gauss = valid_node();
  gauss.simple["INTEGRATION"] = {std::string("GAUSS")};
  gauss.simple["ORDRE_INT"] = {6LL};
  ASSERT_NO_THROW(validate(spec, gauss));
  KwNode simpson = valid_node();
  simpson.simple["INTEGRATION"] = {std::string("SIMPSON")};
  validate(spec, simpson);
  EXPECT_EQ(Args(simpson, spec.body).integer("ORDRE_INT"), 1);  // SIMPSON block default
  simpson.simple["ORDRE_INT"] = {6LL};
  EXPECT_EQ(message_of(simpson), "TEST_CMD: ORDRE_INT: expected integer in [1, 4], got 6");
}

TEST(Validate, ReportsSeveralViolationsAsHints) {
  KwNode node = valid_node();
  node.simple["COEF"] = {5.0};
  node.simple["MODE"] = {std::string("XX")};
  node.simple.erase("MAILLAGE");
  std::string message = message_of(node);
  // Violations are reported in catalogue order: MAILLAGE is declared first.
  EXPECT_EQ(message.substr(0, message.find('\n')),
            "TEST_CMD: MAILLAGE: expected maillage concept (mandatory keyword), got nothing");
  EXPECT_NE(message.find("\n    also COEF: expected real in [0, 1], got 5"), std::string::npos);
  EXPECT_NE(message.find("\n    also MODE: expected one of 'D_PLAN', 'C_PLAN', '3D', got 'XX'"), std::string::npos);
}

TEST(Validate, CapsViolationsAtTen) {
  CommandSpec spec;
  spec.name = "MANY";
  std::vector<Keyword> keywords;
  for (int i = 0; i < 15; ++i) keywords.push_back(real("K" + std::to_string(i)).required());
  spec.body = factor("MANY", keywords);
  KwNode node;
  try {
    validate(spec, node);
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.hints().size(), 10u);  // 9 further violations + the cap note
    EXPECT_EQ(e.hints().back(), "(further errors not shown)");
  }
}

TEST(ClosestName, CaseInsensitiveAndOnlyWhenClose) {
  EXPECT_EQ(closest_name("affe_model", {"AFFE_MODELE", "AFFE_MATERIAU"}), "AFFE_MODELE");
  EXPECT_EQ(closest_name("SIMPSONN", {"AUTO", "GAUSS", "SIMPSON"}), "SIMPSON");
  EXPECT_EQ(closest_name("XYZ", {"AUTO", "GAUSS", "SIMPSON"}), "");
  EXPECT_EQ(closest_name("E", {"NU", "RHO"}), "");
}

// DEBUT's CODE is 'OUI' in current code_aster files and _F(NIV_PUB_WEB=...) in older ones:
// both forms validate, and each is checked as what it is.
TEST(Validate, SimpleKeywordWithAFactorFormTakesBoth) {
  const CommandSpec& debut = *find_command("DEBUT");
  auto debut_error = [&](KwNode node) -> std::string {
    try {
      validate(debut, node);
    } catch (const DeckError& e) {
      return e.what();
    }
    return "";
  };
  KwNode simple;
  simple.simple["CODE"] = {std::string("OUI")};
  EXPECT_EQ(debut_error(simple), "");
  KwNode old_style;
  KwNode code;
  code.simple["NIV_PUB_WEB"] = {std::string("INTERNET")};
  old_style.factors["CODE"] = {code};
  EXPECT_EQ(debut_error(old_style), "");
  KwNode misspelt = old_style;
  misspelt.factors["CODE"][0].simple["NIV_PUB_WBE"] = {std::string("INTERNET")};
  EXPECT_NE(debut_error(misspelt).find("CODE.NIV_PUB_WBE: expected a keyword of CODE, got unknown keyword 'NIV_PUB_WBE'"),
            std::string::npos)
      << debut_error(misspelt);
  KwNode bad_value;
  bad_value.simple["CODE"] = {std::string("PEUT-ETRE")};
  EXPECT_NE(debut_error(bad_value).find("DEBUT: CODE: expected"), std::string::npos) << debut_error(bad_value);
}
