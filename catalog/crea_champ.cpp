#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& crea_champ_spec() {
  static const CommandSpec spec = make_command(
      "CREA_CHAMP", "cham_gd",
      "Create a field: OPERATION='EXTR' takes one field of a result at one time step (a copy: the result may "
      "change afterwards, the field does not)",
      {text("OPERATION",
            "EXTR extracts a field of RESULTAT. code_aster's other operations (AFFE, ASSE, COMB, EVAL, DISC, "
            "NORMALE, ASSE_DEPL, CONC, R2C, C2R) build fields from constants, functions or other fields: they are "
            "refused by name, lunaster's fields coming from results only")
           .into_values({"EXTR", "AFFE", "ASSE", "COMB", "EVAL", "DISC", "NORMALE", "ASSE_DEPL", "CONC", "R2C", "C2R"})
           .required(),
       text("TYPE_CHAM",
            "code_aster's field type, <where>_<quantity>_R: where NOEU (at nodes), ELNO (at each cell's nodes) or "
            "ELGA (at each cell's integration points); the quantity of the field NOM_CHAM (DEPL for DEPL, "
            "FORC_NODA, REAC_NODA; SIEF for the stresses SIGM_*, SIEF_*, SIEQ_*; VARI for VARI_*; INFC for "
            "CONT_NOEU). A type that is not the field's is an error")
           .required()},
      {},
      {Block{"OPERATION",
             {"EXTR"},
             {concept_kw("RESULTAT", {"evol_noli"}, "Result the field is taken from").required(),
              text("NOM_CHAM", "Field of RESULTAT, e.g. DEPL, SIGM_ELNO, SIEF_ELGA (compute it with CALC_CHAMP "
                               "first if needed)")
                  .required(),
              integer("NUME_ORDRE", "Time step the field is taken at"),
              real("INST", "Time the field is taken at (within 1e-6 relative)")},
             {exactly_one({"NUME_ORDRE", "INST"})}}});
  return spec;
}

}  // namespace lunaster::catalog
