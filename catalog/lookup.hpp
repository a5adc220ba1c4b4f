#pragma once
/// Keyword lookup shared by the validator and Args: which keywords of a
/// factor-like spec are active for a given node (children plus the keywords of
/// blocks whose condition holds), and small value helpers.
#include <string>
#include <vector>

#include "catalog/args.hpp"

namespace lunaster::catalog {

/// Blocks of `spec` whose condition holds for `node`; a block may depend on a
/// keyword of another active block (evaluated to a fixed point). Absent
/// condition keywords are read through their default.
std::vector<const Block*> active_blocks(const Keyword& spec, const KwNode& node);
/// Children of `spec` followed by the keywords of its active blocks.
std::vector<const Keyword*> active_keywords(const Keyword& spec, const KwNode& node);
/// An active keyword named `name`, or nullptr.
const Keyword* find_active(const Keyword& spec, const KwNode& node, const std::string& name);
/// A keyword named `name` declared anywhere in `spec` (children or any block), or nullptr.
const Keyword* find_declared(const Keyword& spec, const std::string& name);
/// The form of spec.other_keywords that `value` takes (a named value of FORMULE), or nullptr.
const Keyword* find_other_form(const Keyword& spec, const Value& value);
/// Path of a child keyword: "A.B" (or "B" at the root).
std::string join_path(const std::string& prefix, const std::string& name);
/// Path of occurrence `index` (0-based) of factor `kw`: "EXCIT[2]" if it may repeat, else "CONVERGENCE".
std::string occurrence_path(const std::string& prefix, const Keyword& kw, std::size_t index);
/// A value as shown in messages: 1e-06, 3, 'D_PLAN', modele MO.
std::string describe(const Value& v);
/// A catalogue scalar as shown in messages and docs: 1e-06, 3, 'D_PLAN'.
std::string describe(const Scalar& s);
/// True if a deck value equals a catalogue scalar (numbers compare numerically).
bool equals(const Value& v, const Scalar& s);

}  // namespace lunaster::catalog
