#include "engine/io/med_reader.hpp"

#include <filesystem>
#include <map>

#include "engine/core/error.hpp"
#include "engine/io/med_common.hpp"
#include "engine/mesh/cell_topology.hpp"

namespace lunaster::engine {

namespace {

using namespace med_detail;

[[noreturn]] void fail(const std::string& path, const std::string& what, std::vector<std::string> hints = {}) {
  throw DeckError("mesh file '" + path + "': " + what, std::move(hints));
}

[[noreturn]] void not_med(const std::string& path) {
  DeckError err("mesh file '" + path + "': not a MED file (no HDF5 signature)", {"this reader reads MED files; .msh files are Gmsh meshes"});
  err.failure().what = Failure::What::NotAMedFile;
  throw err;
}

med_idt open_checked(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a MED file");
  med_bool hdf_ok = MED_FALSE, med_ok = MED_FALSE;
  if (MEDfileCompatibility(path.c_str(), &hdf_ok, &med_ok) < 0 || !hdf_ok)
    not_med(path);
  if (!med_ok) fail(path, "an HDF5 file but not a readable MED file (unsupported version, truncated or corrupt)");
  const med_idt fid = MEDfileOpen(path.c_str(), MED_ACC_RDONLY);
  if (fid < 0) fail(path, "cannot be opened as MED (truncated or corrupt file?)");
  return fid;
}

struct MeshHeader {
  std::string name;
  int space_dim = 0;
  med_mesh_type type = MED_UNSTRUCTURED_MESH;
};

std::vector<MeshHeader> list_meshes(med_idt fid, const std::string& path) {
  const med_int n = MEDnMesh(fid);
  if (n < 0) fail(path, "corrupt MED file (cannot count meshes)");
  std::vector<MeshHeader> meshes;
  for (int i = 1; i <= n; ++i) {
    const med_int n_axis = MEDmeshnAxis(fid, i);
    if (n_axis < 0) fail(path, "corrupt MED file (mesh " + std::to_string(i) + ")");
    char name[MED_NAME_SIZE + 1] = {}, desc[MED_COMMENT_SIZE + 1] = {}, dt_unit[MED_SNAME_SIZE + 1] = {};
    std::vector<char> axis_name(static_cast<size_t>(n_axis) * MED_SNAME_SIZE + 1, '\0');
    std::vector<char> axis_unit(axis_name.size(), '\0');
    med_int space_dim = 0, mesh_dim = 0, n_step = 0;
    med_mesh_type type;
    med_sorting_type sorting;
    med_axis_type axis_type;
    if (MEDmeshInfo(fid, i, name, &space_dim, &mesh_dim, &type, desc, dt_unit, &sorting, &n_step, &axis_type,
                    axis_name.data(), axis_unit.data()) < 0)
      fail(path, "corrupt MED file (cannot read the header of mesh " + std::to_string(i) + ")");
    meshes.push_back({trim_fixed(name, MED_NAME_SIZE), static_cast<int>(space_dim), type});
  }
  return meshes;
}

med_int count_entities(med_idt fid, const std::string& mesh, med_entity_type entity, med_geometry_type geo,
                       med_data_type data, med_connectivity_mode mode) {
  med_bool changed = MED_FALSE, transformed = MED_FALSE;
  return MEDmeshnEntity(fid, mesh.c_str(), MED_NO_DT, MED_NO_IT, entity, geo, data, mode, &changed, &transformed);
}

/// Entity names (empty when the file stores none).
std::vector<std::string> read_names(med_idt fid, const std::string& mesh, med_entity_type entity,
                                    med_geometry_type geo, med_int n, const std::string& path) {
  const med_connectivity_mode mode = entity == MED_NODE ? MED_NO_CMODE : MED_NODAL;
  if (count_entities(fid, mesh, entity, geo, MED_NAME, mode) <= 0) return {};
  std::vector<char> buffer(static_cast<size_t>(n) * MED_SNAME_SIZE + 1, '\0');
  if (MEDmeshEntityNameRd(fid, mesh.c_str(), MED_NO_DT, MED_NO_IT, entity, geo, buffer.data()) < 0)
    fail(path, "corrupt MED file (cannot read entity names)");
  std::vector<std::string> names(n);
  for (med_int i = 0; i < n; ++i) names[i] = trim_fixed(&buffer[static_cast<size_t>(i) * MED_SNAME_SIZE], MED_SNAME_SIZE);
  return names;
}

std::vector<med_int> read_families(med_idt fid, const std::string& mesh, med_entity_type entity,
                                   med_geometry_type geo, med_int n) {
  const med_connectivity_mode mode = entity == MED_NODE ? MED_NO_CMODE : MED_NODAL;
  std::vector<med_int> families(n, 0);
  if (count_entities(fid, mesh, entity, geo, MED_FAMILY_NUMBER, mode) <= 0) return families;
  if (MEDmeshEntityFamilyNumberRd(fid, mesh.c_str(), MED_NO_DT, MED_NO_IT, entity, geo, families.data()) < 0)
    std::fill(families.begin(), families.end(), 0);
  return families;
}

std::map<med_int, std::vector<std::string>> read_family_groups(med_idt fid, const std::string& mesh,
                                                               const std::string& path) {
  std::map<med_int, std::vector<std::string>> groups;
  const med_int n = MEDnFamily(fid, mesh.c_str());
  if (n < 0) fail(path, "corrupt MED file (cannot count families)");
  for (int i = 1; i <= n; ++i) {
    const med_int n_groups = MEDnFamilyGroup(fid, mesh.c_str(), i);
    if (n_groups < 0) fail(path, "corrupt MED file (family " + std::to_string(i) + ")");
    std::vector<char> names(static_cast<size_t>(n_groups) * MED_LNAME_SIZE + 1, '\0');
    char family_name[MED_NAME_SIZE + 1] = {};
    med_int number = 0;
    if (MEDfamilyInfo(fid, mesh.c_str(), i, family_name, &number, names.data()) < 0)
      fail(path, "corrupt MED file (family " + std::to_string(i) + ")");
    for (med_int g = 0; g < n_groups; ++g)
      groups[number].push_back(trim_fixed(&names[static_cast<size_t>(g) * MED_LNAME_SIZE], MED_LNAME_SIZE));
  }
  return groups;
}

void read_nodes(med_idt fid, const MeshHeader& header, const std::string& path, Mesh& mesh,
                std::vector<med_int>& families) {
  const std::string& name = header.name;
  const med_int n = count_entities(fid, name, MED_NODE, MED_NONE, MED_COORDINATE, MED_NO_CMODE);
  if (n < 0) fail(path, "corrupt MED file (cannot count the nodes of mesh '" + name + "')");
  if (n == 0) fail(path, "mesh '" + name + "' has no nodes");
  const int sdim = header.space_dim;
  if (sdim < 1 || sdim > 3) fail(path, "mesh '" + name + "' has space dimension " + std::to_string(sdim));
  std::vector<med_float> xyz(static_cast<size_t>(n) * sdim);
  if (MEDmeshNodeCoordinateRd(fid, name.c_str(), MED_NO_DT, MED_NO_IT, MED_FULL_INTERLACE, xyz.data()) < 0)
    fail(path, "corrupt MED file (cannot read the node coordinates)");
  std::vector<std::string> names = read_names(fid, name, MED_NODE, MED_NONE, n, path);
  // Sized once: growing by doubling copies every array and touches its pages twice.
  mesh.coords.reserve(3 * static_cast<size_t>(n));
  mesh.node_names.reserve(static_cast<size_t>(n));
  for (med_int i = 0; i < n; ++i) {
    double p[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < sdim; ++k) p[k] = xyz[static_cast<size_t>(i) * sdim + k];
    mesh.add_node(p[0], p[1], p[2], names.empty() ? std::string() : std::move(names[i]));
  }
  families = read_families(fid, name, MED_NODE, MED_NONE, n);
}

/// Rejects cell types lunaster does not support, naming them. Probes type by
/// type (files written by other tools, e.g. meshio, lack the attributes that
/// MEDmeshEntityInfo needs), then compares with the number of types stored.
void check_cell_types(med_idt fid, const std::string& mesh, const std::string& path) {
  const std::pair<med_geometry_type, const char*> unsupported[] = {
      {MED_SEG4, "SEG4"},         {MED_TRIA7, "TRIA7"},       {MED_QUAD9, "QUAD9"},
      {MED_OCTA12, "OCTA12"},     {MED_PYRA13, "PYRA13"},     {MED_PENTA18, "PENTA18"},
      {MED_HEXA27, "HEXA27"},     {MED_POLYGON, "POLYGON"},   {MED_POLYGON2, "POLYGON2"},
      {MED_POLYHEDRON, "POLYHEDRON"}};
  const std::vector<std::string> hint{
      "supported: POI1 SEG2 SEG3 TRIA3 TRIA6 QUAD4 QUAD8 TETRA4 TETRA10 PYRAM5 PENTA6 PENTA15 HEXA8 HEXA20"};
  for (const auto& [geo, name] : unsupported) {
    const med_data_type data = geo == MED_POLYHEDRON ? MED_INDEX_FACE : geo >= MED_POLYGON ? MED_INDEX_NODE
                                                                                           : MED_CONNECTIVITY;
    if (count_entities(fid, mesh, MED_CELL, geo, data, MED_NODAL) > 0)
      fail(path, std::string("unsupported cell type ") + name + " in mesh '" + mesh + "'", hint);
  }
  int n_supported = 0;
  for (CellType type : cell_types_in_med_order())
    if (count_entities(fid, mesh, MED_CELL, to_med(type), MED_CONNECTIVITY, MED_NODAL) > 0) ++n_supported;
  const med_int n_types = count_entities(fid, mesh, MED_CELL, MED_GEO_ALL, MED_CONNECTIVITY, MED_NODAL);
  if (n_types > n_supported) fail(path, "unsupported (unknown) cell type in mesh '" + mesh + "'", hint);
}

void read_cells_of_type(med_idt fid, const std::string& name, CellType type, const std::string& path, Mesh& mesh,
                        std::vector<med_int>& families) {
  const med_geometry_type geo = to_med(type);
  const med_int n = count_entities(fid, name, MED_CELL, geo, MED_CONNECTIVITY, MED_NODAL);
  if (n < 0) fail(path, "corrupt MED file (cannot count cells)");
  if (n == 0) return;
  const int nn = cell_info(type).n_nodes;
  const std::string type_name(cell_info(type).name);
  std::vector<med_int> conn(static_cast<size_t>(n) * nn);
  if (MEDmeshElementConnectivityRd(fid, name.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, MED_NODAL,
                                   MED_FULL_INTERLACE, conn.data()) < 0)
    fail(path, "corrupt MED file (cannot read the " + type_name + " connectivity)");
  std::vector<std::string> names = read_names(fid, name, MED_CELL, geo, n, path);
  const size_t cells_after = mesh.cell_types.size() + static_cast<size_t>(n);
  mesh.cell_types.reserve(cells_after);
  mesh.cell_offsets.reserve(cells_after + 1);
  mesh.cell_names.reserve(cells_after);
  mesh.cell_nodes.reserve(mesh.cell_nodes.size() + static_cast<size_t>(n) * nn);
  std::vector<int> nodes(nn);
  for (med_int c = 0; c < n; ++c) {
    for (int k = 0; k < nn; ++k) {
      const med_int node = conn[static_cast<size_t>(c) * nn + k];
      if (node < 1 || node > mesh.n_nodes())
        fail(path, "corrupt MED file: " + type_name + " cell " + std::to_string(c + 1) + " refers to node " +
                       std::to_string(node) + " of " + std::to_string(mesh.n_nodes()));
      nodes[k] = static_cast<int>(node - 1);
    }
    mesh.add_cell(type, nodes, names.empty() ? std::string() : std::move(names[c]));
  }
  const std::vector<med_int> fam = read_families(fid, name, MED_CELL, geo, n);
  families.insert(families.end(), fam.begin(), fam.end());
}

void assign_groups(const std::map<med_int, std::vector<std::string>>& family_groups,
                   const std::vector<med_int>& node_families, const std::vector<med_int>& cell_families, Mesh& mesh) {
  std::map<std::string, std::vector<int>> nodes, cells;
  for (size_t i = 0; i < node_families.size(); ++i) {
    const auto it = family_groups.find(node_families[i]);
    if (node_families[i] == 0 || it == family_groups.end()) continue;
    for (const auto& g : it->second) nodes[g].push_back(static_cast<int>(i));
  }
  for (size_t i = 0; i < cell_families.size(); ++i) {
    const auto it = family_groups.find(cell_families[i]);
    if (cell_families[i] == 0 || it == family_groups.end()) continue;
    for (const auto& g : it->second) cells[g].push_back(static_cast<int>(i));
  }
  for (const auto& [g, list] : nodes) mesh.add_to_node_group(g, list);
  for (const auto& [g, list] : cells) mesh.add_to_cell_group(g, list);
}

const MeshHeader& select_mesh(const std::vector<MeshHeader>& meshes, const std::string& wanted,
                              const std::string& path) {
  if (meshes.empty()) fail(path, "the file holds no mesh");
  if (wanted.empty()) return meshes.front();
  std::string available;
  for (const auto& m : meshes) {
    if (m.name == wanted) return m;
    available += (available.empty() ? "" : ", ") + ("'" + m.name + "'");
  }
  fail(path, "no mesh named '" + wanted + "'", {"meshes in this file: " + available});
}

}  // namespace

Mesh read_med(const std::string& path, const std::string& mesh_name) {
  MedFile file(open_checked(path));
  const med_idt fid = file.id();
  const MeshHeader header = select_mesh(list_meshes(fid, path), mesh_name, path);
  if (header.type != MED_UNSTRUCTURED_MESH) fail(path, "mesh '" + header.name + "' is structured (not supported)");
  Mesh mesh;
  mesh.name = header.name;
  std::vector<med_int> node_families, cell_families;
  read_nodes(fid, header, path, mesh, node_families);
  check_cell_types(fid, header.name, path);
  for (CellType type : cell_types_in_med_order())
    read_cells_of_type(fid, header.name, type, path, mesh, cell_families);
  if (mesh.n_cells() == 0) fail(path, "mesh '" + header.name + "' has no cells");
  assign_groups(read_family_groups(fid, header.name, path), node_families, cell_families, mesh);
  mesh.detect_dimension();
  return mesh;
}

std::vector<std::string> med_mesh_names(const std::string& path) {
  MedFile file(open_checked(path));
  std::vector<std::string> names;
  for (const auto& m : list_meshes(file.id(), path)) names.push_back(m.name);
  return names;
}

namespace {

struct FieldHeader {
  std::string name;
  std::vector<std::string> components;
  med_int n_steps = 0;
};

std::vector<FieldHeader> list_fields(med_idt fid, const std::string& path) {
  const med_int n = MEDnField(fid);
  if (n < 0) fail(path, "corrupt MED file (cannot count fields)");
  std::vector<FieldHeader> fields;
  for (int i = 1; i <= n; ++i) {
    const med_int n_cmp = MEDfieldnComponent(fid, i);
    if (n_cmp < 0) fail(path, "corrupt MED file (field " + std::to_string(i) + ")");
    char name[MED_NAME_SIZE + 1] = {}, mesh[MED_NAME_SIZE + 1] = {}, dt_unit[MED_SNAME_SIZE + 1] = {};
    std::vector<char> cmp(static_cast<size_t>(n_cmp) * MED_SNAME_SIZE + 1, '\0'), unit(cmp.size(), '\0');
    med_bool local = MED_TRUE;
    med_field_type type;
    FieldHeader h;
    if (MEDfieldInfo(fid, i, name, mesh, &local, &type, cmp.data(), unit.data(), dt_unit, &h.n_steps) < 0)
      fail(path, "corrupt MED file (field " + std::to_string(i) + ")");
    h.name = trim_fixed(name, MED_NAME_SIZE);
    for (med_int k = 0; k < n_cmp; ++k)
      h.components.push_back(trim_fixed(&cmp[static_cast<size_t>(k) * MED_SNAME_SIZE], MED_SNAME_SIZE));
    fields.push_back(std::move(h));
  }
  return fields;
}

}  // namespace

std::vector<std::string> med_field_names(const std::string& path) {
  MedFile file(open_checked(path));
  std::vector<std::string> names;
  for (const auto& f : list_fields(file.id(), path)) names.push_back(f.name);
  return names;
}

std::vector<MedNodalStep> read_med_nodal_field(const std::string& path, const std::string& field_name) {
  MedFile file(open_checked(path));
  const med_idt fid = file.id();
  for (const auto& h : list_fields(fid, path)) {
    if (h.name != field_name) continue;
    std::vector<MedNodalStep> steps;
    for (int cs = 1; cs <= h.n_steps; ++cs) {
      MedNodalStep step;
      med_int numdt = 0, numit = 0;
      med_float dt = 0.0;
      if (MEDfieldComputingStepInfo(fid, field_name.c_str(), cs, &numdt, &numit, &dt) < 0)
        fail(path, "corrupt field '" + field_name + "'");
      const med_int n = MEDfieldnValue(fid, field_name.c_str(), numdt, numit, MED_NODE, MED_NONE);
      if (n <= 0) continue;
      step.numdt = static_cast<int>(numdt);
      step.time = dt;
      step.field = NodalField(h.components, static_cast<int>(n));
      if (MEDfieldValueRd(fid, field_name.c_str(), numdt, numit, MED_NODE, MED_NONE, MED_FULL_INTERLACE,
                          MED_ALL_CONSTITUENT, reinterpret_cast<unsigned char*>(step.field.values.data())) < 0)
        fail(path, "corrupt values of field '" + field_name + "'");
      std::fill(step.field.defined.begin(), step.field.defined.end(), 1);
      steps.push_back(std::move(step));
    }
    return steps;
  }
  fail(path, "no field named '" + field_name + "'");
}

}  // namespace lunaster::engine
