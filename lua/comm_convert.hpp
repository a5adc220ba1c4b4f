#pragma once
/// code_aster .comm files (Python scripts in a declarative subset) rewritten as lunaster Lua
/// decks, token by token, keeping the layout line for line. What is not translated is
/// reported and commented out; check_comm also names what lunaster's catalogue does not know.
#include <string>
#include <string_view>
#include <vector>

namespace lunaster::lua {

/// One form of a .comm file that is not translated (or, for check_comm, not known to lunaster).
struct CommIssue {
  int line = 0;       ///< 1-based line of the .comm file
  std::string what;   ///< e.g. "'for' loop", "Python function call 'sqrt'", "unknown command POST_RELEVE_T", "STAT_NON_LINE: unknown keyword NEWTON/REAC_ITE (did you mean REAC_ITER?)"
  std::string hint;   ///< short advice: what to write instead
};

/// A .comm file as Lua. The Lua text has exactly the same number of lines as the .comm, and
/// line i of it holds .comm line i (so Lua's error lines are .comm lines when the chunk is named after the .comm).
struct CommConversion {
  std::string lua;
  std::vector<CommIssue> refused;  ///< untranslated forms in line order; their lines are commented out in `lua` with a marker
};

CommConversion convert_comm(std::string_view text);

/// What `lunaster convert --check` reports, in line order: the refused forms, every call of an upper-case
/// name that is not a catalogue command, and every keyword (at any factor depth, including inside _F
/// given as tuples/lists) that the command's catalogue spec does not declare (use catalog::find_command,
/// catalog::find_declared / spec children and catalog::closest_name for "did you mean").
std::vector<CommIssue> check_comm(std::string_view text);

}  // namespace lunaster::lua
