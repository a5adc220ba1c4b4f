#include "lua/runner.hpp"

#include <ostream>

#include "catalog/args.hpp"
#include "catalog/lookup.hpp"
#include "lua/bridge.hpp"

namespace lunaster::lua {

namespace {

/// File and line of the Lua code calling the running C function. A command called
/// through a C function (`pcall(STAT_NON_LINE, {...})`) has that C function as its
/// direct caller: the deck line is the first Lua frame above it.
ErrorContext call_site(lua_State* L, const std::string& command) {
  ErrorContext where;
  where.command = command;
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) continue;  // C frame: no line
    const char* source = ar.source ? ar.source : "";
    where.file = (source[0] == '@' || source[0] == '=') ? std::string(source + 1) : std::string(ar.short_src);
    where.line = ar.currentline;
    break;
  }
  return where;
}

}  // namespace

Runner::Runner(cmd::Session& session, HandlerLookup lookup) : session_(session), lookup_(std::move(lookup)) {
  state_ = luaL_newstate();
  if (!state_) throw InternalError("cannot create a Lua state");
  setup_state(state_, *this);
}

Runner::~Runner() {
  if (state_) lua_close(state_);
}

int Runner::call_command(lua_State* L, const catalog::CommandSpec& spec) {
  pending_ = nullptr;
  pending_message_.clear();
  const ErrorContext where = call_site(L, spec.name);
  catalog::ConceptPtr result;
  bool failed = false;
  try {
    result = execute(L, spec, where);
  } catch (Error& e) {
    e.fill_context(where);
    pending_ = std::current_exception();
    pending_message_ = e.what();
    failed = true;
  } catch (const std::exception& e) {
    InternalError internal(std::string("unexpected exception: ") + e.what());
    internal.fill_context(where);
    pending_message_ = internal.what();
    pending_ = std::make_exception_ptr(internal);
    failed = true;
  }
  if (failed) {
    // No C++ exception crosses into Lua: the typed error is kept and re-raised by run_file.
    lua_pushlstring(L, pending_message_.data(), pending_message_.size());
    return lua_error(L);
  }
  if (!result) return 0;
  push_concept(L, result);
  return 1;
}

catalog::ConceptPtr Runner::execute(lua_State* L, const catalog::CommandSpec& spec, const ErrorContext& where) {
  const int n_args = lua_gettop(L);
  if (n_args > 1 || (n_args == 1 && !lua_istable(L, 1)))
    throw DeckError("expected " + spec.name + "{ KEYWORD = value, ... }, got " + std::to_string(n_args) +
                    " argument(s), the first being " + lua_type_text(L, 1));
  catalog::KwNode node;
  catalog::Value reuse;
  bool has_reuse = false;
  if (n_args == 1) node = to_node(L, 1, "", &reuse, &has_reuse);
  if (has_reuse) {
    if (!spec.reuse_allowed)
      throw DeckError::at("reuse", "no reuse (" + spec.name + " always creates a new concept)", catalog::describe(reuse));
    auto* c = std::get_if<catalog::ConceptPtr>(&reuse);
    if (!c || !*c || (*c)->type_name() != spec.result_type)
      throw DeckError::at("reuse", "a " + spec.result_type + " concept", catalog::describe(reuse));
  }
  catalog::validate(spec, node);
  session_.log().info(where.file + ":" + std::to_string(where.line) + ": " + spec.name + catalog::format_node(node));
  cmd::Handler handler = lookup_ ? lookup_(spec.name) : nullptr;
  if (!handler) throw InternalError("command " + spec.name + " has no handler");
  session_.current = where;
  const catalog::Args args(node, spec.body, {}, reads_);
  catalog::ConceptPtr result;
  try {
    result = handler(args, session_);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InternalError(std::string("unexpected exception: ") + e.what());
  } catch (...) {  // the handler never calls Lua, so this cannot swallow a Lua error
    throw InternalError("unknown exception");
  }
  if (spec.result_type.empty()) return nullptr;
  if (!result) throw InternalError("the handler returned no " + spec.result_type + " concept");
  if (result->type_name() != spec.result_type)
    throw InternalError("the handler returned a " + result->type_name() + " concept instead of a " + spec.result_type);
  return result;
}

void Runner::run_loaded(int load_status) {
  lua_State* L = state_;
  if (load_status != LUA_OK) {
    std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "cannot load the deck";
    lua_pop(L, 1);
    throw DeckError(message);
  }
  lua_getfield(L, LUA_REGISTRYINDEX, "lunaster.msgh");
  lua_insert(L, -2);
  const int handler_index = lua_gettop(L) - 1;
  traceback_.clear();
  const int status = lua_pcall(L, 0, 0, handler_index);
  if (status == LUA_OK) {
    lua_pop(L, 1);
    return;
  }
  std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "(error object is not a string)";
  lua_pop(L, 2);
  if (pending_ && message == pending_message_) {
    std::exception_ptr typed = pending_;
    pending_ = nullptr;
    std::rethrow_exception(typed);
  }
  pending_ = nullptr;
  throw DeckError(message);
}

void Runner::run_file(const std::filesystem::path& deck) {
  if (session_.deck_path.empty()) session_.deck_path = deck;
  deck_dir_ = deck.parent_path();
  if (!std::filesystem::is_regular_file(deck)) throw DeckError("cannot open deck '" + deck.string() + "'");
  run_loaded(luaL_loadfilex(state_, deck.string().c_str(), "t"));
}

void Runner::run_string(const std::string& code, const std::string& chunk_name) {
  if (deck_dir_.empty()) deck_dir_ = std::filesystem::path(chunk_name).parent_path();
  const std::string name = "@" + chunk_name;
  run_loaded(luaL_loadbufferx(state_, code.data(), code.size(), name.c_str(), "t"));
}

int run_deck(const std::filesystem::path& deck, cmd::Session& session, HandlerLookup lookup, std::ostream& err) {
  try {
    Runner runner(session, std::move(lookup));
    try {
      runner.run_file(deck);
    } catch (const InternalError& e) {
      err << "internal error: " << e.what() << "\n" << runner.last_traceback() << "\n";
      return static_cast<int>(ErrorKind::Internal);
    }
  } catch (const Error& e) {
    err << e.what() << "\n";
    return static_cast<int>(e.kind());
  } catch (const std::exception& e) {
    err << "internal error: " << e.what() << "\n";
    return static_cast<int>(ErrorKind::Internal);
  }
  for (const auto& test : session.tests)
    if (!test.ok) return 1;
  return 0;
}

}  // namespace lunaster::lua
