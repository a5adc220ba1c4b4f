#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

namespace {

Keyword ddl_impo() {
  return factor("DDL_IMPO",
                {common::tout("Impose on every node"), common::group_no("Node groups to constrain"),
                 common::noeud("Nodes to constrain"), common::group_ma("Constrain the nodes of these cell groups"),
                 real("DX", "Imposed displacement along x (m)"), real("DY", "Imposed displacement along y (m)"),
                 real("DZ", "Imposed displacement along z (m)")},
                "Imposed displacements (Dirichlet conditions)")
      .occurs(0, -1)
      .with_rules({exactly_one({"TOUT", "GROUP_NO", "NOEUD", "GROUP_MA"}), at_least_one({"DX", "DY", "DZ"})});
}

Keyword pres_rep() {
  return factor("PRES_REP",
                {common::group_ma("Boundary cell groups loaded"), common::maille("Boundary cells loaded"),
                 common::tout("Load every boundary cell of the model"),
                 real("PRES", "Pressure (Pa), positive when pushing against the outward normal").required()},
                "Pressure on boundary cells")
      .occurs(0, -1)
      .with_rules({exactly_one({"GROUP_MA", "MAILLE", "TOUT"})});
}

Keyword force_nodale() {
  return factor("FORCE_NODALE",
                {common::group_no("Node groups loaded"), common::noeud("Nodes loaded"),
                 real("FX", "Force along x on each node (N)"), real("FY", "Force along y on each node (N)"),
                 real("FZ", "Force along z on each node (N)")},
                "Point forces on nodes")
      .occurs(0, -1)
      .with_rules({exactly_one({"GROUP_NO", "NOEUD"}), at_least_one({"FX", "FY", "FZ"})});
}

/// FORCE_CONTOUR, FORCE_FACE, FORCE_ARETE: a force density on GROUP_MA / MAILLE cells.
Keyword cell_force(const char* name, const std::string& cells, const std::string& unit, const std::string& doc,
                   bool tout = false) {
  std::vector<Keyword> children = {common::group_ma(cells + " groups loaded"), common::maille(cells + " loaded")};
  if (tout) children.push_back(common::tout("Load every cell of the model"));
  for (const auto& [kw, axis] : {std::pair{"FX", "x"}, {"FY", "y"}, {"FZ", "z"}})
    children.push_back(real(kw, "Force along " + std::string(axis) + " (" + unit + ")"));
  return factor(name, children, doc)
      .occurs(0, -1)
      .with_rules({tout ? exactly_one({"TOUT", "GROUP_MA", "MAILLE"}) : at_least_one({"GROUP_MA", "MAILLE"}),
                   at_least_one({"FX", "FY", "FZ"})});
}

Keyword pesanteur() {
  return factor("PESANTEUR",
                {common::group_ma("Cell groups weighed; absent (and MAILLE absent): every cell of the model"),
                 common::maille("Cells weighed"),
                 real("GRAVITE", "Acceleration of gravity (m/s2)").required(),
                 real("DIRECTION", "Direction of gravity (x, y, z), normalised; in 2D and AXIS z must be 0")
                     .count(3, 3)
                     .required()},
                "Gravity: the force RHO GRAVITE DIRECTION per unit volume of each cell, RHO from its material's "
                "ELAS (a cell whose material has no RHO is an error)")
      .occurs(0, 1);
}

Keyword liaison_ddl() {
  return factor("LIAISON_DDL",
                {text("GROUP_NO", "Node groups, one term per node, in the order given (a group of one node "
                                  "each, as a rule)")
                     .many(),
                 text("NOEUD", "Nodes, one term per node, in the order given (a node may repeat)").many(),
                 text("DDL", "Component of each term").into_values({"DX", "DY", "DZ"}).many().required(),
                 real("COEF_MULT", "Coefficient of each term").many().required(),
                 real("COEF_IMPO", "Right-hand side of the relation (m); follows the load's FONC_MULT").required()},
                "Linear relation sum COEF_MULT(i) u(node i, DDL(i)) = COEF_IMPO between displacement components "
                "(a Lagrange multiplier each; a relation of one term is an imposed displacement)")
      .occurs(0, -1)
      .with_rules({exactly_one({"GROUP_NO", "NOEUD"})});
}

Keyword liaison_unif() {
  return factor("LIAISON_UNIF",
                {common::group_no("Node groups sharing one value of each DDL"),
                 common::group_ma("Cell groups whose nodes share one value of each DDL"),
                 text("DDL", "Components that take one (unknown) value on all these nodes")
                     .into_values({"DX", "DY", "DZ"})
                     .many()
                     .required()},
                "The same unknown value of each DDL on a set of nodes (a linear relation u(node) - u(first "
                "node) = 0 per other node and component)")
      .occurs(0, -1)
      .with_rules({exactly_one({"GROUP_NO", "GROUP_MA"})});
}

Keyword liaison_mail() {
  return factor(
             "LIAISON_MAIL",
             {text("GROUP_MA_MAIT", "Master cell groups: their cells of the model's dimension (volumes in 3D, faces in "
                                    "2D) are those the slave nodes follow")
                  .many()
                  .required(),
              text("GROUP_MA_ESCL", "Cell groups whose nodes are slave nodes").many(),
              text("GROUP_NO_ESCL", "Node groups of slave nodes").many(),
              text("TYPE_RACCORD", "Kind of gluing: solid to solid (each slave node follows the master cell that "
                                   "holds it)")
                  .into_values({"MASSIF"})
                  .def("MASSIF"),
              text("DDL", "Components tied; default: every displacement component of the model. 'DNOR' "
                          "(alone, with GROUP_MA_ESCL's boundary cells): the component along the slave face's "
                          "normal only, so that the faces may slide on each other")
                  .into_values({"DX", "DY", "DZ", "DNOR"})
                  .many(),
              real("DISTANCE_MAX", "Slave nodes farther than this from every master cell are not tied (m); default: "
                                   "every slave node is tied, to the nearest master cell")
                  .range(0.0, std::nullopt),
              real("DISTANCE_ALARME", "A warning counts the slave nodes tied from farther than this outside their "
                                      "master cell (m); default: a tenth of that cell's size")
                  .range(0.0, std::nullopt),
              text("ELIM_MULT", "'OUI': the slave nodes of the earlier LIAISON_MAIL of this AFFE_CHAR_MECA with "
                                "ELIM_MULT = 'OUI' are left out (tied there or not); 'NON': every slave node is tied")
                  .into_values({"OUI", "NON"})
                  .def("OUI"),
              real("TRAN", "Translation (m) added to each slave node's position before it is located in the master "
                           "cells: glues a face to the master cells TRAN away (periodic conditions); one value per "
                           "coordinate of the model")
                  .count(2, 3)},
             "Glue a mesh to another that does not match it (code_aster's LIAISON_MAIL): each slave node follows the "
             "master cell that holds it, or the nearest, u(node) = sum N_a(xi) u_a for each DDL, a linear relation "
             "each (a Lagrange multiplier, or solved for the slave unknown with SOLVEUR ELIM_LAGR = 'OUI')")
      .occurs(0, -1)
      .with_rules({at_least_one({"GROUP_MA_ESCL", "GROUP_NO_ESCL"})});
}

/// The seed's contact syntax (code_aster 8): one zone with the method inside.
Keyword contact() {
  std::vector<Keyword> children = {
      text("METHODE", "Contact method: continuous (augmented Lagrangian), active set (Lagrange) or penalty")
          .into_values({"CONTINUE", "CONTRAINTE", "PENALISATION"})
          .def("CONTINUE"),
      text("GROUP_MA_ESCL", "Slave boundary cell group").required(),
      text("GROUP_MA_MAIT", "Master boundary cell group").required(),
      text("CONTACT_INIT", "Initial contact status: all active, none, or where already interpenetrating")
          .into_values({"OUI", "NON", "INTERPENETRE"}),
      text("MODL_AXIS",
           "Axisymmetric contact: 'OUI' on an AXIS model, 'NON' on a plane or 3D model (it must match MODELE); "
           "absent: follows the model. On an AXIS model every contact measure is r dl per radian")
          .into_values({"OUI", "NON"}),
  };
  for (auto& kw : common::contact_loop_keywords()) children.push_back(kw);
  std::vector<Block> blocks = {
      Block{"METHODE",
            {"CONTINUE"},
            {common::contact_integration(
                 {"AUTO", "GAUSS", "SIMPSON", "SIMPSON1", "SIMPSON2", "NCOTES", "NCOTES1", "NCOTES2", "NOEUD"}),
             real("COEF_REGU_CONT", "Augmentation coefficient of the contact Lagrangian (seed name of COEF_CONT)")
                 .above(0.0),
             real("COEF_CONT", "Augmentation coefficient of the contact Lagrangian").above(0.0),
             common::algo_reso_cont(false)},
            {at_most_one({"COEF_REGU_CONT", "COEF_CONT"})}},
      Block{"METHODE",
            {"CONTRAINTE", "PENALISATION"},
            {common::algo_reso_cont(true), common::iter_cont_mult()},
            {at_most_one({"ITER_CONT_MAXI", "ITER_CONT_MULT"})}},
      Block{"METHODE", {"PENALISATION"}, {real("E_N", "Normal penalty stiffness (Pa/m)").required().above(0.0)}, {}},
  };
  for (auto& block : common::ordre_int_blocks()) blocks.push_back(block);
  return factor("CONTACT", children, "Frictionless contact zone (seed syntax; pass the load in STAT_NON_LINE EXCIT)")
      .with_blocks(blocks);
}

}  // namespace

const CommandSpec& affe_char_meca_spec() {
  static const CommandSpec spec = make_command(
      "AFFE_CHAR_MECA", "char_meca",
      "Define mechanical loads: imposed displacements, linear relations, pressures, forces, gravity, contact",
      {concept_kw("MODELE", {"modele"}, "Model the loads apply to").required(), ddl_impo(), pres_rep(),
       force_nodale(),
       cell_force("FORCE_CONTOUR", "Edge cell (SEG2/SEG3)", "N/m",
                  "Force per unit length on the edges of a 2D or AXIS model (AXIS: per unit length of the "
                  "meridian, integrated over r dl per radian as PRES_REP); refused in 3D"),
       cell_force("FORCE_FACE", "Face cell (TRIA/QUAD)", "N/m2",
                  "Force per unit area on faces of a 3D model; refused in 2D and AXIS"),
       cell_force("FORCE_ARETE", "Edge cell (SEG2/SEG3)", "N/m",
                  "Force per unit length on edges of a 3D model; refused in 2D and AXIS"),
       cell_force("FORCE_INTERNE", "Cell", "N/m3",
                  "Force per unit volume on cells of the model's dimension, every model (AXIS: per unit "
                  "volume, integrated over r dA per radian)",
                  true),
       pesanteur(), liaison_ddl(), liaison_unif(), liaison_mail(), contact(),
       text("VERI_NORM",
            "'OUI': PRES_REP on boundary cells whose normal points into the body they bound is an error, and so "
            "is a group whose cells point both ways (MODI_MAILLAGE ORIE_PEAU_2D / ORIE_PEAU_3D turns them out); "
            "a cell between two cells of the mesh (no outside) or on none is not checked. As code_aster, only "
            "PRES_REP is checked: FORCE_CONTOUR and FORCE_FACE give their components, which do not depend on "
            "the normal's sign. 'NON': each pressure "
            "pushes against its cells' normals as they are")
           .into_values({"OUI", "NON"})
           .def("OUI"),
       common::info()},
      {at_least_one(
          {"DDL_IMPO", "PRES_REP", "FORCE_NODALE", "FORCE_CONTOUR", "FORCE_FACE", "FORCE_ARETE", "FORCE_INTERNE",
           "PESANTEUR", "LIAISON_DDL", "LIAISON_UNIF", "LIAISON_MAIL", "CONTACT"})});
  return spec;
}

}  // namespace lunaster::catalog
