#include "commands/table.hpp"

#include <cstdio>
#include <regex>

#include "engine/core/error.hpp"

namespace lunaster::cmd {

namespace {

char type_of(const Cell& cell) {
  if (std::holds_alternative<double>(cell)) return 'R';
  if (std::holds_alternative<long long>(cell)) return 'I';
  return 'K';
}

const std::regex& real_format_pattern() {
  static const std::regex pattern("([EFG])([0-9]{1,2})\\.([0-9]{1,2})");
  return pattern;
}

}  // namespace

int Table::column_index(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i].name == name) return static_cast<int>(i);
  return -1;
}

void Table::add_row(const std::vector<std::pair<std::string, Cell>>& row) {
  for (const auto& [name, value] : row) {
    int col = column_index(name);
    if (col < 0) {
      columns.push_back({name, type_of(value), std::vector<Cell>(static_cast<size_t>(n_rows_))});
      col = static_cast<int>(columns.size()) - 1;
    }
    Column& column = columns[static_cast<size_t>(col)];
    if (std::holds_alternative<std::monostate>(value)) continue;
    if (type_of(value) != column.type)
      throw InternalError("table parameter " + name + " holds type " + std::string(1, column.type) + ", not " +
                          std::string(1, type_of(value)));
  }
  for (auto& column : columns) column.cells.emplace_back();
  for (const auto& [name, value] : row) columns[static_cast<size_t>(column_index(name))].cells.back() = value;
  ++n_rows_;
}

std::string Table::parameter_list() const {
  std::string out;
  for (const auto& c : columns) out += (out.empty() ? "" : ", ") + c.name;
  return out.empty() ? "none" : out;
}

bool valid_real_format(const std::string& format_r) { return std::regex_match(format_r, real_format_pattern()); }

std::string format_cell(const Cell& cell, const std::string& format_r) {
  if (std::holds_alternative<std::monostate>(cell)) return "-";
  if (const auto* text = std::get_if<std::string>(&cell)) return *text;
  if (const auto* integer = std::get_if<long long>(&cell)) return std::to_string(*integer);
  std::smatch m;
  if (!std::regex_match(format_r, m, real_format_pattern()))
    throw InternalError("real format '" + format_r + "' was not checked");
  const char conv = m[1].str()[0] == 'E' ? 'E' : m[1].str()[0] == 'F' ? 'f' : 'G';
  const std::string spec = "%" + m[2].str() + "." + m[3].str() + conv;
  char buf[128];
  std::snprintf(buf, sizeof buf, spec.c_str(), std::get<double>(cell));
  return buf;
}

}  // namespace lunaster::cmd
