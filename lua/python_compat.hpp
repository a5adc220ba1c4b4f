#pragma once
/// `py`: the few Python built-ins and the `math` module that code_aster command files use, as a Lua
/// table every deck sees. `lunaster convert` writes `py.range(n)`, `py.fmt('G%d', i)`, `math.sqrt`
/// (after `local math = py.math`) ...; a Lua deck may use them too. Each behaves as Python's does
/// for the values decks give them (0-based ranges, `%` and `str.format` formatting, `str` of reals,
/// integer truncation, math domain errors).
struct lua_State;

namespace lunaster::lua {

/// The Lua source of the library (a chunk returning the `py` table).
const char* python_compat_source();

/// Runs the library and sets the global `py` (before strict globals are set up).
void open_python_compat(lua_State* L);

}  // namespace lunaster::lua
