#pragma once
/// Keyword trees: `KwNode` is what the Lua bridge builds from a deck table;
/// after validation (defaults filled in) it is read through `Args`.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "catalog/concept.hpp"
#include "catalog/spec.hpp"
#include "engine/core/error.hpp"

namespace lunaster::catalog {

/// One value of a simple keyword as given in a deck.
using Value = std::variant<double, long long, std::string, ConceptPtr>;

/// A table of keywords: simple keywords hold value lists, factor keywords hold occurrences.
struct KwNode {
  std::map<std::string, std::vector<Value>> simple;
  std::map<std::string, std::vector<KwNode>> factors;
};

/// The declared keywords a command's handler asked for, as catalogue paths
/// ("STAT_NON_LINE/NEWTON/REAC_ITER", no occurrence numbers). Filled by Args when one
/// is given to the root Args (the runner does so on request): a test proves with it
/// that every keyword the catalogue accepts is read by its handler.
class KeywordReads {
 public:
  void record(const std::string& path) { paths_.insert(path); }
  bool contains(const std::string& path) const { return paths_.count(path) > 0; }
  const std::set<std::string>& paths() const { return paths_; }

 private:
  std::set<std::string> paths_;
};

/// Typed read access to a validated keyword node. Asking for a keyword the
/// spec does not declare is an InternalError (a bug in the command). Every
/// access to a keyword (has, values, count, factor) is a read for KeywordReads.
class Args {
 public:
  /// `reads` (may be null, not owned) records the keywords read through this Args and its factors.
  Args(const KwNode& node, const Keyword& spec, std::string path = {}, KeywordReads* reads = nullptr);

  bool has(const std::string& kw) const;
  /// The names given here that the spec does not declare and takes as other_keywords (FORMULE's named values).
  std::vector<std::string> other_names() const;
  /// True if the spec (or an active block) declares `kw` here; never throws.
  bool declares(const std::string& kw) const;
  double real(const std::string& kw) const;
  long long integer(const std::string& kw) const;
  std::string text(const std::string& kw) const;
  std::vector<double> reals(const std::string& kw) const;
  std::vector<long long> integers(const std::string& kw) const;
  std::vector<std::string> texts(const std::string& kw) const;
  ConceptPtr concept_value(const std::string& kw) const;
  std::vector<ConceptPtr> concepts(const std::string& kw) const;
  /// The concept cast to T; DeckError if it is of another type.
  template <class T>
  std::shared_ptr<T> concept_as(const std::string& kw) const {
    auto c = concept_value(kw);
    auto t = std::dynamic_pointer_cast<T>(c);
    if (!t) throw_wrong_concept(kw, c);
    return t;
  }

  /// Number of occurrences of a factor keyword (0 if absent).
  int count(const std::string& factor) const;
  Args factor(const std::string& factor, int occurrence = 0) const;
  std::vector<Args> factors(const std::string& factor) const;

  /// Keyword path for messages: "EXCIT[2].CHARGE" (occurrences 1-based).
  std::string path(const std::string& kw) const;
  /// Where this node sits, for messages: "LIAISON_DDL[2]" for an occurrence; empty at the root.
  const std::string& where() const { return path_; }
  /// A DeckError located at this keyword: "expected <expected>, got <given>".
  DeckError error(const std::string& kw, const std::string& expected, const std::string& given,
                  std::vector<std::string> hints = {}) const;
  const KwNode& node() const { return *node_; }

 private:
  const std::vector<Value>& values(const std::string& kw) const;
  Args(const KwNode& node, const Keyword& spec, std::string path, std::string catalog_path, KeywordReads* reads);
  /// The declared keyword `kw` (recorded as read); InternalError if the spec has none.
  const Keyword* declared(const std::string& kw) const;
  [[noreturn]] void throw_wrong_concept(const std::string& kw, const ConceptPtr& c) const;
  const KwNode* node_;
  const Keyword* spec_;
  std::string path_;
  std::string catalog_path_;  ///< "STAT_NON_LINE/NEWTON": where this node sits in the catalogue
  KeywordReads* reads_ = nullptr;
};

/// Checks `node` against `spec` (unknown keywords, types, into, ranges, counts,
/// rules, blocks), converts Int to Real where Real is expected, and fills
/// defaults. Throws one DeckError listing every violation (at most 10), each
/// with its keyword path and a "did you mean" hint for misspellings.
void validate(const CommandSpec& spec, KwNode& node);

/// Compact one-line rendering of a node, for the command echo:
/// `{ E=2e+06, NU=0, AFFE=_F{ TOUT='OUI' } }`.
std::string format_node(const KwNode& node);

/// Edit-distance suggestion among `candidates`, or empty if none is close.
std::string closest_name(const std::string& given, const std::vector<std::string>& candidates);

}  // namespace lunaster::catalog
