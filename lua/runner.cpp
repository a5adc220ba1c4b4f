#include "lua/runner.hpp"

#include <fstream>
#include <new>
#include <optional>
#include <ostream>
#include <sstream>

#include "catalog/args.hpp"
#include "catalog/lookup.hpp"
#include "commands/parts.hpp"
#include "lua/bridge.hpp"
#include "lua/comm_convert.hpp"
#include "lua/export_file.hpp"

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

Runner::Runner(cmd::Session& session, HandlerLookup lookup, BudgetGuard* guard)
    : session_(session), lookup_(std::move(lookup)), guard_(guard) {
  cmd::set_parts_in_run(false);  // a deck's commands agree over the ranks once it reads a mesh in parts
  state_ = luaL_newstate();
  if (!state_) throw InternalError("cannot create a Lua state");
  setup_state(state_, *this);
  if (guard_) guard_->install(state_);
}

Runner::~Runner() {
  if (guard_ && state_) guard_->uninstall(state_);
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

namespace {

/// DeckError at the first concept of `node` on a mesh in parts: `command` does not take one.
void refuse_parts(const std::string& command, const catalog::KwNode& node, const std::string& path) {
  for (const auto& [kw, values] : node.simple)
    for (const auto& v : values)
      if (const auto* c = std::get_if<catalog::ConceptPtr>(&v); c && *c && (*c)->in_parts())
        throw DeckError::at(path + kw, "a concept on a whole mesh (" + command + " does not take a mesh in parts yet; "
                                       "the commands that do: " + cmd::commands_taking_parts() + ")",
                            "'" + (*c)->user_name + "', on a mesh read with PARTITIONNEUR",
                            {"read the mesh without PARTITIONNEUR for this deck"});
  for (const auto& [kw, occurrences] : node.factors)
    for (size_t i = 0; i < occurrences.size(); ++i)
      refuse_parts(command, occurrences[i],
                   path + kw + (occurrences.size() > 1 ? "[" + std::to_string(i + 1) + "]" : "") + ".");
}

}  // namespace

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
  // A hard stop of the budget names the command that was running.
  struct Running {
    BudgetGuard* guard;
    ~Running() {
      if (guard) guard->set_running("");
    }
  } running{guard_};
  if (guard_) guard_->set_running(where.file + ":" + std::to_string(where.line) + ": " + spec.name);
  // With a mesh in parts the ranks agree at the end of every command: one rank's failure (or a
  // name no rank's part holds) stops every rank alike, never one alone (commands/parts.hpp).
  cmd::forget_requirements();
  std::exception_ptr failure;
  try {
    if (cmd::parts_in_run() && !cmd::takes_parts(spec.name)) refuse_parts(spec.name, node, "");
    result = handler(args, session_);
  } catch (const Error&) {
    failure = std::current_exception();
  } catch (const std::bad_alloc&) {
    failure = std::make_exception_ptr(
        guard_ && guard_->budget().megabytes
            ? Error(ErrorKind::OutOfMemory, "out of memory (" + guard_->memory_message() + ")")
            : Error(ErrorKind::OutOfMemory, "out of memory: the machine refused an allocation"));
  } catch (const std::exception& e) {
    failure = std::make_exception_ptr(InternalError(std::string("unexpected exception: ") + e.what()));
  } catch (...) {  // the handler never calls Lua, so this cannot swallow a Lua error
    failure = std::make_exception_ptr(InternalError("unknown exception"));
  }
  cmd::agree_over_ranks(failure);
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
  if (guard_) guard_->set_protected(true);
  const int status = lua_pcall(L, 0, 0, handler_index);
  if (guard_) guard_->set_protected(false);
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
  // Over budget, whatever error the deck's code ended with: the budget is why it stopped.
  const std::string deck = session_.deck_path.string();
  if (guard_ && guard_->memory_exceeded()) {
    if (status == LUA_ERRMEM)
      throw Error(ErrorKind::OutOfMemory, deck + ": " + guard_->memory_message() + " by the deck's Lua data");
    throw Error(ErrorKind::OutOfMemory, message);
  }
  if (status == LUA_ERRMEM) throw Error(ErrorKind::OutOfMemory, deck + ": out of memory in the deck's Lua code");
  if (guard_ && guard_->time_up()) throw Error(ErrorKind::TimeLimit, message);
  throw DeckError(message);
}

void Runner::run_file(const std::filesystem::path& deck) {
  if (session_.deck_path.empty()) session_.deck_path = deck;
  deck_dir_ = deck.parent_path();
  if (!std::filesystem::is_regular_file(deck)) throw DeckError("cannot open deck '" + deck.string() + "'");
  if (is_comm_file(deck)) return run_comm(deck);
  run_loaded(luaL_loadfilex(state_, deck.string().c_str(), "t"));
}

void Runner::run_comm(const std::filesystem::path& comm) {
  std::ifstream in(comm, std::ios::binary);
  if (!in) throw DeckError("cannot open command file '" + comm.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  const CommConversion converted = convert_comm(text.str());
  if (!converted.refused.empty()) {
    // Nothing runs from a file that cannot be converted whole: the first form to finish stops it.
    const CommIssue& first = converted.refused.front();
    std::vector<std::string> hints;
    if (!first.hint.empty()) hints.push_back(first.hint);
    if (converted.refused.size() > 1)
      hints.push_back(std::to_string(converted.refused.size() - 1) + " more form(s) to finish by hand: `lunaster convert --check " +
                      comm.string() + "` lists them all");
    DeckError error(first.what + " is not part of the command language lunaster runs", hints);
    ErrorContext where;
    where.file = comm.string();
    where.line = first.line;
    error.fill_context(where);
    throw error;
  }
  session_.code_aster_vale_calc = true;
  // The Lua text keeps the .comm's lines: Lua's messages name the .comm file and line.
  run_string(converted.lua, comm.string());
}

void Runner::run_string(const std::string& code, const std::string& chunk_name) {
  if (deck_dir_.empty()) deck_dir_ = std::filesystem::path(chunk_name).parent_path();
  const std::string name = "@" + chunk_name;
  run_loaded(luaL_loadbufferx(state_, code.data(), code.size(), name.c_str(), "t"));
}

namespace {

int run_in(const std::filesystem::path& deck, cmd::Session& session, HandlerLookup lookup, std::ostream& err,
           BudgetGuard* guard) {
  try {
    Runner runner(session, std::move(lookup), guard);
    try {
      runner.run_file(deck);
    } catch (const InternalError& e) {
      err << "internal error: " << e.what() << "\n" << runner.last_traceback() << "\n";
      return static_cast<int>(ErrorKind::Internal);
    }
  } catch (const Error& e) {
    err << e.what() << "\n";
    const auto* solve = dynamic_cast<const SolveError*>(&e);
    if (solve && solve->out_of_memory()) return static_cast<int>(ErrorKind::OutOfMemory);
    return static_cast<int>(e.kind());
  } catch (const std::bad_alloc&) {
    err << deck.string() << ": out of memory: the machine refused an allocation\n";
    return static_cast<int>(ErrorKind::OutOfMemory);
  } catch (const std::exception& e) {
    err << "internal error: " << e.what() << "\n";
    return static_cast<int>(ErrorKind::Internal);
  }
  for (const auto& test : session.tests)
    if (!test.ok) return 1;
  return 0;
}

}  // namespace

bool is_comm_file(const std::filesystem::path& deck) { return deck.extension() == ".comm"; }
bool is_export_file(const std::filesystem::path& deck) { return deck.extension() == ".export"; }

void apply_export(const ExportFile& study, cmd::Session& session) {
  session.export_path = study.file;
  session.deck_path = study.comm;
  for (const auto& [unit, f] : study.data) session.data_units[unit] = {f.type, f.path};
  for (const auto& [unit, f] : study.results) session.result_units[unit] = {f.type, f.path};
  for (const auto& f : study.skipped)
    session.log().info(study.file.string() + ": file type '" + f.type + "' (line " + std::to_string(f.line) +
                       ", " + f.path.filename().string() + ") is not read by the study: skipped");
  if (!study.ignored.empty()) {
    std::string names;
    for (const auto& name : study.ignored) names += (names.empty() ? "" : ", ") + name;
    session.log().debug(study.file.string() + ": parameters with no effect on a lunaster run: " + names);
  }
}

int run_deck(const std::filesystem::path& given, cmd::Session& session, HandlerLookup lookup, std::ostream& err,
             const Budget& overrides, const ExportFile* read, std::chrono::steady_clock::time_point start) {
  Budget budget;
  std::filesystem::path deck = given;
  try {
    if (is_export_file(given)) {
      std::optional<ExportFile> own;
      const ExportFile& study = read ? *read : own.emplace(read_export(given));
      apply_export(study, session);
      deck = study.comm;
      budget = override_budget(study.budget, overrides);
    } else if (is_comm_file(given)) {
      budget = overrides;  // a .comm has no budget header: the .export or the command line gives it
    } else {
      budget = override_budget(read_budget_header(deck), overrides);
    }
  } catch (const Error& e) {
    err << e.what() << "\n";
    return static_cast<int>(e.kind());
  }
  if (!budget.seconds && !budget.megabytes) return run_in(deck, session, std::move(lookup), err, nullptr);
  BudgetGuard guard(budget, deck.string(), start);
  int code = run_in(deck, session, std::move(lookup), err, &guard);
  guard.stop();
  const int time_limit = static_cast<int>(ErrorKind::TimeLimit);
  const int out_of_memory = static_cast<int>(ErrorKind::OutOfMemory);
  if (code == time_limit || code == out_of_memory) return code;
  // The deck got past its budget and still ended (it caught the error, or its last command
  // finished within the grace): it is over budget all the same.
  if (guard.memory_exceeded()) {
    err << deck.string() << ": " << guard.memory_message() << "\n";
    return out_of_memory;
  }
  if (guard.time_up()) {
    err << deck.string() << ": " << guard.time_message() << "\n";
    return time_limit;
  }
  return code;
}

}  // namespace lunaster::lua
