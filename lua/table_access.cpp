/// Reading a table concept from a deck: TAB['NOM_PARA'][i] (code_aster's TAB['NOM_PARA', i]),
/// #TAB (number of rows) and #TAB['NOM_PARA'].
#include <new>
#include <string>

#include "commands/table.hpp"
#include "lua/bridge.hpp"

namespace lunaster::lua {

namespace {

constexpr const char* kColumnType = "lunaster.table_column";

/// A column of a table, as the deck holds it between TAB['DY'] and [i].
struct ColumnRef {
  std::shared_ptr<cmd::Table> table;
  int column = 0;
};

std::shared_ptr<cmd::Table> table_at(lua_State* L, int index) {
  auto* c = to_concept(L, index);
  return c ? std::dynamic_pointer_cast<cmd::Table>(*c) : nullptr;
}

/// Raises "deck.lua:LINE: message" (the line of the deck statement reading the table).
[[noreturn]] void raise(lua_State* L, const std::string& message) {
  luaL_where(L, 1);
  lua_pushlstring(L, message.data(), message.size());
  lua_concat(L, 2);
  lua_error(L);
  throw;  // not reached: lua_error does not return
}

int column_gc(lua_State* L) {
  static_cast<ColumnRef*>(lua_touserdata(L, 1))->~ColumnRef();
  return 0;
}

int column_len(lua_State* L) {
  auto* ref = static_cast<ColumnRef*>(luaL_checkudata(L, 1, kColumnType));
  lua_pushinteger(L, ref->table->n_rows());
  return 1;
}

int column_index(lua_State* L) {
  auto* ref = static_cast<ColumnRef*>(luaL_checkudata(L, 1, kColumnType));
  const cmd::Table& table = *ref->table;
  const auto& column = table.columns[static_cast<size_t>(ref->column)];
  const std::string where = table.label() + "['" + column.name + "']";
  if (!lua_isinteger(L, 2)) {
    const std::string got = lua_type(L, 2) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, 2)) + "'" : lua_type_text(L, 2);
    raise(L, where + ": expected a row number 1.." + std::to_string(table.n_rows()) + ", got " + got +
                 " (a cell is TAB['NOM_PARA'][i])");
  }
  const lua_Integer row = lua_tointeger(L, 2);
  if (row < 1 || row > table.n_rows())
    raise(L, where + ": row " + std::to_string(row) + " out of range (the table has " + std::to_string(table.n_rows()) +
                 " row(s): 1.." + std::to_string(table.n_rows()) + ")");
  const cmd::Cell& cell = column.cells[static_cast<size_t>(row - 1)];
  if (const auto* r = std::get_if<double>(&cell)) lua_pushnumber(L, *r);
  else if (const auto* i = std::get_if<long long>(&cell)) lua_pushinteger(L, *i);
  else if (const auto* k = std::get_if<std::string>(&cell)) lua_pushlstring(L, k->data(), k->size());
  else raise(L, where + "[" + std::to_string(row) + "]: the cell is empty (this row has no " + column.name + ")");
  return 1;
}

int table_index(lua_State* L) {
  auto table = table_at(L, 1);
  if (!table) return 0;
  if (lua_type(L, 2) != LUA_TSTRING)
    raise(L, table->label() + ": expected a parameter name (" + table->parameter_list() + "), got " +
                 lua_type_text(L, 2) + " (a cell is TAB['NOM_PARA'][i])");
  const std::string name = lua_tostring(L, 2);
  const int col = table->column_index(name);
  if (col < 0) raise(L, table->label() + ": no parameter '" + name + "'; its parameters: " + table->parameter_list());
  void* memory = lua_newuserdatauv(L, sizeof(ColumnRef), 0);
  new (memory) ColumnRef{table, col};
  if (luaL_newmetatable(L, kColumnType)) {
    lua_pushcfunction(L, column_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, column_index);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, column_len);
    lua_setfield(L, -2, "__len");
  }
  lua_setmetatable(L, -2);
  return 1;
}

int table_len(lua_State* L) {
  auto table = table_at(L, 1);
  lua_pushinteger(L, table ? table->n_rows() : 0);
  return 1;
}

}  // namespace

void add_table_access(lua_State* L) {
  lua_pushcfunction(L, table_index);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, table_len);
  lua_setfield(L, -2, "__len");
}

}  // namespace lunaster::lua
