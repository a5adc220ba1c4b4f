#include "engine/io/med_writer.hpp"

#include <filesystem>
#include <map>
#include <set>

#include "engine/core/error.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/med_common.hpp"
#include "engine/mesh/cell_topology.hpp"

namespace lunaster::engine {

namespace {

using namespace med_detail;

class MedWriter {
 public:
  MedWriter(med_idt fid, const std::string& path, const Mesh& mesh) : fid_(fid), path_(path), mesh_(mesh) {}
  void write_mesh();
  void write_result(const MedResult& result);

 private:
  [[noreturn]] void fail(const std::string& what) const { throw DeckError("writing '" + path_ + "': " + what); }
  void check(med_err rc, const std::string& what) const {
    if (rc < 0) fail("MED library error while writing " + what);
  }
  std::string fixed_names(const std::vector<std::string>& names, size_t width, const std::string& what) const;
  void write_families();
  void write_nodal(const std::string& name, const ResultStep& step, const NodalField& field);
  void write_elno(const std::string& name, const ResultStep& step, const ElnoField& field);
  void write_elga(const std::string& name, const ResultStep& step, const ElgaField& field);
  std::string localization(CellType type, const PointLayout& layout);
  struct TypeRows {
    std::vector<med_float> values;
    std::vector<med_int> profile;
    int n_type_cells = 0;
  };
  TypeRows type_rows(const std::string& name, const ElnoField& field, CellType type, const char* kind, int expected,
                     const char* unit) const;
  void create_field(const std::string& name, const std::vector<std::string>& components);

  med_idt fid_;
  std::string path_;
  const Mesh& mesh_;
  std::vector<med_int> node_family_, cell_family_;
  std::map<std::string, std::vector<std::string>> created_fields_;
  std::map<std::string, PointLayout> localizations_;
  int n_profiles_ = 0;
};

std::string MedWriter::fixed_names(const std::vector<std::string>& names, size_t width, const std::string& what) const {
  std::string out;
  out.reserve(names.size() * width + 1);
  for (const auto& n : names)
    if (!append_fixed(out, n, width))
      fail(what + " name '" + n + "' is longer than " + std::to_string(width) + " characters (MED limit)");
  return out;
}

/// Families: one per distinct set of groups, numbered 1.. (nodes), -1.. (cells).
void MedWriter::write_families() {
  auto build = [](int n, const std::map<std::string, std::vector<int>>& groups, int sign,
                  std::vector<med_int>& family, std::map<std::vector<std::string>, int>& families) {
    std::vector<std::vector<std::string>> member(n);
    for (const auto& [g, list] : groups)
      for (int i : list) member[i].push_back(g);
    family.assign(n, 0);
    for (int i = 0; i < n; ++i) {
      if (member[i].empty()) continue;
      auto it = families.find(member[i]);
      if (it == families.end()) it = families.emplace(member[i], sign * static_cast<int>(families.size() + 1)).first;
      family[i] = it->second;
    }
  };
  std::map<std::vector<std::string>, int> node_fams, cell_fams;
  build(mesh_.n_nodes(), mesh_.node_groups, 1, node_family_, node_fams);
  build(mesh_.n_cells(), mesh_.cell_groups, -1, cell_family_, cell_fams);
  check(MEDfamilyCr(fid_, mesh_.name.c_str(), "FAMILLE_ZERO", 0, 0, ""), "family 0");
  for (const auto* fams : {&node_fams, &cell_fams}) {
    for (const auto& [groups, number] : *fams) {
      const std::string names = fixed_names(groups, MED_LNAME_SIZE, "group");
      const std::string fam_name = "FAM_" + std::to_string(number);
      check(MEDfamilyCr(fid_, mesh_.name.c_str(), fam_name.c_str(), number, static_cast<med_int>(groups.size()),
                        names.c_str()),
            "family " + fam_name);
    }
  }
}

void MedWriter::write_mesh() {
  const char* m = mesh_.name.c_str();
  if (mesh_.name.empty() || mesh_.name.size() > MED_NAME_SIZE) fail("invalid mesh name '" + mesh_.name + "'");
  const int sdim = mesh_.dim == 2 ? 2 : 3;
  std::string axis_names, axis_units;
  for (const char* a : {"X", "Y", "Z"}) {
    if (static_cast<int>(axis_names.size()) >= sdim * MED_SNAME_SIZE) break;
    append_fixed(axis_names, a, MED_SNAME_SIZE);
    append_fixed(axis_units, "m", MED_SNAME_SIZE);
  }
  check(MEDmeshCr(fid_, m, sdim, mesh_.dim, MED_UNSTRUCTURED_MESH, "lunaster", "s", MED_SORT_DTIT, MED_CARTESIAN,
                  axis_names.c_str(), axis_units.c_str()),
        "the mesh header");
  std::vector<med_float> xyz;
  xyz.reserve(static_cast<size_t>(mesh_.n_nodes()) * sdim);
  for (int i = 0; i < mesh_.n_nodes(); ++i)
    for (int k = 0; k < sdim; ++k) xyz.push_back(mesh_.node(i)[k]);
  check(MEDmeshNodeCoordinateWr(fid_, m, MED_NO_DT, MED_NO_IT, 0.0, MED_FULL_INTERLACE, mesh_.n_nodes(), xyz.data()),
        "the coordinates");
  check(MEDmeshEntityNameWr(fid_, m, MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, mesh_.n_nodes(),
                            fixed_names(mesh_.node_names, MED_SNAME_SIZE, "node").c_str()),
        "the node names");
  write_families();
  check(MEDmeshEntityFamilyNumberWr(fid_, m, MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, mesh_.n_nodes(),
                                    node_family_.data()),
        "the node families");
  for (CellType type : cell_types_in_med_order()) {
    std::vector<med_int> conn, fam;
    std::vector<std::string> names;
    for (int c = 0; c < mesh_.n_cells(); ++c) {
      if (mesh_.cell_types[c] != type) continue;
      for (int k = 0; k < mesh_.cell_n_nodes(c); ++k) conn.push_back(mesh_.cell(c)[k] + 1);
      fam.push_back(cell_family_[c]);
      names.push_back(mesh_.cell_names[c]);
    }
    if (names.empty()) continue;
    const med_geometry_type geo = to_med(type);
    const med_int n = static_cast<med_int>(names.size());
    const std::string what = std::string(cell_info(type).name) + " cells";
    check(MEDmeshElementConnectivityWr(fid_, m, MED_NO_DT, MED_NO_IT, 0.0, MED_CELL, geo, MED_NODAL,
                                       MED_FULL_INTERLACE, n, conn.data()),
          what);
    check(MEDmeshEntityNameWr(fid_, m, MED_NO_DT, MED_NO_IT, MED_CELL, geo, n,
                              fixed_names(names, MED_SNAME_SIZE, "cell").c_str()),
          what);
    check(MEDmeshEntityFamilyNumberWr(fid_, m, MED_NO_DT, MED_NO_IT, MED_CELL, geo, n, fam.data()), what);
  }
}

void MedWriter::create_field(const std::string& name, const std::vector<std::string>& components) {
  const auto it = created_fields_.find(name);
  if (it != created_fields_.end()) {
    if (it->second != components)
      throw InternalError("MED field '" + name + "' written with different components in two steps");
    return;
  }
  if (name.size() > MED_NAME_SIZE) fail("field name '" + name + "' is longer than 64 characters");
  std::vector<std::string> units(components.size(), "");
  check(MEDfieldCr(fid_, name.c_str(), MED_FLOAT64, static_cast<med_int>(components.size()),
                   fixed_names(components, MED_SNAME_SIZE, "component").c_str(),
                   fixed_names(units, MED_SNAME_SIZE, "unit").c_str(), "s", mesh_.name.c_str()),
        "field " + name);
  created_fields_.emplace(name, components);
}

void MedWriter::write_nodal(const std::string& name, const ResultStep& step, const NodalField& field) {
  if (field.n_nodes != mesh_.n_nodes())
    throw InternalError("nodal field '" + name + "' has " + std::to_string(field.n_nodes) + " nodes, mesh has " +
                        std::to_string(mesh_.n_nodes()));
  create_field(name, field.components);
  std::vector<med_float> values(field.values.begin(), field.values.end());
  for (size_t k = 0; k < values.size(); ++k)
    if (!field.defined[k]) values[k] = 0.0;
  check(MEDfieldValueWr(fid_, name.c_str(), step.nume_ordre, MED_NO_IT, step.inst, MED_NODE, MED_NONE,
                        MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, field.n_nodes,
                        reinterpret_cast<const unsigned char*>(values.data())),
        "field " + name);
}

/// The rows of `field` on the cells of `type` in file order, `expected` rows per cell (InternalError
/// otherwise), the 1-based positions among the type's cells of those carrying rows (a profile)
/// and the type's cell count.
MedWriter::TypeRows MedWriter::type_rows(const std::string& name, const ElnoField& field, CellType type,
                                         const char* kind, int expected, const char* unit) const {
  TypeRows out;
  const int nc = field.n_components();
  for (int c = 0; c < mesh_.n_cells(); ++c) {
    if (mesh_.cell_types[c] != type) continue;
    ++out.n_type_cells;
    const int rows = field.n_rows(c);
    if (rows == 0) continue;
    if (rows != expected)
      throw InternalError(std::string(kind) + " field '" + name + "': cell " + mesh_.cell_names[c] + " has " +
                          std::to_string(rows) + " rows for " + std::to_string(expected) + " " + unit);
    out.profile.push_back(out.n_type_cells);
    for (int r = 0; r < rows; ++r)
      for (int k = 0; k < nc; ++k) out.values.push_back(field.value(c, r, k));
  }
  return out;
}

void MedWriter::write_elno(const std::string& name, const ResultStep& step, const ElnoField& field) {
  if (field.n_cells() != mesh_.n_cells())
    throw InternalError("ELNO field '" + name + "' has " + std::to_string(field.n_cells()) + " cells, mesh has " +
                        std::to_string(mesh_.n_cells()));
  create_field(name, field.components);
  for (CellType type : cell_types_in_med_order()) {
    auto [values, profile, position] = type_rows(name, field, type, "ELNO", cell_info(type).n_nodes, "nodes");
    if (profile.empty()) continue;
    const med_geometry_type geo = to_med(type);
    const auto* data = reinterpret_cast<const unsigned char*>(values.data());
    const med_int n = static_cast<med_int>(profile.size());
    if (static_cast<int>(profile.size()) == position) {
      check(MEDfieldValueWr(fid_, name.c_str(), step.nume_ordre, MED_NO_IT, step.inst, MED_NODE_ELEMENT, geo,
                            MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, n, data),
            "field " + name);
      continue;
    }
    const std::string pname = "PROFIL_" + std::to_string(++n_profiles_);
    check(MEDprofileWr(fid_, pname.c_str(), n, profile.data()), "profile " + pname);
    check(MEDfieldValueWithProfileWr(fid_, name.c_str(), step.nume_ordre, MED_NO_IT, step.inst, MED_NODE_ELEMENT,
                                     geo, MED_COMPACT_STMODE, pname.c_str(), MED_NO_LOCALIZATION,
                                     MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, n, data),
          "field " + name);
  }
}

/// The MED localization of a cell type's points, written on first use ("<TYPE>_<n> points").
std::string MedWriter::localization(CellType type, const PointLayout& layout) {
  const int n_points = static_cast<int>(layout.weights.size());
  const std::string name = std::string(cell_info(type).name) + "_" + std::to_string(n_points) + "_POINTS";
  const auto it = localizations_.find(name);
  if (it != localizations_.end()) {
    if (it->second.points != layout.points || it->second.weights != layout.weights)
      throw InternalError("ELGA fields with two point layouts of one cell type (" + name + ")");
    return name;
  }
  check(MEDlocalizationWr(fid_, name.c_str(), to_med(type), layout.dim, layout.nodes.data(), MED_FULL_INTERLACE,
                          n_points, layout.points.data(), layout.weights.data(), MED_NO_INTERPOLATION,
                          MED_NO_MESH_SUPPORT),
        "localization " + name);
  localizations_.emplace(name, layout);
  return name;
}

void MedWriter::write_elga(const std::string& name, const ResultStep& step, const ElgaField& field) {
  if (field.n_cells() != mesh_.n_cells())
    throw InternalError("ELGA field '" + name + "' has " + std::to_string(field.n_cells()) + " cells, mesh has " +
                        std::to_string(mesh_.n_cells()));
  create_field(name, field.components);
  for (CellType type : cell_types_in_med_order()) {
    const auto layout = field.layouts.find(type);
    const int n_points = layout == field.layouts.end() ? -1 : static_cast<int>(layout->second.weights.size());
    auto [values, profile, position] = type_rows(name, field, type, "ELGA", n_points, "points");
    if (profile.empty()) continue;
    const std::string loc = localization(type, field.layouts.at(type));
    std::string pname = MED_ALLENTITIES_PROFILE;
    const med_int n = static_cast<med_int>(profile.size());
    if (static_cast<int>(profile.size()) != position) {
      pname = "PROFIL_" + std::to_string(++n_profiles_);
      check(MEDprofileWr(fid_, pname.c_str(), n, profile.data()), "profile " + pname);
    }
    check(MEDfieldValueWithProfileWr(fid_, name.c_str(), step.nume_ordre, MED_NO_IT, step.inst, MED_CELL, to_med(type),
                                     MED_COMPACT_STMODE, pname.c_str(), loc.c_str(), MED_FULL_INTERLACE,
                                     MED_ALL_CONSTITUENT, n, reinterpret_cast<const unsigned char*>(values.data())),
          "field " + name);
  }
}

void MedWriter::write_result(const MedResult& result) {
  if (!result.steps) return;
  for (const ResultStep& step : *result.steps) {
    for (const auto& [field, values] : step.nodal) write_nodal(med_field_name(result.name, field), step, values);
    for (const auto& [field, values] : step.elno) write_elno(med_field_name(result.name, field), step, values);
    for (const auto& [field, values] : step.elga) write_elga(med_field_name(result.name, field), step, values);
  }
}

}  // namespace

std::string med_field_name(const std::string& result, const std::string& field) {
  std::string prefix = result;
  if (prefix.size() < 8) prefix.append(8 - prefix.size(), '_');
  else prefix += '_';
  return prefix + field;
}

void write_med(const std::string& path, const Mesh& mesh, const std::vector<MedResult>& results) {
  replace_file_atomically(path, [&](const std::filesystem::path& temp) {
    MedFile file(MEDfileOpen(temp.c_str(), MED_ACC_CREAT));
    if (!file.ok()) throw DeckError("writing '" + path + "': cannot create a file in " + temp.parent_path().string());
    MedWriter writer(file.id(), path, mesh);
    writer.write_mesh();
    for (const auto& r : results) writer.write_result(r);
    if (!file.close()) throw DeckError("writing '" + path + "': closing the MED file failed");
  });
}

}  // namespace lunaster::engine
