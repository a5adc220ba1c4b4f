#pragma once
/// Explicit list of command handlers (no static-init self-registration).
#include <string>
#include <vector>

#include "catalog/args.hpp"
#include "commands/session.hpp"

namespace lunaster::cmd {

/// A command handler: validated keywords in, concept out (nullptr for procedures).
using Handler = catalog::ConceptPtr (*)(const catalog::Args& args, Session& session);

struct CommandEntry {
  const char* name;
  Handler handler;
};

/// Every handler, one line each in commands/register_all.cpp.
const std::vector<CommandEntry>& all_handlers();
/// Handler for a command name, or nullptr.
Handler find_handler(const std::string& name);

}  // namespace lunaster::cmd
