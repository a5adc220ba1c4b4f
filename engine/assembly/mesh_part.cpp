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


SurfacePart with_whole_surfaces(const MeshPart& part, const std::vector<std::vector<int>>& lists,
                                const std::vector<char>& layered) {
  const Mesh& mesh = part.mesh;
  // Each list's cells over the ranks, in the whole mesh's numbers.
  std::vector<int> mine;
  for (const std::vector<int>& list : lists) {
    mine.push_back(static_cast<int>(list.size()));
    for (int c : list) mine.push_back(part.global_cell[c]);
  }
  const std::vector<int> all_lists = parallel::gather_all(mine);
  std::vector<std::vector<int>> wholes(lists.size());
  for (size_t at = 0; at < all_lists.size();)
    for (std::vector<int>& whole : wholes) {
      const int n = all_lists[at++];
      whole.insert(whole.end(), all_lists.begin() + at, all_lists.begin() + at + n);
      at += n;
    }
  for (std::vector<int>& whole : wholes) {
    std::sort(whole.begin(), whole.end());
    whole.erase(std::unique(whole.begin(), whole.end()), whole.end());
  }

  // The cells this rank gives: the lists' cells it holds and the volume cells holding all the
  // nodes of one of them (its part holds them: they touch the node it owns).
  std::vector<char> given(mesh.n_cells(), 0), on_surface(mesh.n_nodes(), 0);
  for (const std::vector<int>& list : lists)
    for (int c : list) {
      given[c] = 1;
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) on_surface[mesh.cell(c)[a]] = 1;
    }
  std::vector<int> faces;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (given[c]) faces.push_back(c);
  // A layered list's owned nodes: every volume cell around them (all in this part).
  std::vector<char> layer_node(mesh.n_nodes(), 0);
  bool any_layer = false;
  for (size_t i = 0; i < lists.size() && i < layered.size(); ++i)
    if (layered[i])
      for (int c : lists[i])
        for (int a = 0; a < mesh.cell_n_nodes(c); ++a)
          if (part.owns(mesh.cell(c)[a])) layer_node[mesh.cell(c)[a]] = 1, any_layer = true;
  if (any_layer)
    for (int c = 0; c < mesh.n_cells(); ++c) {
      if (cell_info(mesh.cell_types[c]).dim != mesh.dim) continue;
      for (int a = 0; a < mesh.cell_n_nodes(c) && !given[c]; ++a) given[c] = layer_node[mesh.cell(c)[a]];
    }
  if (!faces.empty()) {
    std::vector<int> volumes;
    for (int c = 0; c < mesh.n_cells(); ++c) {
      if (cell_info(mesh.cell_types[c]).dim != mesh.dim || given[c]) continue;
      bool touches = false;
      for (int a = 0; a < mesh.cell_n_nodes(c) && !touches; ++a) touches = on_surface[mesh.cell(c)[a]];
      if (touches) volumes.push_back(c);
    }
    const Mesh::NodeCells around = mesh.node_cells(volumes);
    for (int f : faces) {
      const int v0 = mesh.cell(f)[0];
      for (int p = around.start[v0]; p < around.start[v0 + 1]; ++p) {
        const int v = volumes[around.positions[p]];
        if (mesh.cell_holds(v, mesh.cell(f), mesh.cell_n_nodes(f))) given[v] = 1;
      }
    }
  }
  std::vector<int> ints, node_list;
  std::vector<double> xyz;
  std::string names;
  std::vector<char> node_given(mesh.n_nodes(), 0);
  int n_given = 0;
  for (int c = 0; c < mesh.n_cells(); ++c) n_given += given[c];
  ints.push_back(n_given);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (!given[c]) continue;
    ints.insert(ints.end(), {part.global_cell[c], static_cast<int>(mesh.cell_types[c]), part.cell_part[c],
                             mesh.cell_n_nodes(c)});
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) {
      const int v = mesh.cell(c)[a];
      ints.push_back(part.global_node[v]);
      if (!node_given[v]) node_given[v] = 1, node_list.push_back(v);
    }
    names += mesh.cell_names[c] + '\n';
  }
  ints.push_back(static_cast<int>(node_list.size()));
  for (int v : node_list) {
    ints.push_back(part.global_node[v]);
    ints.push_back(part.node_owner[v]);
    xyz.insert(xyz.end(), mesh.node(v), mesh.node(v) + 3);
    names += mesh.node_names[v] + '\n';
  }
  const std::vector<int> all_ints = parallel::gather_all(ints);
  const std::vector<double> all_xyz = parallel::gather_all(xyz);
  const std::string all_names = parallel::gather_all(names);

  struct GivenCell {
    int global, type, rank, first_node, n_nodes;
    std::string name;
  };
  struct GivenNode {
    int global, owner;
    double x[3];
    std::string name;
  };
  std::vector<GivenCell> cells;
  std::vector<int> cell_nodes;  // global numbers
  std::vector<GivenNode> nodes;
  size_t at = 0, at_xyz = 0, at_name = 0;
  auto next_name = [&] {
    const size_t end = all_names.find('\n', at_name);
    std::string name = all_names.substr(at_name, end - at_name);
    at_name = end + 1;
    return name;
  };
  while (at < all_ints.size()) {
    const int n_cells = all_ints[at++];
    for (int k = 0; k < n_cells; ++k) {
      GivenCell gc{all_ints[at], all_ints[at + 1], all_ints[at + 2], static_cast<int>(cell_nodes.size()),
                   all_ints[at + 3], {}};
      at += 4;
      cell_nodes.insert(cell_nodes.end(), all_ints.begin() + at, all_ints.begin() + at + gc.n_nodes);
      at += gc.n_nodes;
      gc.name = next_name();
      cells.push_back(std::move(gc));
    }
    const int n_nodes = all_ints[at++];
    for (int k = 0; k < n_nodes; ++k, at += 2, at_xyz += 3) {
      GivenNode gn{all_ints[at], all_ints[at + 1], {all_xyz[at_xyz], all_xyz[at_xyz + 1], all_xyz[at_xyz + 2]}, {}};
      gn.name = next_name();
      nodes.push_back(std::move(gn));
    }
  }
  auto by_global = [](const auto& a, const auto& b) { return a.global < b.global; };
  auto same_global = [](const auto& a, const auto& b) { return a.global == b.global; };
  std::stable_sort(cells.begin(), cells.end(), by_global);
  cells.erase(std::unique(cells.begin(), cells.end(), same_global), cells.end());
  std::stable_sort(nodes.begin(), nodes.end(), by_global);
  nodes.erase(std::unique(nodes.begin(), nodes.end(), same_global), nodes.end());

  SurfacePart out;
  out.part = nodes_only(part, false);
  MeshPart& sp = out.part;
  Mesh& m = sp.mesh;
  // The given nodes in local numbers: the part's where it holds them, the others appended.
  std::vector<int> local_of(nodes.size(), -1);
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const GivenNode key{part.global_node[v], 0, {0, 0, 0}, {}};
    auto it = std::lower_bound(nodes.begin(), nodes.end(), key, by_global);
    if (it != nodes.end() && it->global == key.global) local_of[it - nodes.begin()] = v;
  }
  for (size_t k = 0; k < nodes.size(); ++k) {
    if (local_of[k] < 0) {
      local_of[k] = m.n_nodes();
      m.coords.insert(m.coords.end(), nodes[k].x, nodes[k].x + 3);
      m.node_names.emplace_back();
      sp.global_node.push_back(nodes[k].global);
      sp.node_owner.push_back(nodes[k].owner);
    }
    m.node_names[local_of[k]] = nodes[k].name;
  }
  auto local_node = [&](int global) {
    const GivenNode key{global, 0, {0, 0, 0}, {}};
    auto it = std::lower_bound(nodes.begin(), nodes.end(), key, by_global);
    LUNASTER_ASSERT(it != nodes.end() && it->global == global, "with_whole_surfaces: a cell's node not given");
    return local_of[it - nodes.begin()];
  };
  for (const GivenCell& gc : cells) {
    m.cell_types.push_back(static_cast<CellType>(gc.type));
    for (int a = 0; a < gc.n_nodes; ++a) m.cell_nodes.push_back(local_node(cell_nodes[gc.first_node + a]));
    m.cell_offsets.push_back(static_cast<int>(m.cell_nodes.size()));
    m.cell_names.push_back(gc.name);
    sp.global_cell.push_back(gc.global);
    sp.cell_part.push_back(gc.rank);
  }
  out.lists.resize(lists.size());
  for (size_t i = 0; i < lists.size(); ++i)
    for (int global : wholes[i]) {
      auto it = std::lower_bound(sp.global_cell.begin(), sp.global_cell.end(), global);
      LUNASTER_ASSERT(it != sp.global_cell.end() && *it == global, "with_whole_surfaces: a listed cell not given");
      out.lists[i].push_back(static_cast<int>(it - sp.global_cell.begin()));
    }
  return out;
}

std::unordered_map<int, int> local_nodes(const MeshPart& part) {
  std::unordered_map<int, int> local;
  local.reserve(part.global_node.size());
  for (int v = 0; v < static_cast<int>(part.global_node.size()); ++v) local.emplace(part.global_node[v], v);
  return local;
}

MeshPart nodes_only(const MeshPart& part, bool names) {
  MeshPart out;
  out.mesh.dim = part.mesh.dim;
  out.mesh.name = part.mesh.name;
  out.mesh.is_part = true;
  out.mesh.coords = part.mesh.coords;
  if (names) out.mesh.node_names = part.mesh.node_names;
  else out.mesh.node_names.assign(part.mesh.n_nodes(), std::string());
  out.global_node = part.global_node;
  out.node_owner = part.node_owner;
  out.n_owned_nodes = part.n_owned_nodes;
  out.n_global_nodes = part.n_global_nodes;
  out.n_global_cells = part.n_global_cells;
  out.rank = part.rank;
  out.parts = part.parts;
  return out;
}

void add_ghost_nodes(MeshPart& numbered, const std::vector<int>& global_nodes, const MeshPart* around) {
  Mesh& mesh = numbered.mesh;
  LUNASTER_ASSERT(!around || (around->n_owned_nodes == numbered.n_owned_nodes &&
                              around->mesh.n_nodes() <= mesh.n_nodes()),
                  "add_ghost_nodes: nodes numbered from another part");
  std::vector<int> listed = global_nodes;
  std::sort(listed.begin(), listed.end());
  listed.erase(std::unique(listed.begin(), listed.end()), listed.end());
  auto is_listed = [&listed](int global) { return std::binary_search(listed.begin(), listed.end(), global); };
  // The nodes this rank gives: the listed ones it owns and, with `around`, every node of the
  // volume cells around them (a part holds every cell touching a node it owns).
  std::vector<char> given(mesh.n_nodes(), 0);
  for (int v = 0; v < numbered.n_owned_nodes; ++v) given[v] = is_listed(numbered.global_node[v]);
  if (around) {
    const Mesh& cells = around->mesh;
    const std::vector<char> owned_listed = given;
    for (int c = 0; c < cells.n_cells(); ++c) {
      if (cell_info(cells.cell_types[c]).dim != cells.dim) continue;
      const int* nodes = cells.cell(c);
      const int nn = cells.cell_n_nodes(c);
      if (std::any_of(nodes, nodes + nn, [&](int v) { return owned_listed[v] != 0; }))
        for (int a = 0; a < nn; ++a) given[nodes[a]] = 1;
    }
  }
  std::vector<int> ints;
  std::vector<double> xyz;
  std::string names;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    if (!given[v]) continue;
    ints.insert(ints.end(), {numbered.global_node[v], numbered.node_owner[v]});
    xyz.insert(xyz.end(), mesh.node(v), mesh.node(v) + 3);
    names += mesh.node_names[v] + '\n';
  }
  const std::vector<int> all_ints = parallel::gather_all(ints);
  const std::vector<double> all_xyz = parallel::gather_all(xyz);
  const std::string all_names = parallel::gather_all(names);

  std::vector<int> held(numbered.global_node);
  std::sort(held.begin(), held.end());
  struct GivenNode {
    int global, owner;
    size_t at;  // its place in the gathered lists
  };
  std::vector<GivenNode> nodes;
  std::vector<std::string> node_names;
  size_t at_name = 0;
  for (size_t k = 0; 2 * k < all_ints.size(); ++k) {
    const size_t end = all_names.find('\n', at_name);
    node_names.push_back(all_names.substr(at_name, end - at_name));
    at_name = end + 1;
    if (!std::binary_search(held.begin(), held.end(), all_ints[2 * k]))
      nodes.push_back({all_ints[2 * k], all_ints[2 * k + 1], k});
  }
  auto by_global = [](const GivenNode& a, const GivenNode& b) { return a.global < b.global; };
  std::stable_sort(nodes.begin(), nodes.end(), by_global);
  nodes.erase(std::unique(nodes.begin(), nodes.end(),
                          [](const GivenNode& a, const GivenNode& b) { return a.global == b.global; }),
              nodes.end());
  for (const GivenNode& g : nodes) {
    mesh.coords.insert(mesh.coords.end(), all_xyz.begin() + 3 * static_cast<long>(g.at),
                       all_xyz.begin() + 3 * static_cast<long>(g.at) + 3);
    mesh.node_names.push_back(std::move(node_names[g.at]));
    numbered.global_node.push_back(g.global);
    numbered.node_owner.push_back(g.owner);
  }
}

}  // namespace lunaster::engine
