#include "commands/commands.hpp"
#include "commands/registry.hpp"

namespace lunaster::cmd {

const std::vector<CommandEntry>& all_handlers() {
  static const std::vector<CommandEntry> handlers = {
      {"DEBUT", debut},
      {"FIN", fin},
      {"LIRE_MAILLAGE", lire_maillage},
      {"DEFI_GROUP", defi_group},
      {"MODI_MAILLAGE", modi_maillage},
      {"AFFE_MODELE", affe_modele},
      {"DEFI_MATERIAU", defi_materiau},
      {"AFFE_MATERIAU", affe_materiau},
      {"AFFE_CHAR_MECA", affe_char_meca},
      {"DEFI_CONTACT", defi_contact},
      {"DEFI_CONT", defi_cont},
      {"DEFI_LIST_REEL", defi_list_reel},
      {"DEFI_LIST_INST", defi_list_inst},
      {"DEFI_FONCTION", defi_fonction},
      {"DEFI_CONSTANTE", defi_constante},
      {"FORMULE", formule},
      {"STAT_NON_LINE", stat_non_line},
      {"MECA_NON_LINE", meca_non_line},
      {"CALC_CHAMP", calc_champ},
      {"CREA_CHAMP", crea_champ},
      {"TEST_RESU", test_resu},
      {"IMPR_RESU", impr_resu},
      {"IMPR_MESURE", impr_mesure},
      {"POST_RELEVE_T", post_releve_t},
      {"TEST_TABLE", test_table},
      {"IMPR_TABLE", impr_table},
  };
  return handlers;
}

Handler find_handler(const std::string& name) {
  for (const auto& entry : all_handlers())
    if (name == entry.name) return entry.handler;
  return nullptr;
}

}  // namespace lunaster::cmd
