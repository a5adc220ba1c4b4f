// Commands on a mesh in parts, in one process: what require_somewhere records and what
// agree_over_ranks decides (commands/parts.hpp). Several ranks: mpi.parts_suite.
#include <gtest/gtest.h>

#include <stdexcept>

#include "commands/parts.hpp"

namespace lunaster::cmd {
namespace {

struct PartsTest : ::testing::Test {
  void SetUp() override {
    forget_requirements();
    set_parts_in_run(false);
  }
  void TearDown() override { SetUp(); }
};

TEST_F(PartsTest, AWholeMeshThrowsAtOnce) {
  engine::Mesh whole;
  EXPECT_NO_THROW(require_somewhere(whole, true, DeckError("unused")));
  EXPECT_THROW(require_somewhere(whole, false, DeckError("no such node")), DeckError);
}

TEST_F(PartsTest, APartDecidesWhenTheRanksAgree) {
  set_parts_in_run(true);
  engine::Mesh part;
  part.is_part = true;
  require_somewhere(part, true, DeckError("first"));
  EXPECT_NO_THROW(require_somewhere(part, false, DeckError("second: held by no rank")));
  require_somewhere(part, false, DeckError("third"));
  try {
    agree_over_ranks(nullptr);
    FAIL() << "a requirement held by no rank must stop the command";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.message(), "second: held by no rank");  // the first one that failed, in order
  }
  // Decided once: the next agreement starts afresh.
  EXPECT_NO_THROW(agree_over_ranks(nullptr));
  require_somewhere(part, true, DeckError("held"));
  EXPECT_NO_THROW(agree_over_ranks(nullptr));
}

TEST_F(PartsTest, AFailureKeepsItsTypeAndIsAgreedOnOnce) {
  set_parts_in_run(true);
  const auto failure = std::make_exception_ptr(SolveError("singular"));
  EXPECT_THROW(agree_over_ranks(failure), SolveError);
  // The error an agreement threw reaches the end of the command: it is not agreed on again
  // (the ranks would not meet there), only rethrown.
  EXPECT_THROW(agree_over_ranks(failure), SolveError);
  forget_requirements();
  EXPECT_NO_THROW(agree_over_ranks(nullptr));
}

TEST_F(PartsTest, ARequirementHeldByNoRankComesBeforeAFailureItCaused) {
  set_parts_in_run(true);
  engine::Mesh part;
  part.is_part = true;
  require_somewhere(part, false, DeckError("no node N99"));
  EXPECT_THROW(
      {
        try {
          agree_over_ranks(std::make_exception_ptr(DeckError("a single node expected, got 0")));
        } catch (const DeckError& e) {
          EXPECT_EQ(e.message(), "no node N99");
          throw;
        }
      },
      DeckError);
}

TEST_F(PartsTest, WithoutAMeshInPartsNothingIsRecorded) {
  engine::Mesh whole;
  EXPECT_THROW(agree_over_ranks(std::make_exception_ptr(std::runtime_error("x"))), std::runtime_error);
  EXPECT_NO_THROW(agree_over_ranks(nullptr));
  EXPECT_FALSE(parts_in_run());
}

TEST_F(PartsTest, OnlyTheCommandsWrittenForPartsTakeThem) {
  EXPECT_TRUE(takes_parts("STAT_NON_LINE"));
  EXPECT_TRUE(takes_parts("IMPR_RESU"));
  EXPECT_TRUE(takes_parts("POST_RELEVE_T"));
  EXPECT_TRUE(takes_parts("DEFI_CONTACT"));
  EXPECT_TRUE(takes_parts("DEFI_CONT"));
  EXPECT_TRUE(takes_parts("IMPR_MESURE"));
  EXPECT_FALSE(takes_parts("TEST_TABLE"));  // takes a table, the same on every rank: never a part
  EXPECT_NE(commands_taking_parts().find("CALC_CHAMP"), std::string::npos);
}

}  // namespace
}  // namespace lunaster::cmd
