#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& impr_table_spec() {
  static const CommandSpec spec = make_command(
      "IMPR_TABLE", "", "Write a table to a text file in the output folder (aligned columns, or CSV with SEPARATEUR)",
      {concept_kw("TABLE", {"table"}, "Table to write").required(),
       text("FORMAT", "File format: code_aster's TABLEAU text table").into_values({"TABLEAU"}).def("TABLEAU"),
       integer("UNITE", "Logical unit: 8 writes <deck name>_8.tab; several IMPR_TABLE on one unit append")
           .def(8LL)
           .range(1, 99),
       text("FICHIER", "Output file name inside the output folder (overrides UNITE)"),
       text("NOM_PARA", "Parameters written, in this order (default: all)").many(),
       text("SEPARATEUR",
            "Column separator: ' ' aligns the columns; any other (',' or ';') writes unpadded cells, a CSV file")
           .def(" "),
       text("COMMENTAIRE", "Prefix of the comment lines above the table").def("#"),
       text("FORMAT_R", "Fortran-like format of reals: E12.5 (default), F12.3, G15.8 ...").def("E12.5")});
  return spec;
}

}  // namespace lunaster::catalog
