#pragma once
/// The keyword catalogue as data. Each command is declared once as a
/// CommandSpec; validation, defaults, error messages, `lunaster help` and
/// docs/commands.md are all derived from it.
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace lunaster::catalog {

/// Type of a simple keyword's values. Concept keywords list accepted concept type names.
enum class ValueType { Real, Int, Text, Concept };
/// 'o' (required), 'f' (optional), 'c' (accepted for old decks, not documented as preferred).
enum class Status { Required, Optional, Legacy };

/// A default or allowed value: real, integer or text.
using Scalar = std::variant<double, long long, std::string>;

struct Rule {
  enum class Kind {
    ExactlyOne,      ///< UN_PARMI
    AtLeastOne,      ///< AU_MOINS_UN
    AtMostOne,       ///< EXCLUS
    Together,        ///< ENSEMBLE: all or none
    PresentAbsent,   ///< if names[0] present, none of the others
    PresentPresent,  ///< if names[0] present, all of the others
  };
  Kind kind;
  std::vector<std::string> names;
};

struct Keyword;

/// Conditional keywords (BLOC): active when `when_keyword` has one of
/// `equals` (or, with `equals` empty, when `when_keyword` is present).
// Defined before Keyword (which holds a vector of blocks and copies itself in its
// inline members): clang instantiates those copies where they are written.
struct Block {
  std::string when_keyword;
  std::vector<Scalar> equals;
  std::vector<Keyword> keywords;
  std::vector<Rule> rules;
};

/// A simple keyword (SIMP) or a factor keyword (FACT, with children).
struct Keyword {
  std::string name;
  bool is_factor = false;
  Status status = Status::Optional;
  std::string doc;
  // ---- simple keywords ----
  ValueType type = ValueType::Text;
  std::vector<std::string> concept_types;  ///< for ValueType::Concept
  std::optional<Scalar> default_value;
  std::vector<Scalar> into;                ///< allowed values (empty: any)
  std::optional<double> val_min, val_max;  ///< bounds for Real/Int, inclusive unless marked open below
  bool min_open = false, max_open = false; ///< open (exclusive) bounds: E > 0, -1 < NU < 0.5
  /// Values of the type that are recognised but refused, each with the reason shown in the
  /// error (e.g. ALGO_RESO_CONT = 'NEWTON' with the discrete formulation).
  std::vector<std::pair<Scalar, std::string>> refused;
  int min_values = 1, max_values = 1;      ///< number of values; max -1 = unbounded
  // ---- factor keywords ----
  int min_occurs = 0, max_occurs = 1;      ///< occurrences; max -1 = unbounded
  bool present_by_default = false;         ///< FACT statut='d': filled with defaults when absent
  std::vector<Keyword> children;
  std::vector<Rule> rules;
  std::vector<Block> blocks;
  /// A simple keyword that code_aster also takes as a factor occurrence (DEBUT's CODE='OUI'
  /// and older CODE=_F(NIV_PUB_WEB=...)): the children of that form (empty: simple only).
  std::vector<Keyword> factor_form;
  /// Names the spec does not declare, each a simple keyword taking one of these forms (FORMULE's
  /// named values: a real or a function); empty: an undeclared name is an unknown keyword.
  std::vector<Keyword> other_keywords;

  // ---- fluent construction (each returns a modified copy) ----
  Keyword required() const { Keyword k = *this; k.status = Status::Required; if (k.is_factor && k.min_occurs < 1) k.min_occurs = 1; return k; }
  Keyword legacy() const { Keyword k = *this; k.status = Status::Legacy; return k; }
  /// Also accepted as one factor occurrence with these children (see factor_form).
  Keyword or_factor(std::vector<Keyword> children) const { Keyword k = *this; k.factor_form = std::move(children); return k; }
  Keyword def(Scalar v) const { Keyword k = *this; k.default_value = std::move(v); return k; }
  Keyword into_values(std::vector<Scalar> v) const { Keyword k = *this; k.into = std::move(v); return k; }
  /// Inclusive bounds lo <= x <= hi (either may be absent).
  Keyword range(std::optional<double> lo, std::optional<double> hi) const { Keyword k = *this; k.val_min = lo; k.val_max = hi; k.min_open = k.max_open = false; return k; }
  /// Open lower bound x > lo (the upper bound is kept).
  Keyword above(double lo) const { Keyword k = *this; k.val_min = lo; k.min_open = true; return k; }
  /// Open upper bound x < hi (the lower bound is kept).
  Keyword below(double hi) const { Keyword k = *this; k.val_max = hi; k.max_open = true; return k; }
  /// A value refused with a reason (not in `into`; the error names the reason).
  Keyword refuse(Scalar v, std::string reason) const { Keyword k = *this; k.refused.emplace_back(std::move(v), std::move(reason)); return k; }
  Keyword count(int lo, int hi) const { Keyword k = *this; k.min_values = lo; k.max_values = hi; return k; }
  Keyword many() const { return count(1, -1); }
  Keyword occurs(int lo, int hi) const { Keyword k = *this; k.min_occurs = lo; k.max_occurs = hi; return k; }
  Keyword by_default() const { Keyword k = *this; k.present_by_default = true; return k; }
  Keyword with_rules(std::vector<Rule> r) const { Keyword k = *this; k.rules = std::move(r); return k; }
  Keyword with_blocks(std::vector<Block> b) const;
  Keyword help(std::string text) const { Keyword k = *this; k.doc = std::move(text); return k; }
  /// Any other name is a simple keyword of one of these forms (their `name` is shown in the help).
  Keyword others(std::vector<Keyword> forms) const { Keyword k = *this; k.other_keywords = std::move(forms); return k; }
};


inline Keyword Keyword::with_blocks(std::vector<Block> b) const { Keyword k = *this; k.blocks = std::move(b); return k; }

// ---- constructors for the catalogue files ----
Keyword real(std::string name, std::string doc = {});
Keyword integer(std::string name, std::string doc = {});
Keyword text(std::string name, std::string doc = {});
Keyword concept_kw(std::string name, std::vector<std::string> types, std::string doc = {});
Keyword factor(std::string name, std::vector<Keyword> children, std::string doc = {});
Rule exactly_one(std::vector<std::string> names);
Rule at_least_one(std::vector<std::string> names);
Rule at_most_one(std::vector<std::string> names);
Rule together(std::vector<std::string> names);
Rule present_absent(std::vector<std::string> names);
Rule present_present(std::vector<std::string> names);

/// One command.
struct CommandSpec {
  std::string name;         ///< "STAT_NON_LINE"
  std::string result_type;  ///< concept type returned, empty if none
  std::string doc;          ///< one line
  bool reuse_allowed = false;
  Keyword body;             ///< a factor-like root holding keywords, rules and blocks
};

/// Every command of the catalogue, in documentation order.
const std::vector<CommandSpec>& all_commands();
/// Lookup by name; nullptr if unknown.
const CommandSpec* find_command(const std::string& name);

}  // namespace lunaster::catalog
