#pragma once
/// Base of every typed object a command returns (maillage, modele, evol_noli ...).
/// Concrete concepts live in commands/concepts.hpp; the catalogue only knows
/// their type names.
#include <memory>
#include <string>

namespace lunaster::catalog {

class Concept {
 public:
  virtual ~Concept() = default;
  /// code_aster type name: "maillage", "modele", "mater", "cham_mater", "char_meca",
  /// "char_contact", "listr8", "list_inst", "fonction", "formule", "evol_noli", "table"; "function" is a
  /// function of the deck given to FORMULE.
  virtual std::string type_name() const = 0;
  /// True for a concept on a mesh in parts (LIRE_MAILLAGE's PARTITIONNEUR): only the commands
  /// written for parts take it (docs/distributed-model.md).
  virtual bool in_parts() const { return false; }
  /// Name of the deck variable the concept was assigned to (set by the runner), for messages.
  std::string user_name;
};

using ConceptPtr = std::shared_ptr<Concept>;

}  // namespace lunaster::catalog
