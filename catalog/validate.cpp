/// The generic validator: checks a KwNode against a CommandSpec and fills
/// defaults (code_aster's SyntaxChecker semantics, STYLE.md §2-3 messages).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "catalog/args.hpp"
#include "catalog/doc.hpp"
#include "catalog/lookup.hpp"

namespace lunaster::catalog {

namespace {

constexpr std::size_t kMaxViolations = 10;

struct Violation {
  std::string path, expected, got;
  std::vector<std::string> hints;
};

std::string join_names(const std::vector<std::string>& names, const std::string& last_sep = " and ") {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += (i + 1 == names.size()) ? last_sep : ", ";
    out += names[i];
  }
  return out;
}

/// "real in [-1, 0.5]", "integer >= 1", "one of 'A', 'B'", "maillage".
std::string expected_text(const Keyword& kw) {
  if (kw.into.size() == 1) return describe(kw.into.front());
  if (!kw.into.empty()) {
    std::vector<std::string> items;
    for (const auto& s : kw.into) items.push_back(describe(s));
    return "one of " + join_names(items, ", ");
  }
  std::string base;
  switch (kw.type) {
    case ValueType::Real: base = "real"; break;
    case ValueType::Int: base = "integer"; break;
    case ValueType::Text: base = "text"; break;
    case ValueType::Concept: base = join_names(kw.concept_types, " or ") + " concept"; break;
  }
  return base + bounds_text(kw);
}

/// True if x lies outside the keyword's bounds (open bounds exclude their end).
bool out_of_bounds(const Keyword& kw, double x) {
  if (kw.val_min && (kw.min_open ? x <= *kw.val_min : x < *kw.val_min)) return true;
  if (kw.val_max && (kw.max_open ? x >= *kw.val_max : x > *kw.val_max)) return true;
  return false;
}

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

class Checker {
 public:
  explicit Checker(std::string command) : command_(std::move(command)) {}
  void check(const Keyword& spec, KwNode& node, const std::string& prefix);
  std::vector<Violation> found;

 private:
  void add(std::string path, std::string expected, std::string got, std::vector<std::string> hints = {}) {
    found.push_back({std::move(path), std::move(expected), std::move(got), std::move(hints)});
  }
  void check_unknown(const Keyword& spec, KwNode& node, const std::string& prefix);
  void check_simple(const Keyword& kw, KwNode& node, const std::string& prefix);
  void check_factor(const Keyword& kw, KwNode& node, const std::string& prefix);
  void check_value(const Keyword& kw, Value& value, const std::string& path);
  void check_rules(const std::vector<Rule>& rules, const std::set<std::string>& given, const std::string& prefix);
  std::string command_;
};

void Checker::check(const Keyword& spec, KwNode& node, const std::string& prefix) {
  std::set<std::string> given;
  for (const auto& [name, values] : node.simple) given.insert(name);
  for (const auto& [name, occurrences] : node.factors) given.insert(name);
  check_unknown(spec, node, prefix);
  // Blocks are re-evaluated after unknown keywords were removed; defaults of the
  // condition keywords count (code_aster injects defaults before evaluating blocks).
  for (const Keyword* kw : active_keywords(spec, node)) {
    if (kw->is_factor) {
      check_factor(*kw, node, prefix);
    } else if (!kw->factor_form.empty() && node.factors.count(kw->name)) {
      Keyword as_factor = factor(kw->name, kw->factor_form, kw->doc);
      as_factor.status = kw->status;
      check_factor(as_factor, node, prefix);
    } else {
      check_simple(*kw, node, prefix);
    }
  }
  std::vector<Rule> rules = spec.rules;
  for (const Block* block : active_blocks(spec, node)) rules.insert(rules.end(), block->rules.begin(), block->rules.end());
  check_rules(rules, given, prefix);
}

void Checker::check_unknown(const Keyword& spec, KwNode& node, const std::string& prefix) {
  auto active = active_keywords(spec, node);
  std::vector<std::string> names;
  for (const Keyword* kw : active) names.push_back(kw->name);
  std::vector<std::string> unknown;
  for (const auto& [name, values] : node.simple) unknown.push_back(name);
  for (const auto& [name, occurrences] : node.factors) unknown.push_back(name);
  const std::string where = prefix.empty() ? command_ : prefix;
  for (const auto& name : unknown) {
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    std::string path = join_path(prefix, name);
    if (!spec.other_keywords.empty() && node.simple.count(name)) {  // a named value (FORMULE's)
      const auto& values = node.simple[name];
      std::vector<std::string> forms;
      for (const auto& form : spec.other_keywords) forms.push_back(expected_text(form));
      if (values.size() == 1 && find_other_form(spec, values.front())) {
        if (auto i = std::get_if<long long>(&node.simple[name].front());
            i && find_other_form(spec, values.front())->type == ValueType::Real)
          node.simple[name].front() = static_cast<double>(*i);
        continue;
      }
      add(path, "a single value: " + join_names(forms, " or "),
          values.size() == 1 ? describe(values.front()) : plural(values.size(), "value"));
      node.simple.erase(name);
      continue;
    }
    // Keywords of inactive blocks: say when they would be valid (conditions merged per keyword).
    std::vector<std::pair<std::string, std::vector<std::string>>> conditions;
    for (const auto& block : spec.blocks) {
      if (std::none_of(block.keywords.begin(), block.keywords.end(), [&](const Keyword& k) { return k.name == name; }))
        continue;
      auto it = std::find_if(conditions.begin(), conditions.end(), [&](const auto& c) { return c.first == block.when_keyword; });
      if (it == conditions.end()) it = conditions.insert(conditions.end(), {block.when_keyword, {}});
      for (const auto& s : block.equals) it->second.push_back(describe(s));
    }
    if (!conditions.empty()) {
      std::vector<std::string> parts;
      for (const auto& [when, values] : conditions)
        parts.push_back(values.empty() ? when + " is given" : when + " = " + join_names(values, " or "));
      std::string got = node.simple.count(name) && !node.simple[name].empty()
                            ? name + " = " + describe(node.simple[name].front())
                            : name + " = _F{...}";
      add(path, "no " + name + " here (only valid when " + join_names(parts, " or ") + ")", got);
    } else {
      std::vector<std::string> hints;
      std::string suggestion = closest_name(name, names);
      if (!suggestion.empty()) hints.push_back("did you mean '" + suggestion + "'?");
      add(path, "a keyword of " + where, "unknown keyword '" + name + "'", std::move(hints));
    }
    node.simple.erase(name);
    node.factors.erase(name);
  }
}

void Checker::check_simple(const Keyword& kw, KwNode& node, const std::string& prefix) {
  const std::string path = join_path(prefix, kw.name);
  auto factor_it = node.factors.find(kw.name);
  if (factor_it != node.factors.end()) {
    bool empty_table = factor_it->second.size() == 1 && factor_it->second[0].simple.empty() &&
                       factor_it->second[0].factors.empty();
    node.factors.erase(factor_it);
    if (!empty_table) {
      add(path, expected_text(kw), "a table of keywords");
      return;
    }
    node.simple[kw.name] = {};
  }
  auto it = node.simple.find(kw.name);
  if (it == node.simple.end()) {
    if (kw.status == Status::Required)
      add(path, expected_text(kw) + " (mandatory keyword)", "nothing");
    else if (kw.default_value)
      node.simple[kw.name] = {std::visit([](const auto& x) -> Value { return x; }, *kw.default_value)};
    return;
  }
  auto& values = it->second;
  std::size_t n = values.size();
  if (n < static_cast<std::size_t>(kw.min_values)) {
    add(path, "at least " + plural(kw.min_values, "value") + " (" + expected_text(kw) + ")",
        n == 0 ? "an empty list" : plural(n, "value"));
    return;
  }
  if (kw.max_values >= 0 && n > static_cast<std::size_t>(kw.max_values)) {
    std::string expected = kw.max_values == 1 ? "a single value (" + expected_text(kw) + ")"
                                              : "at most " + plural(kw.max_values, "value");
    add(path, expected, "a list of " + plural(n, "value"));
    return;
  }
  for (auto& value : values) {
    if (found.size() >= kMaxViolations + 1) return;
    check_value(kw, value, path);
  }
}

void Checker::check_value(const Keyword& kw, Value& value, const std::string& path) {
  bool type_ok = false;
  switch (kw.type) {
    case ValueType::Real:
      if (auto i = std::get_if<long long>(&value)) value = static_cast<double>(*i);
      type_ok = std::holds_alternative<double>(value);
      break;
    case ValueType::Int:
      if (auto d = std::get_if<double>(&value); d && std::isfinite(*d) && std::floor(*d) == *d && std::fabs(*d) < 9e15)
        value = static_cast<long long>(*d);
      type_ok = std::holds_alternative<long long>(value);
      break;
    case ValueType::Text: type_ok = std::holds_alternative<std::string>(value); break;
    case ValueType::Concept: {
      auto c = std::get_if<ConceptPtr>(&value);
      type_ok = c && *c &&
                std::find(kw.concept_types.begin(), kw.concept_types.end(), (*c)->type_name()) != kw.concept_types.end();
      break;
    }
  }
  if (!type_ok) {
    add(path, expected_text(kw), describe(value));
    return;
  }
  // NaN and infinities (0/0, 1/0 in a deck) are no numbers for any keyword: NaN would also
  // slip through every bound, since each comparison with it is false.
  if (auto d = std::get_if<double>(&value); d && !std::isfinite(*d)) {
    add(path, "a finite " + expected_text(kw), describe(value));
    return;
  }
  for (const auto& [refused, reason] : kw.refused) {
    if (equals(value, refused)) {
      add(path, expected_text(kw) + " (" + reason + ")", describe(value));
      return;
    }
  }
  if (!kw.into.empty()) {
    bool inside = std::any_of(kw.into.begin(), kw.into.end(), [&](const Scalar& s) { return equals(value, s); });
    if (!inside) {
      std::vector<std::string> hints;
      if (auto s = std::get_if<std::string>(&value)) {
        std::vector<std::string> names;
        for (const auto& allowed : kw.into)
          if (auto t = std::get_if<std::string>(&allowed)) names.push_back(*t);
        std::string suggestion = closest_name(*s, names);
        if (!suggestion.empty()) hints.push_back("did you mean '" + suggestion + "'?");
      }
      add(path, expected_text(kw), describe(value), std::move(hints));
      return;
    }
  }
  if (kw.type == ValueType::Real || kw.type == ValueType::Int) {
    double x = kw.type == ValueType::Real ? std::get<double>(value) : static_cast<double>(std::get<long long>(value));
    if (out_of_bounds(kw, x)) add(path, expected_text(kw), describe(value));
  }
}

void Checker::check_factor(const Keyword& kw, KwNode& node, const std::string& prefix) {
  const std::string path = join_path(prefix, kw.name);
  auto simple_it = node.simple.find(kw.name);
  if (simple_it != node.simple.end()) {
    std::string got = simple_it->second.size() == 1 ? describe(simple_it->second[0])
                                                     : "a list of " + plural(simple_it->second.size(), "value");
    add(path, "_F{...} (factor keyword)", got);
    node.simple.erase(simple_it);
    return;
  }
  auto it = node.factors.find(kw.name);
  if (it == node.factors.end()) {
    if (kw.status == Status::Required || kw.min_occurs > 0) {
      add(path, "_F{...} (mandatory factor keyword)", "nothing");
    } else if (kw.present_by_default) {
      node.factors[kw.name] = {KwNode{}};
      check(kw, node.factors[kw.name][0], occurrence_path(prefix, kw, 0));
    }
    return;
  }
  auto& occurrences = it->second;
  std::size_t n = occurrences.size();
  if (n < static_cast<std::size_t>(std::max(kw.min_occurs, 1))) {
    add(path, "at least " + plural(std::max(kw.min_occurs, 1), "occurrence"), plural(n, "occurrence"));
    return;
  }
  if (kw.max_occurs >= 0 && n > static_cast<std::size_t>(kw.max_occurs)) {
    add(path, "at most " + plural(kw.max_occurs, "occurrence"), plural(n, "occurrence"));
    return;
  }
  for (std::size_t i = 0; i < n; ++i) check(kw, occurrences[i], occurrence_path(prefix, kw, i));
}

void Checker::check_rules(const std::vector<Rule>& rules, const std::set<std::string>& given,
                          const std::string& prefix) {
  for (const auto& rule : rules) {
    std::vector<std::string> present, absent;
    for (const auto& name : rule.names) (given.count(name) ? present : absent).push_back(name);
    const std::string all = join_names(rule.names, ", ");
    const std::string got = present.empty() ? "none" : join_names(present);
    switch (rule.kind) {
      case Rule::Kind::ExactlyOne:
        if (present.size() != 1) add(prefix, "exactly one of " + all, got);
        break;
      case Rule::Kind::AtLeastOne:
        if (present.empty()) add(prefix, "at least one of " + all, got);
        break;
      case Rule::Kind::AtMostOne:
        if (present.size() > 1) add(prefix, "at most one of " + all, got);
        break;
      case Rule::Kind::Together:
        if (!present.empty() && !absent.empty()) add(prefix, "all or none of " + all, "only " + got);
        break;
      case Rule::Kind::PresentAbsent: {
        if (!given.count(rule.names[0])) break;
        std::vector<std::string> clash(present.begin(), present.end());
        clash.erase(std::remove(clash.begin(), clash.end(), rule.names[0]), clash.end());
        std::vector<std::string> others(rule.names.begin() + 1, rule.names.end());
        if (!clash.empty())
          add(prefix, "none of " + join_names(others, ", ") + " when " + rule.names[0] + " is given",
              rule.names[0] + " with " + join_names(clash));
        break;
      }
      case Rule::Kind::PresentPresent:
        if (given.count(rule.names[0]) && !absent.empty())
          add(prefix, join_names(absent) + " together with " + rule.names[0], rule.names[0] + " alone");
        break;
    }
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// Optimal string alignment distance: insertions, deletions, substitutions and
/// transpositions of adjacent letters (a common typo) each cost one.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::string closest_name(const std::string& given, const std::vector<std::string>& candidates) {
  const std::string key = lower(given);
  // Close enough: at most a third of the name wrong (at least one edit allowed).
  const std::size_t limit = std::max<std::size_t>(1, key.size() / 3);
  std::string best;
  std::size_t best_distance = limit + 1;
  for (const auto& candidate : candidates) {
    std::size_t d = edit_distance(key, lower(candidate));
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

void validate(const CommandSpec& spec, KwNode& node) {
  Checker checker(spec.name);
  checker.check(spec.body, node, "");
  if (checker.found.empty()) return;
  const auto& first = checker.found.front();
  DeckError err = DeckError::at(first.path, first.expected, first.got, first.hints);
  std::size_t shown = std::min(checker.found.size(), kMaxViolations);
  for (std::size_t i = 1; i < shown; ++i) {
    const auto& v = checker.found[i];
    err.add_hint("also " + (v.path.empty() ? std::string() : v.path + ": ") + "expected " + v.expected + ", got " + v.got);
    for (const auto& hint : v.hints) err.add_hint("  " + hint);
  }
  if (checker.found.size() > kMaxViolations) err.add_hint("(further errors not shown)");
  ErrorContext ctx;
  ctx.command = spec.name;
  err.fill_context(ctx);
  throw err;
}

}  // namespace lunaster::catalog
