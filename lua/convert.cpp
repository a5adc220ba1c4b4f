/// Lua values <-> catalogue values, and the concept userdata.
#include <new>

#include "lua/bridge.hpp"

#include "commands/concepts.hpp"

namespace lunaster::lua {

using catalog::ConceptPtr;
using catalog::KwNode;
using catalog::Value;

namespace {

constexpr const char* kConceptTag = "__lunaster_concept";
constexpr int kMaxDepth = 8;

int concept_gc(lua_State* L) {
  auto* c = static_cast<ConceptPtr*>(lua_touserdata(L, 1));
  if (c) c->~ConceptPtr();
  return 0;
}

int concept_tostring(lua_State* L) {
  auto* c = static_cast<ConceptPtr*>(lua_touserdata(L, 1));
  std::string text = "<nil>";
  if (c && *c) text = "<" + (*c)->type_name() + ((*c)->user_name.empty() ? "" : " " + (*c)->user_name) + ">";
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

/// A function of the deck (a Python def converted, or written in Lua) given where the catalogue takes
/// a function (FORMULE's named values): called with numbers, it must return a number. It lives as long
/// as the deck's Lua state, which runs every command that may call it.
class LuaFunction : public cmd::RealFunction {
 public:
  LuaFunction(lua_State* L, int index) : L_(L) {
    lua_Debug ar;
    lua_pushvalue(L, index);
    lua_getinfo(L, ">S", &ar);
    where_ = std::string(ar.short_src) + ":" + std::to_string(ar.linedefined);
    lua_pushvalue(L, index);
    ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  std::vector<std::string> parameters() const override { return {}; }
  double evaluate(const std::vector<double>& values) const override {
    lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_);
    for (double v : values) lua_pushnumber(L_, v);
    if (lua_pcall(L_, static_cast<int>(values.size()), 1, 0) != LUA_OK) {
      std::string message = lua_type(L_, -1) == LUA_TSTRING ? lua_tostring(L_, -1) : "an error";
      lua_pop(L_, 1);
      throw DeckError("the deck's function defined at " + where_ + " failed: " + message);
    }
    int is_number = 0;
    const double x = lua_tonumberx(L_, -1, &is_number);
    const std::string type = luaL_typename(L_, -1);
    lua_pop(L_, 1);
    if (!is_number) throw DeckError("the deck's function defined at " + where_ + " returned a " + type + ", not a number");
    return x;
  }
  std::string type_name() const override { return "function"; }

 private:
  lua_State* L_;
  int ref_ = LUA_NOREF;
  std::string where_;
};

Value to_value(lua_State* L, int index, const std::string& path) {
  switch (lua_type(L, index)) {
    case LUA_TNUMBER:
      if (lua_isinteger(L, index)) return static_cast<long long>(lua_tointeger(L, index));
      return static_cast<double>(lua_tonumber(L, index));
    case LUA_TSTRING: {
      std::size_t len = 0;
      const char* s = lua_tolstring(L, index, &len);
      return std::string(s, len);
    }
    case LUA_TUSERDATA:
      if (auto* c = to_concept(L, index)) return *c;
      break;
    case LUA_TFUNCTION:
      return ConceptPtr(std::make_shared<LuaFunction>(L, lua_absindex(L, index)));
    default: break;
  }
  throw DeckError::at(path, "a real, an integer, a text or a concept", lua_type_text(L, index));
}

/// Number of entries of the table at `index` (all keys).
std::size_t n_entries(lua_State* L, int index) {
  std::size_t n = 0;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    ++n;
    lua_pop(L, 1);
  }
  return n;
}

KwNode node_at(lua_State* L, int index, const std::string& path, int depth, Value* reuse, bool* has_reuse);

/// Stores the value at `index` (keyword `name`) into `node`.
void add_entry(lua_State* L, int index, const std::string& name, const std::string& path, int depth, KwNode& node) {
  if (lua_type(L, index) != LUA_TTABLE) {
    node.simple[name] = {to_value(L, index, path)};
    return;
  }
  const std::size_t length = lua_rawlen(L, index);
  const std::size_t entries = n_entries(L, index);
  if (length == 0 && entries == 0) {  // {} or _F{}: the validator decides from the spec
    node.factors[name] = {KwNode{}};
    return;
  }
  if (length == 0) {  // one _F{...}
    node.factors[name] = {node_at(L, index, path, depth + 1, nullptr, nullptr)};
    return;
  }
  if (entries != length)
    throw DeckError::at(path, "a list of values or a list of _F{...}", "a table mixing a list and keywords");
  int n_tables = 0;
  for (std::size_t i = 1; i <= length; ++i) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(i));
    n_tables += lua_type(L, -1) == LUA_TTABLE;
    lua_pop(L, 1);
  }
  if (n_tables != 0 && n_tables != static_cast<int>(length))
    throw DeckError::at(path, "a list of values or a list of _F{...}", "a list mixing tables and values");
  for (std::size_t i = 1; i <= length; ++i) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(i));
    std::string item_path = path + "[" + std::to_string(i) + "]";
    if (n_tables) {
      node.factors[name].push_back(node_at(L, lua_gettop(L), item_path, depth + 1, nullptr, nullptr));
    } else {
      node.simple[name].push_back(to_value(L, -1, item_path));
    }
    lua_pop(L, 1);
  }
}

KwNode node_at(lua_State* L, int index, const std::string& path, int depth, Value* reuse, bool* has_reuse) {
  if (depth > kMaxDepth) throw DeckError::at(path, "keyword tables nested at most " + std::to_string(kMaxDepth) + " deep", "a deeper (or self-referencing) table");
  luaL_checkstack(L, 6, "keyword table");
  KwNode node;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) {
      std::string got = lua_type(L, -2) == LUA_TNUMBER ? "a value without keyword" : "a key that is " + lua_type_text(L, -2);
      lua_pop(L, 2);
      throw DeckError::at(path, "KEYWORD = value pairs", got);
    }
    std::string name = lua_tostring(L, -2);
    std::string child_path = path.empty() ? name : path + "." + name;
    if (reuse && name == "reuse") {
      *reuse = to_value(L, lua_gettop(L), child_path);
      *has_reuse = true;
    } else {
      add_entry(L, lua_gettop(L), name, child_path, depth, node);
    }
    lua_pop(L, 1);
  }
  return node;
}

/// __call of a function concept: its value at the numbers given.
int function_call(lua_State* L) {
  auto* c = static_cast<ConceptPtr*>(lua_touserdata(L, 1));
  auto f = c ? std::dynamic_pointer_cast<cmd::RealFunction>(*c) : nullptr;
  if (!f) return luaL_error(L, "not a function");
  std::vector<double> values;
  for (int i = 2; i <= lua_gettop(L); ++i) values.push_back(luaL_checknumber(L, i));
  std::string message;
  try {
    lua_pushnumber(L, f->evaluate(values));
    return 1;
  } catch (const std::exception& e) {
    message = e.what();
  }
  return luaL_error(L, "%s", message.c_str());
}

}  // namespace

std::string lua_type_text(lua_State* L, int index) {
  int type = lua_type(L, index);
  std::string name = lua_typename(L, type);
  if (type == LUA_TNIL) return "nil";
  return (name == "userdata" || name == "integer" ? "an " : "a ") + name;
}

void push_concept(lua_State* L, const ConceptPtr& c) {
  void* memory = lua_newuserdatauv(L, sizeof(ConceptPtr), 0);
  new (memory) ConceptPtr(c);
  const std::string type = c->type_name();
  if (luaL_newmetatable(L, type.c_str())) {  // sets __name = type
    lua_pushcfunction(L, concept_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, concept_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pushboolean(L, 1);
    lua_setfield(L, -2, kConceptTag);
    if (type == "table") add_table_access(L);
    if (std::dynamic_pointer_cast<cmd::RealFunction>(c)) {  // F(x), as code_aster's Python calls a function
      lua_pushcfunction(L, function_call);
      lua_setfield(L, -2, "__call");
    }
  }
  lua_setmetatable(L, -2);
}

ConceptPtr* to_concept(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TUSERDATA || !lua_getmetatable(L, index)) return nullptr;
  lua_pushstring(L, kConceptTag);
  lua_rawget(L, -2);
  bool ours = lua_toboolean(L, -1);
  lua_pop(L, 2);
  return ours ? static_cast<ConceptPtr*>(lua_touserdata(L, index)) : nullptr;
}

KwNode to_node(lua_State* L, int index, const std::string& path, Value* reuse, bool* has_reuse) {
  return node_at(L, lua_absindex(L, index), path, 0, reuse, has_reuse);
}

}  // namespace lunaster::lua
