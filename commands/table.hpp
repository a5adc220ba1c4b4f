#pragma once
/// The table concept (code_aster's table_sdaster): named columns (parameters) of reals,
/// integers or texts, filled row by row by POST_RELEVE_T, read by TEST_TABLE,
/// IMPR_TABLE and by decks as TAB['NOM_PARA'][i].
#include <string>
#include <variant>
#include <vector>

#include "catalog/concept.hpp"

namespace lunaster::cmd {

/// One cell: empty, real, integer or text.
using Cell = std::variant<std::monostate, double, long long, std::string>;

/// A table of `n_rows()` rows; a row need not fill every column (the rest stay empty).
struct Table : catalog::Concept {
  /// One parameter: its name and its cells, one per row.
  struct Column {
    std::string name;
    char type = 'R';  ///< 'R' real, 'I' integer, 'K' text (code_aster's column types)
    std::vector<Cell> cells;
  };
  std::vector<Column> columns;

  std::string type_name() const override { return "table"; }
  int n_rows() const { return n_rows_; }
  /// Column of a parameter, or -1.
  int column_index(const std::string& name) const;
  /// Appends a row; parameters the table lacks become new columns (empty in earlier rows).
  /// InternalError if a value's type differs from its column's.
  void add_row(const std::vector<std::pair<std::string, Cell>>& row);
  /// "INTITULE, NOEUD, DX" for messages.
  std::string parameter_list() const;
  /// Name of the table for messages: the deck variable, or "the table".
  std::string label() const { return user_name.empty() ? "the table" : "table " + user_name; }

 private:
  int n_rows_ = 0;
};

/// A cell written with the Fortran-like real format `format_r` ("E12.5": 12 wide, 5 decimals;
/// also F and G), integers and texts as they are, empty cells as "-".
std::string format_cell(const Cell& cell, const std::string& format_r);
/// True when `format_r` is an accepted Fortran-like real format (E, F or G, width.decimals).
bool valid_real_format(const std::string& format_r);

}  // namespace lunaster::cmd
