#include "catalog/specs.hpp"

namespace lunaster::catalog {

CommandSpec make_command(std::string name, std::string result_type, std::string doc, std::vector<Keyword> keywords,
                         std::vector<Rule> rules, std::vector<Block> blocks, bool reuse_allowed) {
  CommandSpec spec;
  spec.name = name;
  spec.result_type = std::move(result_type);
  spec.doc = std::move(doc);
  spec.reuse_allowed = reuse_allowed;
  spec.body = factor(std::move(name), std::move(keywords)).with_rules(std::move(rules)).with_blocks(std::move(blocks));
  return spec;
}

const std::vector<CommandSpec>& all_commands() {
  static const std::vector<CommandSpec> commands = {
      debut_spec(),          fin_spec(),           lire_maillage_spec(),  defi_group_spec(),
      modi_maillage_spec(),  affe_modele_spec(),   defi_materiau_spec(),  affe_materiau_spec(),
      affe_char_meca_spec(), defi_contact_spec(),  defi_cont_spec(),  defi_list_reel_spec(), defi_list_inst_spec(),
      defi_fonction_spec(),  defi_constante_spec(), formule_spec(), stat_non_line_spec(),  meca_non_line_spec(), calc_champ_spec(),     crea_champ_spec(),     test_resu_spec(),
      impr_resu_spec(),      impr_mesure_spec(),   post_releve_t_spec(),  test_table_spec(),  impr_table_spec(),
  };
  return commands;
}

const CommandSpec* find_command(const std::string& name) {
  for (const auto& spec : all_commands())
    if (spec.name == name) return &spec;
  return nullptr;
}

}  // namespace lunaster::catalog
