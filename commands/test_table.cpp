// TEST_TABLE: checks one cell of a table, chosen by FILTRE, or a reduction of a column
// (TYPE_TEST), with the same OK/NOOK lines as TEST_RESU.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "commands/commands.hpp"
#include "commands/table.hpp"
#include "commands/test_report.hpp"

namespace lunaster::cmd {

namespace {

/// Column of a parameter; DeckError at `kw` naming the table's parameters.
int column_of(const Args& args, const std::string& kw, const Table& table, const std::string& name) {
  const int col = table.column_index(name);
  if (col < 0)
    throw args.error(kw, "a parameter of " + table.label() + " (" + table.parameter_list() + ")", "'" + name + "'");
  return col;
}

double as_real(const Cell& cell) {
  if (const auto* r = std::get_if<double>(&cell)) return *r;
  return static_cast<double>(std::get<long long>(cell));
}

bool compare(const std::string& crit, int sign) {
  if (crit == "EQ") return sign == 0;
  if (crit == "NE") return sign != 0;
  if (crit == "LT") return sign < 0;
  if (crit == "GT") return sign > 0;
  if (crit == "LE") return sign <= 0;
  return sign >= 0;  // GE
}

/// Sign of (cell - value) for a comparison filter; equality of reals within CRITERE/PRECISION.
int cell_sign(const Args& f, const Table::Column& column, const Cell& cell) {
  if (f.has("VALE_K")) {
    const std::string& text = std::get<std::string>(cell);
    return text < f.text("VALE_K") ? -1 : text > f.text("VALE_K") ? 1 : 0;
  }
  const double x = as_real(cell);
  const double v = f.has("VALE") ? f.real("VALE") : static_cast<double>(f.integer("VALE_I"));
  if (f.has("PRECISION") && column.type == 'R') {
    const double tol = f.text("CRITERE") == "RELATIF" ? f.real("PRECISION") * std::abs(v) : f.real("PRECISION");
    if (std::abs(x - v) <= tol) return 0;
  }
  return x < v ? -1 : x > v ? 1 : 0;
}

/// Rows left by one FILTRE occurrence.
std::vector<int> apply_filter(const Args& f, const Table& table, const std::vector<int>& rows) {
  const int col = column_of(f, "NOM_PARA", table, f.text("NOM_PARA"));
  const Table::Column& column = table.columns[static_cast<size_t>(col)];
  const std::string crit = f.text("CRIT_COMP");
  auto empty = [&](int r) { return std::holds_alternative<std::monostate>(column.cells[static_cast<size_t>(r)]); };
  std::vector<int> out;
  if (crit == "VIDE" || crit == "NON_VIDE") {
    for (int r : rows)
      if (empty(r) == (crit == "VIDE")) out.push_back(r);
    return out;
  }
  const bool text_column = column.type == 'K';
  const bool text_value = !(crit.rfind("MAXI", 0) == 0 || crit.rfind("MINI", 0) == 0) && f.has("VALE_K");
  if (crit.rfind("MAXI", 0) == 0 || crit.rfind("MINI", 0) == 0) {
    if (text_column) throw f.error("CRIT_COMP", "a numeric parameter for " + crit, "'" + column.name + "' holds texts");
  } else if (text_column != text_value) {
    throw f.error(text_column ? "VALE_K" : "VALE", std::string(text_column ? "VALE_K" : "VALE or VALE_I") + " for the " +
                  (text_column ? "text" : "numeric") + " parameter '" + column.name + "'",
                  text_value ? "VALE_K" : "a number");
  }
  if (crit.rfind("MAXI", 0) == 0 || crit.rfind("MINI", 0) == 0) {
    const bool abs = crit.size() > 4;
    const bool max = crit[1] == 'A';
    double best = 0.0;
    bool any = false;
    for (int r : rows) {
      if (empty(r)) continue;
      double x = as_real(column.cells[static_cast<size_t>(r)]);
      if (abs) x = std::abs(x);
      if (!any || (max ? x > best : x < best)) best = x;
      any = true;
    }
    for (int r : rows)
      if (!empty(r) && (abs ? std::abs(as_real(column.cells[static_cast<size_t>(r)])) : as_real(column.cells[static_cast<size_t>(r)])) == best)
        out.push_back(r);
    return out;
  }
  for (int r : rows)
    if (!empty(r) && compare(crit, cell_sign(f, column, column.cells[static_cast<size_t>(r)]))) out.push_back(r);
  return out;
}

std::string filter_text(const Args& f) {
  std::string out = f.text("NOM_PARA") + " " + f.text("CRIT_COMP");
  if (f.has("VALE")) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " %.6g", f.real("VALE"));
    out += buf;
  }
  if (f.has("VALE_I")) out += " " + std::to_string(f.integer("VALE_I"));
  if (f.has("VALE_K")) out += " '" + f.text("VALE_K") + "'";
  return out;
}

}  // namespace

ConceptPtr test_table(const Args& args, Session& session) {
  auto table = args.concept_as<Table>("TABLE");
  const std::string para = args.text("NOM_PARA");
  const int col = column_of(args, "NOM_PARA", *table, para);
  std::vector<int> rows(static_cast<size_t>(table->n_rows()));
  for (int r = 0; r < table->n_rows(); ++r) rows[static_cast<size_t>(r)] = r;
  std::string filters;
  for (const auto& f : args.factors("FILTRE")) {
    rows = apply_filter(f, *table, rows);
    filters += (filters.empty() ? "" : ", ") + filter_text(f);
  }
  const Table::Column& column = table->columns[static_cast<size_t>(col)];
  if (column.type == 'K') throw args.error("NOM_PARA", "a numeric parameter", "'" + para + "', a text parameter");
  std::vector<double> values;
  for (int r : rows)
    if (!std::holds_alternative<std::monostate>(column.cells[static_cast<size_t>(r)]))
      values.push_back(as_real(column.cells[static_cast<size_t>(r)]));
  std::string what = table->label() + "  " + para;
  if (!filters.empty()) what += "  [" + filters + "]";
  double value = 0.0;
  if (args.has("TYPE_TEST")) {
    const std::string type = args.text("TYPE_TEST");
    if (values.empty())
      throw args.error("FILTRE", "rows with a value of " + para + " to reduce by TYPE_TEST", "none left");
    if (type == "MIN") value = *std::min_element(values.begin(), values.end());
    else if (type == "MAX") value = *std::max_element(values.begin(), values.end());
    else for (double x : values) value += type == "SOMM_ABS" ? std::abs(x) : x;
    what = type + "  " + what;
  } else {
    if (rows.size() != 1)
      throw args.error("FILTRE", "filters leaving exactly one row of " + table->label(),
                       std::to_string(rows.size()) + " row(s) left" + (filters.empty() ? " (no FILTRE)" : " by " + filters),
                       {"add a FILTRE on a parameter that tells the rows apart (" + table->parameter_list() +
                        "), or reduce the column with TYPE_TEST"});
    if (values.empty()) throw args.error("NOM_PARA", "a filled cell", "the cell of '" + para + "' in the row left is empty");
    value = values.front();
  }
  if (args.has("LEGENDE")) what += "  [" + args.text("LEGENDE") + "]";
  report_checks(args, session, value, what, column.type == 'I');
  return nullptr;
}

}  // namespace lunaster::cmd
