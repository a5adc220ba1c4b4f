#include <gtest/gtest.h>

#include "catalog/args.hpp"

using namespace lunaster;
using namespace lunaster::catalog;

namespace {
Keyword body() {
  return factor("CMD", {real("E"), text("G").many(), factor("EXCIT", {real("F")}).occurs(0, -1),
                        factor("NEWTON", {integer("N")})});
}
}  // namespace

TEST(Args, UndeclaredKeywordIsInternalError) {
  KwNode node;
  Keyword spec = body();
  Args args(node, spec);
  EXPECT_THROW(args.has("NOPE"), InternalError);
  EXPECT_THROW(args.real("NOPE"), InternalError);
  EXPECT_FALSE(args.declares("NOPE"));
  EXPECT_TRUE(args.declares("E"));
}

TEST(Args, AbsentScalarIsInternalErrorAbsentListIsEmpty) {
  KwNode node;
  Keyword spec = body();
  Args args(node, spec);
  EXPECT_FALSE(args.has("E"));
  EXPECT_THROW(args.real("E"), InternalError);
  EXPECT_TRUE(args.texts("G").empty());
  EXPECT_EQ(args.count("EXCIT"), 0);
}

TEST(Args, PathsAreOneBasedForRepeatableFactors) {
  KwNode node;
  KwNode a, b;
  a.simple["F"] = {1.0};
  b.simple["F"] = {2.0};
  node.factors["EXCIT"] = {a, b};
  node.factors["NEWTON"] = {KwNode{}};
  Keyword spec = body();
  Args args(node, spec);
  auto excit = args.factors("EXCIT");
  ASSERT_EQ(excit.size(), 2u);
  EXPECT_DOUBLE_EQ(excit[1].real("F"), 2.0);
  EXPECT_EQ(excit[1].path("F"), "EXCIT[2].F");
  EXPECT_EQ(args.factor("NEWTON").path("N"), "NEWTON.N");
  DeckError err = excit[1].error("F", "a positive real", "2");
  EXPECT_STREQ(err.what(), "EXCIT[2].F: expected a positive real, got 2");
  EXPECT_THROW(args.factor("EXCIT", 2), InternalError);
}

TEST(Args, ReadsListsAndTexts) {
  KwNode node;
  node.simple["G"] = {std::string("A"), std::string("B")};
  Keyword spec = body();
  Args args(node, spec);
  EXPECT_EQ(args.texts("G"), (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(args.text("G"), "A");
}

TEST(Args, FormatNodeIsCompact) {
  KwNode node;
  node.simple["E"] = {2e6};
  node.simple["G"] = {std::string("A"), std::string("B")};
  KwNode occ;
  occ.simple["F"] = {1LL};
  node.factors["EXCIT"] = {occ};
  EXPECT_EQ(format_node(node), "{ E=2e+06, G={'A', 'B'}, EXCIT=_F{ F=1 } }");
}
