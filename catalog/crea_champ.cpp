#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

/// The places of an AFFE or ASSE occurrence: the whole support, cell groups' nodes, node groups, nodes.
std::vector<Keyword> places(const std::string& what) {
  return {common::tout("The whole support (the mesh's nodes with MAILLAGE, the model's with MODELE) " + what),
          common::group_ma("Cell groups whose nodes " + what), common::group_no("Node groups that " + what),
          common::noeud("Nodes that " + what)};
}

Keyword affe() {
  std::vector<Keyword> children = places("take the values");
  children.push_back(text("NOM_CMP", "Components given, of TYPE_CHAM's quantity (DEPL: DX, DY, DZ, DRX ..., LAGS_C; "
                                     "TEMP: TEMP; NEUT: X1 ... X30; GEOM: X, Y, Z; SIEF: SIXX ...)")
                         .many()
                         .required());
  children.push_back(real("VALE", "One real per component of NOM_CMP (a *_R field)").many());
  children.push_back(concept_kw("VALE_F", {"fonction", "formule", "function"},
                                "One function per component of NOM_CMP (a *_F field; EVAL gives its values)")
                         .many());
  return factor("AFFE",
                children, "Values given on a part of the support; a later occurrence overrides an earlier one where "
                          "they meet. A component is defined at the nodes some occurrence gives it, and only there")
      .occurs(1, -1)
      .required()
      .with_rules({at_least_one({"TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"}), exactly_one({"VALE", "VALE_F"})});
}

Keyword asse() {
  std::vector<Keyword> children = places("take CHAM_GD's values");
  children.push_back(concept_kw("CHAM_GD", {"cham_gd"}, "Field at nodes the values are taken from").required());
  children.push_back(text("NOM_CMP", "Components of CHAM_GD taken (all its components if absent)").many());
  children.push_back(text("NOM_CMP_RESU", "Their names in the new field, one per NOM_CMP (absent: the same names)").many());
  children.push_back(text("CUMUL", "'OUI': added to what earlier occurrences put there; 'NON': replaces it")
                         .into_values({"OUI", "NON"})
                         .def("NON"));
  children.push_back(real("COEF_R", "Factor applied to the values taken").def(1.0));
  return factor("ASSE", children, "Components of another field, on a part of the support, in order")
      .occurs(1, -1)
      .required()
      .with_rules({at_least_one({"TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"}), present_present({"NOM_CMP_RESU", "NOM_CMP"})});
}

/// The field types some operation makes: results' fields (EXTR) and fields built at nodes.
std::vector<Scalar> field_types() {
  std::vector<Scalar> out;
  for (const char* q : {"DEPL", "SIEF", "VARI", "EPSI", "INFC", "TEMP", "NEUT", "GEOM"}) out.push_back("NOEU_" + std::string(q) + "_R");
  for (const char* where : {"ELNO_", "ELGA_"})
    for (const char* q : {"SIEF", "VARI", "EPSI"}) out.push_back(std::string(where) + q + "_R");
  for (const char* q : {"DEPL", "SIEF", "TEMP", "NEUT", "GEOM"}) out.push_back("NOEU_" + std::string(q) + "_F");
  return out;
}

Keyword support(const char* name, bool mesh) {
  return mesh ? concept_kw(name, {"maillage"}, "Mesh the field lies on (TOUT: all its nodes)")
              : concept_kw(name, {"modele"}, "Model the field lies on (TOUT: the nodes of its cells)");
}

}  // namespace

const CommandSpec& crea_champ_spec() {
  const std::string at_nodes_only =
      "lunaster builds fields at nodes (NOEU_*) from constants, functions and other fields; fields per cell "
      "come from results (EXTR)";
  const std::string per_cell =
      "a field per cell or integration point built from constants, functions or other fields: lunaster builds "
      "such fields at nodes (NOEU_*)";
  static const CommandSpec spec = make_command(
      "CREA_CHAMP", "cham_gd",
      "Create a field: taken out of a result at one time step (EXTR; a copy: the result may change afterwards, "
      "the field does not) or of a mesh (its geometry), or built at nodes from constants or functions (AFFE), "
      "other fields' components (ASSE), a linear combination (COMB), or functions evaluated (EVAL)",
      {text("OPERATION",
            "EXTR: a field of RESULTAT, or MAILLAGE's geometry. AFFE: constants (VALE, a *_R field) or functions "
            "(VALE_F, a *_F field) given per group. ASSE: components of other fields, renamed, scaled, added. "
            "COMB: sum of COEF_R x CHAM_GD. EVAL: a *_F field's functions evaluated at each node with CHAM_PARA's "
            "components as parameters (X, Y, Z of a NOEU_GEOM_R field ...). AFFE, ASSE and EVAL build fields at "
            "nodes (NOEU_*): a TYPE_CHAM per cell (ELGA_, ELNO_, ELEM_, CART_) is refused")
           .into_values({"EXTR", "AFFE", "ASSE", "COMB", "EVAL"})
           .refuse("DISC", "a field moved between nodes, cells and integration points: " + at_nodes_only)
           .refuse("NORMALE", "the normals of a surface as a field are not built by lunaster")
           .refuse("ASSE_DEPL", "XFEM displacements: lunaster has no XFEM")
           .refuse("R2C", "lunaster's fields are real")
           .refuse("C2R", "lunaster's fields are real")
           .required(),
       text("TYPE_CHAM",
            "code_aster's field type, <where>_<quantity>_<R|F>: where NOEU (at nodes), ELNO (at each cell's nodes) "
            "or ELGA (at each cell's integration points). EXTR: the quantity of the field NOM_CHAM (DEPL for DEPL, "
            "FORC_NODA, REAC_NODA; SIEF for the stresses SIGM_*, SIEF_*, SIEQ_*; VARI for VARI_*; INFC for "
            "CONT_NOEU; GEOM for a mesh's GEOMETRIE), a type that is not the field's is an error. AFFE, ASSE, "
            "COMB, EVAL: NOEU_ with DEPL, TEMP, NEUT, GEOM or SIEF, _R (reals) or _F (functions, AFFE only). "
            "code_aster's other types (maps CART_*, per-cell ELEM_*, per-cell fields of constants or functions "
            "ELGA_NEUT_*, ...) are no lunaster field")
           .into_values(field_types())
           .refuse("ELGA_NEUT_R", per_cell)
           .refuse("ELGA_NEUT_F", per_cell)
           .refuse("ELGA_DEPL_R", per_cell)
           .refuse("ELGA_GEOM_R", per_cell)
           .refuse("CART_NEUT_R", per_cell)
           .refuse("ELEM_CLAC_R", "code_aster's discrete contact statuses per cell: lunaster's are CONT_NOEU (NOEU_INFC_R)")
           .required(),
       common::info()},
      {},
      {Block{"OPERATION",
             {"EXTR"},
             {concept_kw("RESULTAT", {"evol_noli"}, "Result the field is taken from"),
              concept_kw("MAILLAGE", {"maillage"}, "Mesh whose geometry is taken (NOM_CHAM='GEOMETRIE')"),
              text("NOM_CHAM", "Field of RESULTAT, e.g. DEPL, SIGM_ELNO, SIEF_ELGA (compute it with CALC_CHAMP "
                               "first if needed); with MAILLAGE, 'GEOMETRIE': the nodes' X, Y, Z (Z = 0 in 2D), "
                               "TYPE_CHAM='NOEU_GEOM_R'")
                  .required(),
              integer("NUME_ORDRE", "Time step the field is taken at"),
              real("INST", "Time the field is taken at (within 1e-6 relative)")},
             {exactly_one({"RESULTAT", "MAILLAGE"}), present_absent({"MAILLAGE", "NUME_ORDRE", "INST"})}},
       Block{"RESULTAT", {}, {}, {exactly_one({"NUME_ORDRE", "INST"})}},
       Block{"OPERATION", {"AFFE"}, {support("MAILLAGE", true), support("MODELE", false), affe()},
             {exactly_one({"MAILLAGE", "MODELE"})}},
       Block{"OPERATION", {"ASSE"}, {support("MAILLAGE", true), support("MODELE", false), asse()},
             {exactly_one({"MAILLAGE", "MODELE"})}},
       Block{"OPERATION", {"COMB"},
             {factor("COMB",
                     {concept_kw("CHAM_GD", {"cham_gd"}, "Field at nodes (all of the same components)").required(),
                      real("COEF_R", "Its factor").required()},
                     "The terms of the sum COEF_R x CHAM_GD: fields at nodes of the same mesh, type and components; "
                     "the sum is defined where every term is")
                  .occurs(1, -1)
                  .required()},
             {}},
       Block{"OPERATION", {"EVAL"},
             {concept_kw("CHAM_F", {"cham_gd"}, "Field of functions at nodes (AFFE, TYPE_CHAM NOEU_*_F)").required(),
              concept_kw("CHAM_PARA", {"cham_gd"},
                         "Fields at nodes whose components are the functions' parameters by name (X, Y, Z of "
                         "NOEU_GEOM_R; TEMP; ...)")
                  .many()
                  .required()},
             {}}});
  return spec;
}

}  // namespace lunaster::catalog
