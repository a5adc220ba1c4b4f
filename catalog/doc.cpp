#include "catalog/doc.hpp"

#include <cctype>
#include <sstream>

#include "catalog/lookup.hpp"

namespace lunaster::catalog {

namespace {

/// Text safe inside a Markdown table cell.
std::string md_cell(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '<') out += "&lt;";
    else if (ch == '>') out += "&gt;";
    else if (ch == '|') out += "\\|";
    else out += ch;
  }
  return out;
}

std::string lower(std::string s) {
  for (auto& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string names(const std::vector<std::string>& list) {
  std::string out;
  for (std::size_t i = 0; i < list.size(); ++i) out += (i ? ", " : "") + list[i];
  return out;
}

std::string status_text(const Keyword& kw) {
  if (kw.is_factor) {
    std::string occ = kw.max_occurs == 1 ? "once" : "repeatable";
    if (kw.status == Status::Required) return "required, " + occ;
    if (kw.present_by_default) return "optional (present by default), " + occ;
    return (kw.status == Status::Legacy ? "legacy, " : "optional, ") + occ;
  }
  if (kw.status == Status::Required) return "required";
  return kw.status == Status::Legacy ? "legacy" : "optional";
}

std::string condition_text(const Block& block) {
  if (block.equals.empty()) return "when " + block.when_keyword + " is given";
  std::string values;
  for (std::size_t i = 0; i < block.equals.size(); ++i) values += (i ? " or " : "") + describe(block.equals[i]);
  return "when " + block.when_keyword + " = " + values;
}

/// Keyword lines for the text help, indented by depth.
void text_keywords(std::ostringstream& out, const Keyword& spec, int depth) {
  std::string pad(2 * depth, ' ');
  auto one = [&](const Keyword& kw, const std::string& condition) {
    out << pad << kw.name << "  [" << (kw.is_factor ? "factor" : type_text(kw)) << "; " << status_text(kw);
    if (kw.default_value) out << "; default " << describe(*kw.default_value);
    out << refused_text(kw);
    if (!condition.empty()) out << "; " << condition;
    out << "]\n" << pad << "    " << kw.doc << "\n";
    if (kw.is_factor) text_keywords(out, kw, depth + 1);
  };
  for (const auto& kw : spec.children) one(kw, "");
  for (const auto& block : spec.blocks)
    for (const auto& kw : block.keywords) one(kw, condition_text(block));
  for (const auto& kw : spec.other_keywords) one(kw, "any other name");
  for (const auto& rule : spec.rules) out << pad << "rule: " << rule_text(rule) << "\n";
  for (const auto& block : spec.blocks)
    for (const auto& rule : block.rules) out << pad << "rule (" << condition_text(block) << "): " << rule_text(rule) << "\n";
}

void markdown_rows(std::ostringstream& out, const Keyword& spec, const std::string& prefix) {
  auto row = [&](const Keyword& kw, const std::string& condition) {
    std::string path = prefix.empty() ? kw.name : prefix + "/" + kw.name;
    out << "| `" << path << "` | " << (kw.is_factor ? "factor" : type_text(kw)) << " | " << status_text(kw) << " | "
        << (kw.default_value ? "`" + describe(*kw.default_value) + "`" : "") << " | " << md_cell(kw.doc)
        << (condition.empty() ? "" : " (" + condition + ")") << md_cell(refused_text(kw)) << " |\n";
    if (kw.is_factor) markdown_rows(out, kw, path);
  };
  for (const auto& kw : spec.children) row(kw, "");
  for (const auto& block : spec.blocks)
    for (const auto& kw : block.keywords) row(kw, condition_text(block));
  for (const auto& kw : spec.other_keywords) row(kw, "any other name");
}

void markdown_rules(std::ostringstream& out, const Keyword& spec, const std::string& prefix) {
  std::string where = prefix.empty() ? "" : "`" + prefix + "`: ";
  for (const auto& rule : spec.rules) out << "- " << where << rule_text(rule) << "\n";
  for (const auto& block : spec.blocks)
    for (const auto& rule : block.rules) out << "- " << where << rule_text(rule) << " (" << condition_text(block) << ")\n";
  auto recurse = [&](const Keyword& kw) {
    if (kw.is_factor) markdown_rules(out, kw, prefix.empty() ? kw.name : prefix + "/" + kw.name);
  };
  for (const auto& kw : spec.children) recurse(kw);
  for (const auto& block : spec.blocks)
    for (const auto& kw : block.keywords) recurse(kw);
}

}  // namespace

std::string type_text(const Keyword& kw) {
  std::string base;
  switch (kw.type) {
    case ValueType::Real: base = "real"; break;
    case ValueType::Int: base = "integer"; break;
    case ValueType::Text: base = "text"; break;
    case ValueType::Concept: {
      for (std::size_t i = 0; i < kw.concept_types.size(); ++i) base += (i ? " or " : "") + kw.concept_types[i];
      break;
    }
  }
  if (!kw.into.empty()) {
    base += " in (";
    for (std::size_t i = 0; i < kw.into.size(); ++i) base += (i ? ", " : "") + describe(kw.into[i]);
    base += ")";
  }
  base += bounds_text(kw);
  if (kw.max_values != 1) base = "list of " + base;
  return base;
}

std::string bounds_text(const Keyword& kw) {
  if (kw.val_min && kw.val_max)
    return std::string(" in ") + (kw.min_open ? "(" : "[") + number(*kw.val_min) + ", " + number(*kw.val_max) +
           (kw.max_open ? ")" : "]");
  if (kw.val_min) return (kw.min_open ? " > " : " >= ") + number(*kw.val_min);
  if (kw.val_max) return (kw.max_open ? " < " : " <= ") + number(*kw.val_max);
  return {};
}

std::string refused_text(const Keyword& kw) {
  std::string out;
  for (const auto& [value, reason] : kw.refused) out += "; " + describe(value) + " refused: " + reason;
  return out;
}

std::string rule_text(const Rule& rule) {
  const std::string all = names(rule.names);
  switch (rule.kind) {
    case Rule::Kind::ExactlyOne: return "exactly one of " + all;
    case Rule::Kind::AtLeastOne: return "at least one of " + all;
    case Rule::Kind::AtMostOne: return "at most one of " + all;
    case Rule::Kind::Together: return "all or none of " + all;
    case Rule::Kind::PresentAbsent:
      return "if " + rule.names[0] + " is given, none of " +
             names(std::vector<std::string>(rule.names.begin() + 1, rule.names.end()));
    case Rule::Kind::PresentPresent:
      return "if " + rule.names[0] + " is given, also " +
             names(std::vector<std::string>(rule.names.begin() + 1, rule.names.end()));
  }
  return {};
}

std::string command_list() {
  std::ostringstream out;
  for (const auto& spec : all_commands()) {
    std::string name = spec.name;
    name.resize(std::max<std::size_t>(name.size(), 16), ' ');
    std::string type = spec.result_type.empty() ? "-" : spec.result_type;
    type.resize(std::max<std::size_t>(type.size(), 13), ' ');
    out << "  " << name << type << spec.doc << "\n";
  }
  return out.str();
}

std::string command_help(const CommandSpec& spec) {
  std::ostringstream out;
  out << spec.name << " -- " << spec.doc << "\n";
  out << "returns: " << (spec.result_type.empty() ? "nothing" : spec.result_type)
      << (spec.reuse_allowed ? " (reuse = X accepted)" : "") << "\n\n";
  text_keywords(out, spec.body, 1);
  return out.str();
}

std::string catalog_markdown() {
  std::ostringstream out;
  out << "# lunaster command catalogue\n\n"
      << "Generated by `lunaster --dump-catalog md` from the catalogue in `catalog/`; do not edit by hand.\n\n"
      << "| command | returns | description |\n|---|---|---|\n";
  for (const auto& spec : all_commands())
    out << "| [" << spec.name << "](#" << lower(spec.name) << ") | " << (spec.result_type.empty() ? "-" : spec.result_type)
        << " | " << md_cell(spec.doc) << " |\n";
  for (const auto& spec : all_commands()) {
    out << "\n## " << spec.name << "\n\n" << spec.doc << "\n\n";
    out << "Returns: " << (spec.result_type.empty() ? "nothing" : "`" + spec.result_type + "`")
        << (spec.reuse_allowed ? " (`reuse = X` accepted)" : "") << ".\n\n";
    if (spec.body.children.empty() && spec.body.blocks.empty()) {
      out << "No keywords.\n";
      continue;
    }
    out << "| keyword | type | status | default | description |\n|---|---|---|---|---|\n";
    markdown_rows(out, spec.body, "");
    std::ostringstream rules;
    markdown_rules(rules, spec.body, "");
    if (!rules.str().empty()) out << "\nRules:\n\n" << rules.str();
  }
  return out.str();
}

}  // namespace lunaster::catalog
