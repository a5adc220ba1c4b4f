#include "catalog/lookup.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lunaster::catalog {

namespace {

std::optional<double> as_number(const Value& v) {
  if (auto d = std::get_if<double>(&v)) return *d;
  if (auto i = std::get_if<long long>(&v)) return static_cast<double>(*i);
  return std::nullopt;
}

/// The value deciding a block: the given first value, else the keyword's default.
std::optional<Value> condition_value(const KwNode& node, const Keyword* kw, const std::string& name) {
  auto it = node.simple.find(name);
  if (it != node.simple.end() && !it->second.empty()) return it->second.front();
  if (kw && kw->default_value) {
    return std::visit([](const auto& x) -> Value { return x; }, *kw->default_value);
  }
  return std::nullopt;
}

bool block_holds(const Block& block, const KwNode& node, const Keyword* condition_kw) {
  bool given = node.simple.count(block.when_keyword) || node.factors.count(block.when_keyword);
  if (block.equals.empty()) return given || (condition_kw && condition_kw->default_value);
  auto value = condition_value(node, condition_kw, block.when_keyword);
  if (!value) return false;
  return std::any_of(block.equals.begin(), block.equals.end(), [&](const Scalar& s) { return equals(*value, s); });
}

}  // namespace

bool equals(const Value& v, const Scalar& s) {
  if (auto text = std::get_if<std::string>(&s)) {
    auto given = std::get_if<std::string>(&v);
    return given && *given == *text;
  }
  auto number = as_number(v);
  if (!number) return false;
  double expected = std::holds_alternative<double>(s) ? std::get<double>(s) : static_cast<double>(std::get<long long>(s));
  return *number == expected;
}

std::vector<const Block*> active_blocks(const Keyword& spec, const KwNode& node) {
  std::vector<const Block*> active;
  std::vector<const Keyword*> visible;
  for (const auto& child : spec.children) visible.push_back(&child);
  bool changed = true;
  while (changed) {
    changed = false;
    for (const auto& block : spec.blocks) {
      if (std::find(active.begin(), active.end(), &block) != active.end()) continue;
      auto cond = std::find_if(visible.begin(), visible.end(),
                               [&](const Keyword* k) { return k->name == block.when_keyword; });
      if (cond == visible.end()) continue;
      if (!block_holds(block, node, *cond)) continue;
      active.push_back(&block);
      for (const auto& kw : block.keywords) visible.push_back(&kw);
      changed = true;
    }
  }
  return active;
}

std::vector<const Keyword*> active_keywords(const Keyword& spec, const KwNode& node) {
  std::vector<const Keyword*> out;
  for (const auto& child : spec.children) out.push_back(&child);
  for (const Block* block : active_blocks(spec, node))
    for (const auto& kw : block->keywords) out.push_back(&kw);
  return out;
}

const Keyword* find_active(const Keyword& spec, const KwNode& node, const std::string& name) {
  for (const Keyword* kw : active_keywords(spec, node))
    if (kw->name == name) return kw;
  return nullptr;
}

const Keyword* find_declared(const Keyword& spec, const std::string& name) {
  for (const auto& child : spec.children)
    if (child.name == name) return &child;
  for (const auto& block : spec.blocks)
    for (const auto& kw : block.keywords)
      if (kw.name == name) return &kw;
  return nullptr;
}

const Keyword* find_other_form(const Keyword& spec, const Value& value) {
  for (const auto& form : spec.other_keywords) {
    switch (form.type) {
      case ValueType::Real:
        if (std::holds_alternative<double>(value) || std::holds_alternative<long long>(value)) return &form;
        break;
      case ValueType::Int:
        if (std::holds_alternative<long long>(value)) return &form;
        break;
      case ValueType::Text:
        if (std::holds_alternative<std::string>(value)) return &form;
        break;
      case ValueType::Concept: {
        const auto* c = std::get_if<ConceptPtr>(&value);
        if (c && *c && std::find(form.concept_types.begin(), form.concept_types.end(), (*c)->type_name()) != form.concept_types.end())
          return &form;
        break;
      }
    }
  }
  return nullptr;
}

std::string join_path(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "." + name;
}

std::string occurrence_path(const std::string& prefix, const Keyword& kw, std::size_t index) {
  std::string path = join_path(prefix, kw.name);
  if (kw.max_occurs != 1) path += "[" + std::to_string(index + 1) + "]";
  return path;
}

std::string describe(const Value& v) {
  if (auto d = std::get_if<double>(&v)) {
    if (std::isnan(*d)) return "nan";  // one spelling whatever the sign bit (0/0 gives -nan on x86)
    std::ostringstream out;
    out << *d;
    return out.str();
  }
  if (auto i = std::get_if<long long>(&v)) return std::to_string(*i);
  if (auto s = std::get_if<std::string>(&v)) return "'" + *s + "'";
  const auto& c = std::get<ConceptPtr>(v);
  if (!c) return "nil";
  return c->type_name() + (c->user_name.empty() ? "" : " " + c->user_name);
}

std::string describe(const Scalar& s) {
  return std::visit([](const auto& x) { return describe(Value(x)); }, s);
}

}  // namespace lunaster::catalog
