// The table concept: columns appear as rows bring them, missing cells stay empty, a column
// keeps one type, and cells are written with Fortran-like real formats.
#include <gtest/gtest.h>

#include "commands/table.hpp"
#include "engine/core/error.hpp"

using namespace lunaster;
using cmd::Cell;
using cmd::Table;

TEST(Table, RowsAddColumnsAndLeaveMissingCellsEmpty) {
  Table t;
  t.add_row({{"INTITULE", std::string("A")}, {"NUME_ORDRE", 1LL}, {"DX", 1.5}});
  t.add_row({{"INTITULE", std::string("B")}, {"DY", -2.0}});
  ASSERT_EQ(t.n_rows(), 2);
  EXPECT_EQ(t.parameter_list(), "INTITULE, NUME_ORDRE, DX, DY");
  const auto& dy = t.columns[static_cast<size_t>(t.column_index("DY"))];
  EXPECT_EQ(dy.type, 'R');
  EXPECT_TRUE(std::holds_alternative<std::monostate>(dy.cells[0]));
  EXPECT_EQ(std::get<double>(dy.cells[1]), -2.0);
  const auto& dx = t.columns[static_cast<size_t>(t.column_index("DX"))];
  EXPECT_EQ(std::get<double>(dx.cells[0]), 1.5);
  EXPECT_TRUE(std::holds_alternative<std::monostate>(dx.cells[1]));
  EXPECT_EQ(t.columns[1].type, 'I');
  EXPECT_EQ(t.column_index("DZ"), -1);
}

TEST(Table, AColumnKeepsItsType) {
  Table t;
  t.add_row({{"NOEUD", std::string("N1")}});
  EXPECT_THROW(t.add_row({{"NOEUD", 3.0}}), InternalError);
  EXPECT_EQ(t.n_rows(), 1);  // the refused row was not added
}

TEST(Table, CellsUseFortranLikeFormats) {
  EXPECT_EQ(cmd::format_cell(Cell{2.0e5}, "E12.5"), " 2.00000E+05");
  EXPECT_EQ(cmd::format_cell(Cell{-0.05}, "F8.3"), "  -0.050");
  EXPECT_EQ(cmd::format_cell(Cell{7LL}, "E12.5"), "7");
  EXPECT_EQ(cmd::format_cell(Cell{std::string("GH")}, "E12.5"), "GH");
  EXPECT_EQ(cmd::format_cell(Cell{}, "E12.5"), "-");
  EXPECT_TRUE(cmd::valid_real_format("G15.8"));
  EXPECT_FALSE(cmd::valid_real_format("%12.5e"));
  EXPECT_FALSE(cmd::valid_real_format("E12"));
}
