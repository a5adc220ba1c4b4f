/// The sandboxed Lua environment of a deck: allowed libraries only, text-only
/// `load`, deck-relative `require`, `_F`, command trampolines, strict globals.
#include <cctype>
#include <filesystem>
#include <vector>

#include "lua/bridge.hpp"
#include "lua/python_compat.hpp"
#include "lua/runner.hpp"

namespace lunaster::lua {

namespace {

Runner* runner_of(lua_State* L, int upvalue) { return static_cast<Runner*>(lua_touserdata(L, lua_upvalueindex(upvalue))); }

int trampoline(lua_State* L) {
  Runner* runner = runner_of(L, 1);
  const auto* spec = static_cast<const catalog::CommandSpec*>(lua_touserdata(L, lua_upvalueindex(2)));
  return runner->call_command(L, *spec);
}

/// _F{...}: one occurrence of a factor keyword; the identity on a table.
int factor_identity(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_settop(L, 1);
  return 1;
}

/// load(chunk [, name [, mode [, env]]]) restricted to text chunks given as strings.
int safe_load(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING) return luaL_error(L, "load: only text chunks given as strings are allowed in decks");
  std::size_t len = 0;
  const char* code = lua_tolstring(L, 1, &len);
  const char* name = luaL_optstring(L, 2, "=(load)");
  int env = !lua_isnone(L, 4) ? 4 : 0;
  if (luaL_loadbufferx(L, code, len, name, "t") != LUA_OK) {
    luaL_pushfail(L);
    lua_insert(L, -2);
    return 2;
  }
  if (env) {
    lua_pushvalue(L, env);
    if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
  }
  return 1;
}

/// require(name): loads <deck dir>/<name with dots as slashes>.lua once, as text.
int deck_require(lua_State* L) {
  Runner* runner = runner_of(L, 1);
  const char* name = luaL_checkstring(L, 1);
  lua_getfield(L, LUA_REGISTRYINDEX, "lunaster.modules");
  lua_getfield(L, -1, name);
  if (!lua_isnil(L, -1)) return 1;
  lua_pop(L, 1);
  std::string relative = name;
  for (auto& ch : relative)
    if (ch == '.') ch = '/';
  std::string path = (runner->deck_dir() / (relative + ".lua")).string();
  if (!std::filesystem::exists(path)) {
    lua_pushfstring(L, "module '%s' not found (looked for %s)", name, path.c_str());
    path.clear();
    return lua_error(L);
  }
  if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK) return lua_error(L);
  lua_pushstring(L, name);
  lua_call(L, 1, 1);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_pushboolean(L, 1);
  }
  lua_pushvalue(L, -1);
  lua_setfield(L, -3, name);
  return 1;
}

/// print(...) to the session log (always shown).
int deck_print(lua_State* L) {
  Runner* runner = runner_of(L, 1);
  int n = lua_gettop(L);
  luaL_Buffer buffer;
  luaL_buffinit(L, &buffer);
  for (int i = 1; i <= n; ++i) {
    if (i > 1) luaL_addchar(&buffer, '\t');
    luaL_tolstring(L, i, nullptr);
    luaL_addvalue(&buffer);
  }
  luaL_pushresult(&buffer);
  runner->session().log().always(lua_tostring(L, -1));
  return 0;
}

/// Candidate names for "did you mean": globals (commands, libraries) and deck variables.
void collect_names(lua_State* L, int table, std::vector<std::string>& out) {
  lua_pushnil(L);
  while (lua_next(L, table) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) out.emplace_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
}

/// A code_aster command name: upper case, digits and underscores, with an underscore (MA, RESU are concepts).
bool looks_like_command(const std::string& name) {
  if (name.find('_') == std::string::npos || name.front() == '_') return false;
  for (char ch : name)
    if (!(std::isupper(static_cast<unsigned char>(ch)) || std::isdigit(static_cast<unsigned char>(ch)) || ch == '_'))
      return false;
  return true;
}

std::string command_names() {
  std::string out;
  for (const auto& spec : catalog::all_commands()) out += (out.empty() ? "" : ", ") + spec.name;
  return out;
}

/// __index of _G: deck variables live in upvalue 1; reading an unknown name is an error.
int strict_index(lua_State* L) {
  lua_pushvalue(L, 2);
  lua_rawget(L, lua_upvalueindex(1));  // value
  if (!lua_isnil(L, -1)) return 1;
  lua_pushvalue(L, 2);
  lua_rawget(L, lua_upvalueindex(2));  // declared (assigned nil)?
  if (lua_toboolean(L, -1)) {
    lua_pushnil(L);
    return 1;
  }
  lua_settop(L, 2);
  if (lua_type(L, 2) != LUA_TSTRING) return 0;
  luaL_where(L, 1);
  {
    std::vector<std::string> names;
    lua_pushvalue(L, lua_upvalueindex(1));
    collect_names(L, lua_gettop(L), names);
    collect_names(L, 1, names);
    lua_pop(L, 1);
    const std::string name = lua_tostring(L, 2);
    std::string message = "unknown name '" + name + "'";
    std::string suggestion = catalog::closest_name(name, names);
    if (!suggestion.empty()) message += " (did you mean " + suggestion + "?)";
    else if (looks_like_command(name)) message += ": not a lunaster command; the commands are " + command_names();
    lua_pushlstring(L, message.data(), message.size());
  }
  lua_concat(L, 2);
  return lua_error(L);
}

/// __newindex of _G: stores deck variables and names the concepts assigned to them.
int strict_newindex(lua_State* L) {
  if (auto* c = to_concept(L, 3); c && *c && lua_type(L, 2) == LUA_TSTRING) (*c)->user_name = lua_tostring(L, 2);
  lua_pushvalue(L, 2);
  lua_pushvalue(L, 3);
  lua_rawset(L, lua_upvalueindex(1));
  lua_pushvalue(L, 2);
  lua_pushboolean(L, 1);
  lua_rawset(L, lua_upvalueindex(2));
  return 0;
}

/// Message handler of the protected call: keeps the traceback, returns the message.
int message_handler(lua_State* L) {
  Runner* runner = runner_of(L, 1);
  const char* message = lua_tostring(L, 1);
  if (!message) {
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) {
      message = lua_tostring(L, -1);
    } else {
      message = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    }
  }
  luaL_traceback(L, L, nullptr, 1);
  runner->set_traceback(lua_tostring(L, -1));
  lua_pop(L, 1);
  lua_pushstring(L, message);
  return 1;
}

void open_libraries(lua_State* L) {
  const luaL_Reg libraries[] = {{LUA_GNAME, luaopen_base},        {LUA_STRLIBNAME, luaopen_string},
                                {LUA_TABLIBNAME, luaopen_table},  {LUA_MATHLIBNAME, luaopen_math},
                                {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const auto& lib : libraries) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  lua_pushglobaltable(L);
  for (const char* name : {"dofile", "loadfile"}) {
    lua_pushnil(L);
    lua_setfield(L, -2, name);
  }
  lua_getfield(L, -1, LUA_STRLIBNAME);
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");  // bytecode stays out of decks
  lua_pop(L, 2);
}

}  // namespace

void setup_state(lua_State* L, Runner& runner) {
  open_libraries(L);
  open_python_compat(L);
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, "lunaster.modules");
  lua_pushglobaltable(L);
  int globals = lua_gettop(L);
  lua_pushcfunction(L, safe_load);
  lua_setfield(L, globals, "load");
  lua_pushcfunction(L, factor_identity);
  lua_setfield(L, globals, "_F");
  const std::pair<const char*, lua_CFunction> with_runner[] = {{"require", deck_require}, {"print", deck_print}};
  for (const auto& [name, fn] : with_runner) {
    lua_pushlightuserdata(L, &runner);
    lua_pushcclosure(L, fn, 1);
    lua_setfield(L, globals, name);
  }
  for (const auto& spec : catalog::all_commands()) {
    lua_pushlightuserdata(L, &runner);
    lua_pushlightuserdata(L, const_cast<catalog::CommandSpec*>(&spec));
    lua_pushcclosure(L, trampoline, 2);
    lua_setfield(L, globals, spec.name.c_str());
  }
  // Strict globals: deck variables live in a side table so that every assignment reaches __newindex.
  lua_newtable(L);  // metatable
  lua_newtable(L);  // variables
  lua_newtable(L);  // declared names
  lua_pushvalue(L, -2);
  lua_pushvalue(L, -2);
  lua_pushcclosure(L, strict_index, 2);
  lua_setfield(L, -4, "__index");
  lua_pushcclosure(L, strict_newindex, 2);
  lua_setfield(L, -2, "__newindex");
  lua_setmetatable(L, globals);
  lua_pushlightuserdata(L, &runner);
  lua_pushcclosure(L, message_handler, 1);
  lua_setfield(L, LUA_REGISTRYINDEX, "lunaster.msgh");
  lua_pop(L, 1);
}

}  // namespace lunaster::lua
