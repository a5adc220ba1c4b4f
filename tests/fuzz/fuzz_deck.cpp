// libFuzzer harness: the deck front end. The input is run as a deck through the
// real Lua runner and the real keyword catalogue; every command gets a no-op
// handler returning a concept of the declared result type, so the target is the
// Lua bridge (table conversion, strict globals, sandbox) and the catalogue
// validation. A lunaster::Error is the expected outcome of a bad deck; crashes,
// sanitizer reports, hangs and runaway memory are bugs. Runaway decks (endless
// loops, huge strings) are stopped by an instruction budget and a memory cap.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "catalog/lookup.hpp"
#include "lua/runner.hpp"

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

namespace {

using namespace lunaster;

struct FuzzConcept : catalog::Concept {
  explicit FuzzConcept(std::string type) : type_(std::move(type)) {}
  std::string type_name() const override { return type_; }
  std::string type_;
};

catalog::ConceptPtr no_op_handler(const catalog::Args&, cmd::Session& session) {
  const catalog::CommandSpec* spec = catalog::find_command(session.current.command);
  if (!spec || spec->result_type.empty()) return nullptr;
  return std::make_shared<FuzzConcept>(spec->result_type);
}

constexpr int kInstructionBudget = 200000;  ///< in units of 1000 VM instructions
constexpr long long kMemoryCap = 64ll << 20;  ///< bytes the deck may allocate after start-up

struct Budget {
  long long used = 0;  ///< signed: blocks allocated before the cap was installed are freed too
  int ticks = 0;
  lua_Alloc base = nullptr;
  void* base_ud = nullptr;
};
Budget budget;

void* capped_alloc(void* ud, void* ptr, size_t old_size, size_t new_size) {
  auto* b = static_cast<Budget*>(ud);
  const long long old_bytes = ptr ? static_cast<long long>(old_size) : 0;
  const long long delta = static_cast<long long>(new_size) - old_bytes;
  if (delta > 0 && b->used + delta > kMemoryCap) return nullptr;  // Lua raises "not enough memory"
  void* out = b->base(b->base_ud, ptr, old_size, new_size);
  if (new_size == 0 || out) b->used += delta;
  return out;
}

void count_hook(lua_State* L, lua_Debug*) {
  if (++budget.ticks > kInstructionBudget / 1000) luaL_error(L, "fuzz: instruction budget exhausted");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string code(reinterpret_cast<const char*>(data), size);
  std::ostringstream sink;
  Log log(sink, 0);
  cmd::Session session(log);
  session.deck_path = "fuzz.lua";
  session.output_dir = "";
  try {
    lua::Runner runner(session, [](const std::string&) -> cmd::Handler { return no_op_handler; });
    lua_State* L = runner.state();
    budget = Budget{};
    budget.base = lua_getallocf(L, &budget.base_ud);
    lua_setallocf(L, capped_alloc, &budget);
    lua_sethook(L, count_hook, LUA_MASKCOUNT, 1000);
    runner.run_string(code, "fuzz.lua");
  } catch (const Error&) {
    // a bad deck: expected
  }
  return 0;
}
