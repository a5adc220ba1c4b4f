#pragma once
/// Private to lua/: conversions between Lua values and catalogue values, the
/// concept userdata, and the sandbox setup. The only header including Lua.
#include <lua.hpp>

#include <string>

#include "catalog/args.hpp"

namespace lunaster::lua {

class Runner;

/// Pushes a concept as full userdata whose metatable `__name` is its type name.
void push_concept(lua_State* L, const catalog::ConceptPtr& c);
/// Adds __index (TAB['NOM_PARA'] -> a column, column[i] -> the cell) and __len (rows) to the
/// metatable at the top of the stack, for the table concept.
void add_table_access(lua_State* L);
/// The concept held by the userdata at `index`, or nullptr if it is not one of ours.
catalog::ConceptPtr* to_concept(lua_State* L, int index);
/// Converts the keyword table at `index` to a KwNode (DeckError on bad values).
/// At the top level, `reuse` is taken out into `*reuse` (if non-null).
catalog::KwNode to_node(lua_State* L, int index, const std::string& path, catalog::Value* reuse, bool* has_reuse);
/// "a boolean", "a function", ... for messages.
std::string lua_type_text(lua_State* L, int index);

/// Opens the allowed libraries (base, string, table, math, utf8), removes file
/// and bytecode access, installs text-only `load`, deck-relative `require`, `print`
/// to the session log, `_F`, the command trampolines and strict globals.
void setup_state(lua_State* L, Runner& runner);

}  // namespace lunaster::lua
