#include "engine/assembly/mesh_part.hpp"

#include <algorithm>
#include <string>

#include "engine/assembly/partition.hpp"
#include "engine/core/error.hpp"
#include "engine/mesh/mesh_bytes.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {

MeshCut cut_mesh(const Mesh& whole, int parts) {
  MeshCut cut;
  cut.parts = parts;
  std::vector<int> volume;
  for (int c = 0; c < whole.n_cells(); ++c)
    if (cell_info(whole.cell_types[c]).dim == whole.dim) volume.push_back(c);
  const Mesh::NodeCells around = whole.node_cells(volume);
  const std::vector<int> parts_of_volume = scotch_cell_parts(whole, volume, whole.dim, parts, around);
  cut.cell_part.assign(whole.n_cells(), -1);
  for (size_t i = 0; i < volume.size(); ++i) cut.cell_part[volume[i]] = parts_of_volume[i];
  cut.node_owner = node_owners(whole.n_nodes(), parts_of_volume, parts, around);
  for (int& owner : cut.node_owner) owner = std::max(owner, 0);
  return cut;
}

namespace {

/// Every cell of `whole` around each node (cell numbers).
Mesh::NodeCells cells_around(const Mesh& whole) {
  std::vector<int> all(whole.n_cells());
  for (int c = 0; c < whole.n_cells(); ++c) all[c] = c;
  return whole.node_cells(all);
}

/// extract_part with the cells around each node computed once for every part.
MeshPart extract(const Mesh& whole, const MeshCut& cut, const Mesh::NodeCells& around, int rank) {
  LUNASTER_ASSERT(static_cast<int>(cut.cell_part.size()) == whole.n_cells() &&
                      static_cast<int>(cut.node_owner.size()) == whole.n_nodes() && rank >= 0 && rank < cut.parts,
                  "extract_part: a cut of another mesh");
  MeshPart part;
  part.rank = rank;
  part.parts = cut.parts;
  part.n_global_nodes = whole.n_nodes();
  part.n_global_cells = whole.n_cells();
  // The cells: its own, and every cell touching a node it owns.
  std::vector<char> in_part(whole.n_cells(), 0);
  for (int c = 0; c < whole.n_cells(); ++c) in_part[c] = cut.cell_part[c] == rank;
  for (int v = 0; v < whole.n_nodes(); ++v)
    if (cut.node_owner[v] == rank)
      for (int p = around.start[v]; p < around.start[v + 1]; ++p) in_part[around.positions[p]] = 1;
  // The nodes: the owned ones (every one, a node in no cell too), then the others of its cells.
  std::vector<int> local(whole.n_nodes(), -1);
  for (int v = 0; v < whole.n_nodes(); ++v)
    if (cut.node_owner[v] == rank) local[v] = static_cast<int>(part.global_node.size()), part.global_node.push_back(v);
  part.n_owned_nodes = static_cast<int>(part.global_node.size());
  std::vector<char> ghost(whole.n_nodes(), 0);
  for (int c = 0; c < whole.n_cells(); ++c)
    if (in_part[c])
      for (int a = 0, nn = whole.cell_n_nodes(c); a < nn; ++a)
        if (local[whole.cell(c)[a]] < 0) ghost[whole.cell(c)[a]] = 1;
  for (int v = 0; v < whole.n_nodes(); ++v)
    if (ghost[v]) local[v] = static_cast<int>(part.global_node.size()), part.global_node.push_back(v);

  Mesh& mesh = part.mesh;
  mesh.dim = whole.dim;
  mesh.name = whole.name;
  const size_t n_local = part.global_node.size();
  mesh.coords.resize(3 * n_local);
  mesh.node_names.resize(n_local);
  part.node_owner.resize(n_local);
  for (size_t i = 0; i < n_local; ++i) {
    const int v = part.global_node[i];
    std::copy(whole.node(v), whole.node(v) + 3, mesh.coords.begin() + 3 * static_cast<long>(i));
    mesh.node_names[i] = whole.node_names[v];
    part.node_owner[i] = cut.node_owner[v];
  }
  std::vector<int> local_cell(whole.n_cells(), -1);
  for (int c = 0; c < whole.n_cells(); ++c) {
    if (!in_part[c]) continue;
    local_cell[c] = mesh.n_cells();
    part.global_cell.push_back(c);
    part.cell_part.push_back(cut.cell_part[c]);
    mesh.cell_types.push_back(whole.cell_types[c]);
    for (int a = 0, nn = whole.cell_n_nodes(c); a < nn; ++a) mesh.cell_nodes.push_back(local[whole.cell(c)[a]]);
    mesh.cell_offsets.push_back(static_cast<int>(mesh.cell_nodes.size()));
    mesh.cell_names.push_back(whole.cell_names[c]);
  }
  for (const auto& [name, members] : whole.node_groups) {
    std::vector<int>& here = mesh.node_groups[name];
    for (int v : members)
      if (local[v] >= 0) here.push_back(local[v]);
    std::sort(here.begin(), here.end());
  }
  for (const auto& [name, members] : whole.cell_groups) {
    std::vector<int>& here = mesh.cell_groups[name];
    for (int c : members)
      if (local_cell[c] >= 0) here.push_back(local_cell[c]);  // ascending: local cells keep the whole order
  }
  return part;
}

}  // namespace

MeshPart extract_part(const Mesh& whole, const MeshCut& cut, int rank) {
  return extract(whole, cut, cells_around(whole), rank);
}

MeshPart distribute_mesh(const Mesh* whole) {
  const int parts = parallel::size(), rank = parallel::rank();
  LUNASTER_ASSERT(rank != 0 || whole != nullptr, "distribute_mesh: rank 0 without the mesh");
  if (parts == 1) return extract_part(*whole, cut_mesh(*whole, 1), 0);
  // Rank 0 cuts; every rank learns whether it could before anyone waits for a part.
  MeshCut cut;
  std::string failure;
  if (rank == 0) {
    try {
      cut = cut_mesh(*whole, parts);
    } catch (const SolveError& e) {
      failure = e.message();
    }
  }
  parallel::broadcast(failure);
  if (!failure.empty()) throw SolveError(failure);
  if (rank == 0) {
    const Mesh::NodeCells around = cells_around(*whole);
    for (int r = 1; r < parts; ++r) {
      const MeshPart part = extract(*whole, cut, around, r);
      const std::vector<int> sizes{part.n_owned_nodes, part.n_global_nodes, part.n_global_cells};
      parallel::send_bytes(r, mesh_to_bytes(part.mesh, {&part.global_node, &part.global_cell, &part.node_owner,
                                                         &part.cell_part, &sizes}));
    }
    return extract(*whole, cut, around, 0);
  }
  MeshPart part;
  std::vector<int> sizes;
  part.mesh = mesh_from_bytes(parallel::receive_bytes(0),
                              {&part.global_node, &part.global_cell, &part.node_owner, &part.cell_part, &sizes});
  LUNASTER_ASSERT(sizes.size() == 3, "distribute_mesh: a part without its sizes");
  part.n_owned_nodes = sizes[0];
  part.n_global_nodes = sizes[1];
  part.n_global_cells = sizes[2];
  part.rank = rank;
  part.parts = parts;
  return part;
}

}  // namespace lunaster::engine
