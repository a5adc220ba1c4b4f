#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

const std::vector<std::string> kNodeSources = {"TOUT_GROUP_MA", "GROUP_MA", "GROUP_NO", "NOEUD", "INTERSEC", "UNION", "DIFFE"};

Keyword point(const std::string& what) {
  return real("POINT", what + ": its coordinates, as many as the mesh's dimension (2 or 3)").count(2, 3);
}
Keyword precision(const std::string& what) {
  return real("PRECISION", what).above(0.0);
}

Keyword crea_group_no() {
  const std::string not_offered = "not offered by lunaster";
  std::vector<Keyword> children = {
      common::group_ma("Cell groups whose nodes form node groups of the same name (or NOM); with "
                       "OPTION='NOEUD_ORDO', the line cells (SEG2, SEG3) whose nodes are taken"),
      common::group_no("Node groups merged into NOM; with OPTION='SEGM_DROI_ORDO', the nodes checked to lie on "
                       "the segment"),
      common::noeud("Nodes of the new group (with NOM); with OPTION='SEGM_DROI_ORDO', as GROUP_NO"),
      text("TOUT_GROUP_MA", "Create a node group for every cell group").into_values({"OUI"}),
      text("INTERSEC", "Node groups: the new group NOM holds the nodes they all share").many(),
      text("UNION", "Node groups: the new group NOM holds the nodes of any of them").many(),
      text("DIFFE", "Node groups: the new group NOM holds the nodes of the first that none of the others holds")
          .many(),
      text("NOM", "Name of the new node group (with GROUP_MA: one name per group, or one for them all)").many(),
      text("CRIT_NOEUD", "With GROUP_MA: which nodes of the cells: TOUS (all), SOMMET (the corners), MILIEU (the "
                         "mid-side nodes of quadratic cells), CENTRE (the centre nodes: lunaster's cells have none)")
          .into_values({"TOUS", "SOMMET", "MILIEU", "CENTRE"})
          .def("TOUS"),
      text("OPTION",
           "Nodes chosen by geometry: PLAN (within PRECISION of the plane, a line in 2D, through POINT normal to "
           "VECT_NORMALE), ENV_SPHERE (at RAYON +- PRECISION from POINT: a circle in 2D), ENV_CYLINDRE (at RAYON "
           "+- PRECISION from the axis through POINT along VECT_NORMALE, 3D), SEGM_DROI_ORDO (the nodes of "
           "GROUP_NO/NOEUD, which must lie on the segment from GROUP_NO_ORIG to GROUP_NO_EXTR), NOEUD_ORDO (the "
           "nodes of the line of cells GROUP_MA, from GROUP_NO_ORIG to GROUP_NO_EXTR). lunaster's node groups "
           "are sets, in the mesh's order: the order along the segment or line that code_aster keeps (for "
           "POST_RELEVE_T's rows) is checked and logged, not kept")
          .into_values({"PLAN", "ENV_SPHERE", "ENV_CYLINDRE", "SEGM_DROI_ORDO", "NOEUD_ORDO"})
          .refuse("TUNNEL", not_offered)
          .refuse("INCLUSION", not_offered)
          .refuse("FISS_XFEM", "lunaster has no XFEM")
          .refuse("INTERVALLE_VALE", not_offered)
          .refuse("RELA_CINE_BP", "lunaster has no prestressing cables"),
  };
  std::vector<Block> blocks = {
      Block{"OPTION", {"PLAN"},
            {point("A point of the plane").required(),
             real("VECT_NORMALE", "The plane's normal (2 or 3 components)").count(2, 3).required(),
             precision("Largest distance of a node to the plane").required()},
            {present_absent({"OPTION", "GROUP_MA", "GROUP_NO", "NOEUD"})}},
      Block{"OPTION", {"ENV_SPHERE"},
            {point("The sphere's centre").required(), real("RAYON", "The sphere's radius").above(0.0).required(),
             precision("Largest difference of a node's distance to POINT with RAYON").required()},
            {present_absent({"OPTION", "GROUP_MA", "GROUP_NO", "NOEUD"})}},
      Block{"OPTION", {"ENV_CYLINDRE"},
            {point("A point of the axis").required(), real("VECT_NORMALE", "The axis' direction").count(3, 3).required(),
             real("RAYON", "The cylinder's radius").above(0.0).required(),
             precision("Largest difference of a node's distance to the axis with RAYON").required()},
            {present_absent({"OPTION", "GROUP_MA", "GROUP_NO", "NOEUD"})}},
      Block{"OPTION", {"SEGM_DROI_ORDO"},
            {text("GROUP_NO_ORIG", "One-node group: the segment's origin").required(),
             text("GROUP_NO_EXTR", "One-node group: the segment's end").required(),
             precision("Largest distance of a node to the segment's line (CRITERE='RELATIF': relative to the "
                       "segment's length)")
                 .required(),
             text("CRITERE", "PRECISION absolute or relative to the segment's length")
                 .into_values({"ABSOLU", "RELATIF"})
                 .required()},
            {at_least_one({"GROUP_NO", "NOEUD"}), present_absent({"OPTION", "GROUP_MA"})}},
      Block{"OPTION", {"NOEUD_ORDO"},
            {text("GROUP_NO_ORIG", "One-node group: where the line starts (an end of an open line; absent: one of "
                                   "its ends)"),
             text("GROUP_NO_EXTR", "One-node group: where it stops (absent: the other end)")},
            {present_present({"OPTION", "GROUP_MA"}), present_absent({"OPTION", "GROUP_NO", "NOEUD"})}},
  };
  std::vector<Rule> rules = {at_most_one(kNodeSources)};
  std::vector<std::string> any = kNodeSources;
  any.push_back("OPTION");
  rules.push_back(at_least_one(any));
  for (const char* source : {"NOEUD", "GROUP_NO", "INTERSEC", "UNION", "DIFFE", "OPTION"})
    rules.push_back(present_present({source, "NOM"}));
  for (const char* option_free : {"TOUT_GROUP_MA", "INTERSEC", "UNION", "DIFFE"})
    rules.push_back(present_absent({"OPTION", option_free}));
  return factor("CREA_GROUP_NO", children, "Create node groups").occurs(0, -1).with_rules(rules).with_blocks(blocks);
}

}  // namespace

const CommandSpec& defi_group_spec() {
  static const CommandSpec spec = make_command(
      "DEFI_GROUP", "maillage", "Create node or cell groups in a mesh",
      {concept_kw("MAILLAGE", {"maillage"}, "Mesh to enrich").required(),
       crea_group_no(),
       factor("CREA_GROUP_MA",
              {text("NOM", "Name of the new cell group").required(), common::group_ma("Cell groups to merge"),
               common::maille("Cells of the new group"), common::tout("Every cell of the mesh"),
               text("INTERSEC", "Cell groups: the new group holds the cells they all share").many(),
               text("UNION", "Cell groups: the new group holds the cells of any of them").many(),
               text("DIFFE", "Cell groups: the new group holds the cells of the first that none of the others holds")
                   .many()},
              "Create cell groups")
           .occurs(0, -1)
           .with_rules({exactly_one({"GROUP_MA", "MAILLE", "TOUT", "INTERSEC", "UNION", "DIFFE"})}),
       common::info()},
      {at_least_one({"CREA_GROUP_NO", "CREA_GROUP_MA"})}, {}, true);
  return spec;
}

}  // namespace lunaster::catalog
