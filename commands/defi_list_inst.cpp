// DEFI_LIST_INST: instants with automatic step subdivision on failure.
#include "commands/commands.hpp"
#include "commands/concepts.hpp"

namespace lunaster::cmd {

ConceptPtr defi_list_inst(const Args& args, Session&) {
  auto result = std::make_shared<ListInst>();
  const Args defi = args.factor("DEFI_LIST");
  result->instants = defi.concept_as<ListR8>("LIST_INST")->values;
  for (const auto& occ : args.factors("ECHEC")) {
    if (occ.text("ACTION") == "DECOUPE") {
      result->subdivide = true;
      result->subd_pas = static_cast<int>(occ.integer("SUBD_PAS"));
      result->subd_niveau = static_cast<int>(occ.integer("SUBD_NIVEAU"));
    }
  }
  return result;
}

}  // namespace lunaster::cmd
