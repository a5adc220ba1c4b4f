// Every spec of the catalogue is well formed: defaults inside `into` and
// ranges, rules and blocks name declared keywords, docs everywhere.
#include <gtest/gtest.h>

#include <set>

#include "catalog/args.hpp"
#include "catalog/doc.hpp"
#include "catalog/spec.hpp"

using namespace lunaster;
using namespace lunaster::catalog;

namespace {

const std::set<std::string> kConceptTypes = {"maillage", "modele",   "mater",    "cham_mater", "char_meca", "char_contact",
                                             "listr8",   "list_inst", "fonction", "formule",    "function",
                                             "evol_noli", "table",    "cham_gd"};

bool scalar_matches(const Scalar& s, ValueType type) {
  switch (type) {
    case ValueType::Real: return std::holds_alternative<double>(s);
    case ValueType::Int: return std::holds_alternative<long long>(s);
    case ValueType::Text: return std::holds_alternative<std::string>(s);
    case ValueType::Concept: return false;
  }
  return false;
}

double as_double(const Scalar& s) {
  return std::holds_alternative<double>(s) ? std::get<double>(s) : static_cast<double>(std::get<long long>(s));
}

void check_keyword(const Keyword& kw, const std::string& where) {
  const std::string path = where + "/" + kw.name;
  EXPECT_FALSE(kw.name.empty()) << where;
  EXPECT_FALSE(kw.doc.empty()) << path << " has no doc";
  if (kw.is_factor) {
    EXPECT_TRUE(kw.max_occurs == -1 || kw.max_occurs >= std::max(kw.min_occurs, 1)) << path;
    EXPECT_FALSE(kw.default_value) << path;
    std::set<std::string> names;
    for (const auto& child : kw.children) {
      EXPECT_TRUE(names.insert(child.name).second) << path << " declares " << child.name << " twice";
      check_keyword(child, path);
    }
    std::set<std::string> block_names;
    for (const auto& block : kw.blocks) {
      bool declared = names.count(block.when_keyword) > 0 || block_names.count(block.when_keyword) > 0;
      for (const auto& other : kw.blocks)
        for (const auto& k : other.keywords) declared = declared || k.name == block.when_keyword;
      EXPECT_TRUE(declared) << path << ": block condition on undeclared " << block.when_keyword;
      for (const auto& k : block.keywords) {
        EXPECT_EQ(names.count(k.name), 0u) << path << ": " << k.name << " both plain and in a block";
        block_names.insert(k.name);
        check_keyword(k, path);
      }
    }
    auto check_rule_names = [&](const Rule& rule) {
      EXPECT_GE(rule.names.size(), 2u) << path;
      for (const auto& name : rule.names)
        EXPECT_TRUE(names.count(name) || block_names.count(name)) << path << ": rule names undeclared " << name;
    };
    for (const auto& rule : kw.rules) check_rule_names(rule);
    for (const auto& block : kw.blocks)
      for (const auto& rule : block.rules) check_rule_names(rule);
    return;
  }
  EXPECT_TRUE(kw.max_values == -1 || kw.max_values >= kw.min_values) << path;
  EXPECT_GE(kw.min_values, 0) << path;
  if (kw.type == ValueType::Concept) {
    EXPECT_FALSE(kw.concept_types.empty()) << path;
    for (const auto& t : kw.concept_types) {
      EXPECT_TRUE(kConceptTypes.count(t)) << path << ": unknown concept " << t;
    }
    EXPECT_FALSE(kw.default_value) << path;
  }
  for (const auto& value : kw.into) {
    EXPECT_TRUE(scalar_matches(value, kw.type)) << path << ": into of the wrong type";
  }
  for (const auto& [value, reason] : kw.refused) {
    EXPECT_TRUE(scalar_matches(value, kw.type)) << path << ": refused value of the wrong type";
    EXPECT_FALSE(reason.empty()) << path << ": a refused value without its reason";
    for (const auto& allowed : kw.into) EXPECT_FALSE(allowed == value) << path << ": a value both allowed and refused";
  }
  EXPECT_FALSE(kw.min_open && !kw.val_min) << path;
  EXPECT_FALSE(kw.max_open && !kw.val_max) << path;
  if (kw.val_min && kw.val_max) {
    EXPECT_LE(*kw.val_min, *kw.val_max) << path;
  }
  if (kw.default_value) {
    EXPECT_NE(kw.status, Status::Required) << path << ": a required keyword with a default";
    EXPECT_TRUE(scalar_matches(*kw.default_value, kw.type)) << path << ": default of the wrong type";
    if (!kw.into.empty()) {
      bool inside = false;
      for (const auto& value : kw.into) inside = inside || value == *kw.default_value;
      EXPECT_TRUE(inside) << path << ": default outside into";
    }
    if (kw.type == ValueType::Real || kw.type == ValueType::Int) {
      double d = as_double(*kw.default_value);
      if (kw.val_min) {
        EXPECT_GE(d, *kw.val_min) << path << ": default below val_min";
        if (kw.min_open) {
          EXPECT_NE(d, *kw.val_min) << path << ": default on an open bound";
        }
      }
      if (kw.val_max) {
        EXPECT_LE(d, *kw.val_max) << path << ": default above val_max";
        if (kw.max_open) {
          EXPECT_NE(d, *kw.val_max) << path << ": default on an open bound";
        }
      }
    }
  }
}

}  // namespace

TEST(Catalog, EverySpecIsWellFormed) {
  std::set<std::string> names;
  for (const auto& spec : all_commands()) {
    EXPECT_TRUE(names.insert(spec.name).second) << spec.name << " twice";
    EXPECT_FALSE(spec.doc.empty()) << spec.name;
    EXPECT_TRUE(spec.result_type.empty() || kConceptTypes.count(spec.result_type)) << spec.name;
    if (spec.reuse_allowed) {
      EXPECT_FALSE(spec.result_type.empty()) << spec.name;
    }
    for (const auto& kw : spec.body.children) EXPECT_FALSE(kw.name.empty());
    Keyword body = spec.body;
    body.doc = "root";
    check_keyword(body, spec.name);
  }
}

TEST(Catalog, ListsTheCommandsOfTheDeckContract) {
  for (const char* name : {"DEBUT", "FIN", "LIRE_MAILLAGE", "DEFI_GROUP", "MODI_MAILLAGE", "AFFE_MODELE",
                           "DEFI_MATERIAU", "AFFE_MATERIAU", "AFFE_CHAR_MECA", "DEFI_CONTACT", "DEFI_LIST_REEL",
                           "DEFI_LIST_INST", "DEFI_FONCTION", "STAT_NON_LINE", "CALC_CHAMP", "TEST_RESU", "IMPR_RESU"})
    EXPECT_NE(find_command(name), nullptr) << name;
  EXPECT_EQ(find_command("AFFE_MODEL"), nullptr);
}

TEST(Catalog, CommandsWithoutRequiredKeywordsAcceptAnEmptyCall) {
  for (const char* name : {"DEBUT", "FIN"}) {
    KwNode node;
    EXPECT_NO_THROW(validate(*find_command(name), node)) << name;
  }
  KwNode node;
  EXPECT_THROW(validate(*find_command("STAT_NON_LINE"), node), DeckError);
}

TEST(Catalog, DefiContactBlocksFollowFormulation) {
  struct Modele : Concept {
    std::string type_name() const override { return "modele"; }
  };
  const CommandSpec& spec = *find_command("DEFI_CONTACT");
  auto zone = [](std::string algo) {
    KwNode z;
    z.simple["GROUP_MA_ESCL"] = {std::string("AB")};
    z.simple["GROUP_MA_MAIT"] = {std::string("EF")};
    if (!algo.empty()) z.simple["ALGO_CONT"] = {std::move(algo)};
    return z;
  };
  KwNode node;
  node.simple["MODELE"] = {ConceptPtr(std::make_shared<Modele>())};
  node.simple["FORMULATION"] = {std::string("CONTINUE")};
  KwNode z = zone("");
  z.simple["INTEGRATION"] = {std::string("SIMPSON")};
  z.simple["ORDRE_INT"] = {4LL};
  node.factors["ZONE"] = {z};
  validate(spec, node);
  Args args(node, spec.body);
  Args first = args.factor("ZONE");
  EXPECT_EQ(first.text("ALGO_CONT"), "STANDARD");
  EXPECT_DOUBLE_EQ(first.real("COEF_CONT"), 100.0);
  EXPECT_EQ(first.integer("ORDRE_INT"), 4);
  EXPECT_EQ(first.text("CONTACT_INIT"), "INTERPENETRE");
  EXPECT_EQ(first.path("ORDRE_INT"), "ZONE[1].ORDRE_INT");

  // CONTRAINTE belongs to the discrete formulation only.
  KwNode wrong;
  wrong.simple["MODELE"] = node.simple["MODELE"];
  wrong.simple["FORMULATION"] = {std::string("CONTINUE")};
  wrong.factors["ZONE"] = {zone("CONTRAINTE")};
  try {
    validate(spec, wrong);
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 85),
              "DEFI_CONTACT: ZONE[1].ALGO_CONT: expected one of 'STANDARD', 'PENALISATION', got 'CON");
  }
  // The discrete default zone needs E_N only with PENALISATION.
  KwNode discrete;
  discrete.simple["MODELE"] = node.simple["MODELE"];
  discrete.factors["ZONE"] = {zone("PENALISATION")};
  try {
    validate(spec, discrete);
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_STREQ(e.what(), "DEFI_CONTACT: ZONE[1].E_N: expected real > 0 (mandatory keyword), got nothing");
  }
}

TEST(Catalog, HelpAndMarkdownComeFromTheSpecs) {
  std::string md = catalog_markdown();
  EXPECT_NE(md.find("## STAT_NON_LINE"), std::string::npos);
  EXPECT_NE(md.find("| `CONVERGENCE/ITER_GLOB_MAXI` | integer >= 1 | optional | `10` |"), std::string::npos);
  EXPECT_NE(md.find("`ZONE/ORDRE_INT`"), std::string::npos);
  // Open bounds and refused values are shown from the same data the validator uses.
  EXPECT_NE(md.find("| `ELAS/NU` | real in (-1, 0.5) | required |"), std::string::npos);
  EXPECT_NE(md.find("| `ELAS/E` | real > 0 | required |"), std::string::npos);
  EXPECT_NE(md.find("'NEWTON' refused: the discrete formulation updates its contact statuses between Newton solves only"),
            std::string::npos);
  EXPECT_NE(command_help(*find_command("DEFI_MATERIAU")).find("E  [real > 0; required]"), std::string::npos);
  std::string help = command_help(*find_command("AFFE_MODELE"));
  EXPECT_NE(help.find("MODELISATION  [text in ('D_PLAN', 'C_PLAN', '3D', 'AXIS'); required]"), std::string::npos);
  EXPECT_NE(command_list().find("STAT_NON_LINE"), std::string::npos);
}
