#include "tools/aster_mail_writer.hpp"

#include <iomanip>
#include <sstream>

#include "engine/core/error.hpp"
#include "engine/io/aster_mail_reader.hpp"
#include "engine/io/atomic_file.hpp"

namespace lunaster::tools {

namespace {

const std::string& checked(const std::string& name, const char* what) {
  if (name.empty() || name.size() > 24 || name.find_first_of(" \t%=,") != std::string::npos)
    throw DeckError("write_aster_mail: " + std::string(what) + " name '" + name +
                    "' cannot be written in code_aster's text format (1 to 24 characters, no blank, %, = or ,)");
  return name;
}

/// Names, eight to a line.
void write_names(std::ostringstream& os, const std::vector<int>& items, const std::vector<std::string>& names,
                 const char* what) {
  for (size_t k = 0; k < items.size(); ++k)
    os << (k % 8 == 0 ? "\n  " : " ") << checked(names[items[k]], what);
  os << "\n";
}

}  // namespace

void write_aster_mail(const std::string& path, const engine::Mesh& mesh) {
  std::ostringstream os;
  os << std::setprecision(16);  // a node of COOR_3D within code_aster's 80 columns
  os << "TITRE\n" << mesh.name << "\nFINSF\n%\n" << (mesh.dim == 2 ? "COOR_2D" : "COOR_3D") << "\n";
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    os << "  " << checked(mesh.node_names[n], "node");
    for (int k = 0; k < mesh.dim; ++k) os << " " << mesh.coords[3 * n + k];
    os << "\n";
  }
  os << "FINSF\n";
  for (int t = 0; t < engine::kCellTypeCount; ++t) {
    const auto type = static_cast<engine::CellType>(t);
    bool open = false;
    const auto& order = engine::aster_to_med_order(type);
    for (int c = 0; c < mesh.n_cells(); ++c) {
      if (mesh.cell_types[c] != type) continue;
      if (!open) os << "%\n" << engine::cell_info(type).name << "\n";
      open = true;
      os << "  " << checked(mesh.cell_names[c], "cell");
      const int* nodes = mesh.cell(c);
      const int n = mesh.cell_n_nodes(c);
      for (int k = 0; k < n; ++k) {  // aster[k] = med[order[k]]
        os << ((k + 1) % 8 == 0 ? "\n     " : " ") << mesh.node_names[nodes[order.empty() ? k : order[k]]];
      }
      os << "\n";
    }
    if (open) os << "FINSF\n";
  }
  for (const auto& [name, nodes] : mesh.node_groups) {
    os << "%\nGROUP_NO NOM=" << checked(name, "group");
    write_names(os, nodes, mesh.node_names, "node");
    os << "FINSF\n";
  }
  for (const auto& [name, cells] : mesh.cell_groups) {
    os << "%\nGROUP_MA NOM=" << checked(name, "group");
    write_names(os, cells, mesh.cell_names, "cell");
    os << "FINSF\n";
  }
  os << "FIN\n";
  engine::write_file_atomically(path, [&](std::ostream& out) { out << os.str(); });
}

}  // namespace lunaster::tools
