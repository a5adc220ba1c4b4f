#include "catalog/args.hpp"

#include "catalog/lookup.hpp"

namespace lunaster::catalog {

Args::Args(const KwNode& node, const Keyword& spec, std::string path, KeywordReads* reads)
    : Args(node, spec, std::move(path), spec.name, reads) {}

Args::Args(const KwNode& node, const Keyword& spec, std::string path, std::string catalog_path, KeywordReads* reads)
    : node_(&node), spec_(&spec), path_(std::move(path)), catalog_path_(std::move(catalog_path)), reads_(reads) {}

const Keyword* Args::declared(const std::string& kw) const {
  const Keyword* found = find_active(*spec_, *node_, kw);
  if (!found) found = find_declared(*spec_, kw);
  if (!found && node_->simple.count(kw) && node_->simple.at(kw).size() == 1) {
    // a named value (FORMULE's): the deck's own name, not a catalogue path to record
    if (const Keyword* form = find_other_form(*spec_, node_->simple.at(kw).front())) return form;
  }
  if (!found)
    throw InternalError("keyword " + path(kw) + " is not declared in the catalogue of '" +
                        (path_.empty() ? spec_->name : path_) + "'");
  if (reads_) reads_->record(catalog_path_ + "/" + kw);
  return found;
}

std::vector<std::string> Args::other_names() const {
  std::vector<std::string> names;
  if (spec_->other_keywords.empty()) return names;
  for (const auto& [name, values] : node_->simple)
    if (!find_active(*spec_, *node_, name) && !find_declared(*spec_, name)) names.push_back(name);
  return names;
}

bool Args::declares(const std::string& kw) const {
  return find_active(*spec_, *node_, kw) != nullptr || find_declared(*spec_, kw) != nullptr;
}

bool Args::has(const std::string& kw) const {
  const Keyword* k = declared(kw);
  if (k->is_factor) return node_->factors.count(kw) > 0;
  return node_->simple.count(kw) > 0;
}

const std::vector<Value>& Args::values(const std::string& kw) const {
  const Keyword* k = declared(kw);
  if (k->is_factor) throw InternalError("keyword " + path(kw) + " is a factor keyword, read it with factor()");
  static const std::vector<Value> none;
  auto it = node_->simple.find(kw);
  return it == node_->simple.end() ? none : it->second;
}

namespace {
template <class T>
const T& first_as(const std::vector<Value>& values, const std::string& path, const char* type) {
  if (values.empty()) throw InternalError("keyword " + path + " has no value (check has() first)");
  const T* v = std::get_if<T>(&values.front());
  if (!v) throw InternalError("keyword " + path + " does not hold a " + type + " value");
  return *v;
}
template <class T>
std::vector<T> all_as(const std::vector<Value>& values, const std::string& path, const char* type) {
  std::vector<T> out;
  for (const auto& value : values) {
    const T* v = std::get_if<T>(&value);
    if (!v) throw InternalError("keyword " + path + " does not hold " + type + " values");
    out.push_back(*v);
  }
  return out;
}
}  // namespace

double Args::real(const std::string& kw) const { return first_as<double>(values(kw), path(kw), "real"); }
long long Args::integer(const std::string& kw) const { return first_as<long long>(values(kw), path(kw), "integer"); }
std::string Args::text(const std::string& kw) const { return first_as<std::string>(values(kw), path(kw), "text"); }
std::vector<double> Args::reals(const std::string& kw) const { return all_as<double>(values(kw), path(kw), "real"); }
std::vector<long long> Args::integers(const std::string& kw) const {
  return all_as<long long>(values(kw), path(kw), "integer");
}
std::vector<std::string> Args::texts(const std::string& kw) const {
  return all_as<std::string>(values(kw), path(kw), "text");
}
ConceptPtr Args::concept_value(const std::string& kw) const {
  return first_as<ConceptPtr>(values(kw), path(kw), "concept");
}
std::vector<ConceptPtr> Args::concepts(const std::string& kw) const {
  return all_as<ConceptPtr>(values(kw), path(kw), "concept");
}

int Args::count(const std::string& factor_name) const {
  const Keyword* k = declared(factor_name);
  if (!k->is_factor) throw InternalError("keyword " + path(factor_name) + " is not a factor keyword");
  auto it = node_->factors.find(factor_name);
  return it == node_->factors.end() ? 0 : static_cast<int>(it->second.size());
}

Args Args::factor(const std::string& factor_name, int occurrence) const {
  int n = count(factor_name);
  if (occurrence < 0 || occurrence >= n)
    throw InternalError("factor keyword " + path(factor_name) + " has " + std::to_string(n) +
                        " occurrence(s), asked for number " + std::to_string(occurrence + 1));
  const Keyword* k = declared(factor_name);
  return Args(node_->factors.at(factor_name)[occurrence], *k, occurrence_path(path_, *k, occurrence),
              catalog_path_ + "/" + factor_name, reads_);
}

std::vector<Args> Args::factors(const std::string& factor_name) const {
  std::vector<Args> out;
  int n = count(factor_name);
  for (int i = 0; i < n; ++i) out.push_back(factor(factor_name, i));
  return out;
}

std::string Args::path(const std::string& kw) const { return join_path(path_, kw); }

DeckError Args::error(const std::string& kw, const std::string& expected, const std::string& given,
                      std::vector<std::string> hints) const {
  return DeckError::at(path(kw), expected, given, std::move(hints));
}

void Args::throw_wrong_concept(const std::string& kw, const ConceptPtr& c) const {
  const Keyword* k = declared(kw);
  std::string expected;
  for (const auto& t : k->concept_types) expected += (expected.empty() ? "" : " or ") + t;
  throw error(kw, expected + " concept", c ? describe(Value(c)) : "nothing");
}

std::string format_node(const KwNode& node) {
  std::string out = "{";
  bool first = true;
  auto sep = [&] { out += first ? " " : ", "; first = false; };
  for (const auto& [name, values] : node.simple) {
    sep();
    out += name + "=";
    if (values.size() == 1) {
      out += describe(values[0]);
    } else {
      out += "{";
      for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + describe(values[i]);
      out += "}";
    }
  }
  for (const auto& [name, occurrences] : node.factors) {
    sep();
    out += name + "=";
    if (occurrences.size() != 1) out += "{";
    for (std::size_t i = 0; i < occurrences.size(); ++i) out += (i ? ", " : "") + std::string("_F") + format_node(occurrences[i]);
    if (occurrences.size() != 1) out += "}";
  }
  out += first ? "}" : " }";
  return out;
}

}  // namespace lunaster::catalog
