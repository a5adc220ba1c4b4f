#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& lire_maillage_spec() {
  static const CommandSpec spec = make_command(
      "LIRE_MAILLAGE", "maillage", "Read a mesh from a MED, Gmsh or code_aster text (.mail) file",
      {integer("UNITE", "Logical unit: 20 reads <deck name>.med (.msh, .mail) beside the deck; under an .export, "
               "the unit of its 'F mmed|msh|mail' line").def(20LL).range(1, 99),
       text("FORMAT", "File format: MED, GMSH, or ASTER (code_aster's text format, .mail; nodes and cells keep "
                     "their names)")
           .into_values({"MED", "GMSH", "ASTER"})
           .def("MED"),
       text("FICHIER", "Mesh file path, relative to the deck (overrides UNITE)"),
       text("NOM_MED", "Name of the mesh inside the MED file (default: the first one)"),
       text("PARTITIONNEUR", "Read the mesh in parts, one per MPI rank (cut by Scotch on rank 0): each rank "
                             "holds its cells, a ghost layer and their nodes (and the contact surfaces and the "
                             "linear relations' nodes whole); linear elasticity, contact, LIAISON_DDL and "
                             "LIAISON_UNIF, not LIAISON_MAIL")
           .into_values({"PTSCOTCH"}),
       factor("VERI_MAIL",
              {text("VERIF", "OUI: the checks below, as warnings; NON: none (not even the warning on nodes in no cell)")
                   .into_values({"OUI", "NON"})
                   .def("OUI"),
               real("APLAT", "A cell is flat when its shortest distance between two nodes is below APLAT times its "
                             "longest")
                   .above(0.0)
                   .def(1.0e-3)},
              "Mesh checks after reading, as warnings: nodes in no cell, cells on the same nodes, cells listing a "
              "node twice, flat cells (without VERI_MAIL: nodes in no cell only)"),
       common::info()});
  return spec;
}

}  // namespace lunaster::catalog
