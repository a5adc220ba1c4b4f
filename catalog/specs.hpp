#pragma once
/// One function per command, each defined in catalog/<command>.cpp and listed
/// by all_commands() in catalog/catalog.cpp.
#include "catalog/spec.hpp"

namespace lunaster::catalog {

const CommandSpec& debut_spec();
const CommandSpec& fin_spec();
const CommandSpec& lire_maillage_spec();
const CommandSpec& defi_group_spec();
const CommandSpec& modi_maillage_spec();
const CommandSpec& affe_modele_spec();
const CommandSpec& defi_materiau_spec();
const CommandSpec& affe_materiau_spec();
const CommandSpec& affe_char_meca_spec();
const CommandSpec& defi_contact_spec();
const CommandSpec& defi_cont_spec();
const CommandSpec& defi_list_reel_spec();
const CommandSpec& defi_list_inst_spec();
const CommandSpec& defi_fonction_spec();
const CommandSpec& defi_constante_spec();
const CommandSpec& formule_spec();
const CommandSpec& stat_non_line_spec();
const CommandSpec& meca_non_line_spec();
const CommandSpec& calc_champ_spec();
const CommandSpec& crea_champ_spec();
const CommandSpec& test_resu_spec();
const CommandSpec& impr_resu_spec();
const CommandSpec& impr_mesure_spec();
const CommandSpec& post_releve_t_spec();
const CommandSpec& test_table_spec();
const CommandSpec& impr_table_spec();

/// Builds a CommandSpec from its parts (the body is a root factor keyword).
CommandSpec make_command(std::string name, std::string result_type, std::string doc, std::vector<Keyword> keywords,
                         std::vector<Rule> rules = {}, std::vector<Block> blocks = {}, bool reuse_allowed = false);

}  // namespace lunaster::catalog
