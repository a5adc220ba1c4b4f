#pragma once
/// Help and documentation derived from the catalogue (`lunaster help`,
/// `lunaster --dump-catalog md` -> docs/commands.md).
#include <string>

#include "catalog/spec.hpp"

namespace lunaster::catalog {

/// One line per command: name, result type and one-line doc.
std::string command_list();
/// Plain-text help of one command: every keyword with type, status, default, into, range and doc.
std::string command_help(const CommandSpec& spec);
/// The whole catalogue as Markdown.
std::string catalog_markdown();
/// "real", "integer >= 1", "text in ('A', 'B')", "maillage", with "list of" when several values.
std::string type_text(const Keyword& kw);
/// Bounds of a Real/Int keyword, shared by messages and docs: " in [-1, 0.5]",
/// " in (-1, 0.5)" (open), " > 0", " <= 99"; empty without bounds.
std::string bounds_text(const Keyword& kw);
/// Values refused with a reason: "; 'OUI' refused: axisymmetric models are not supported yet".
std::string refused_text(const Keyword& kw);
/// Human form of a rule: "exactly one of TOUT, GROUP_MA".
std::string rule_text(const Rule& rule);

}  // namespace lunaster::catalog
