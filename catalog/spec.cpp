#include "catalog/spec.hpp"

namespace lunaster::catalog {

namespace {
Keyword simple(std::string name, ValueType type, std::string doc) {
  Keyword k;
  k.name = std::move(name);
  k.type = type;
  k.doc = std::move(doc);
  return k;
}
Rule make_rule(Rule::Kind kind, std::vector<std::string> names) { return Rule{kind, std::move(names)}; }
}  // namespace

Keyword real(std::string name, std::string doc) { return simple(std::move(name), ValueType::Real, std::move(doc)); }
Keyword integer(std::string name, std::string doc) { return simple(std::move(name), ValueType::Int, std::move(doc)); }
Keyword text(std::string name, std::string doc) { return simple(std::move(name), ValueType::Text, std::move(doc)); }

Keyword concept_kw(std::string name, std::vector<std::string> types, std::string doc) {
  Keyword k = simple(std::move(name), ValueType::Concept, std::move(doc));
  k.concept_types = std::move(types);
  return k;
}

Keyword factor(std::string name, std::vector<Keyword> children, std::string doc) {
  Keyword k;
  k.name = std::move(name);
  k.is_factor = true;
  k.children = std::move(children);
  k.doc = std::move(doc);
  return k;
}

Rule exactly_one(std::vector<std::string> names) { return make_rule(Rule::Kind::ExactlyOne, std::move(names)); }
Rule at_least_one(std::vector<std::string> names) { return make_rule(Rule::Kind::AtLeastOne, std::move(names)); }
Rule at_most_one(std::vector<std::string> names) { return make_rule(Rule::Kind::AtMostOne, std::move(names)); }
Rule together(std::vector<std::string> names) { return make_rule(Rule::Kind::Together, std::move(names)); }
Rule present_absent(std::vector<std::string> names) { return make_rule(Rule::Kind::PresentAbsent, std::move(names)); }
Rule present_present(std::vector<std::string> names) { return make_rule(Rule::Kind::PresentPresent, std::move(names)); }

}  // namespace lunaster::catalog
