#pragma once
/// A mesh distributed among the ranks of an MPI run: each rank holds its part, not the whole.
///
/// Rank 0 reads the mesh and cuts it: its volume cells (the cells of the mesh's dimension) are
/// partitioned as partition_cells does (Scotch on their dual graph, each weighing its element
/// matrix), and each node is owned by the rank holding most of its cells. Each rank then gets
/// - its own volume cells (the ones it assembles);
/// - the ghost layer: every other cell, volume or boundary, that touches a node it owns, so that
///   the equations of its nodes are complete without another rank's help;
/// - the nodes of those cells: the ones it owns first, then the others (its ghosts), each group
///   in the whole mesh's order, with their owners;
/// - every group of the whole mesh restricted to the part: a group with nothing here is kept,
///   empty, so that a group name means the same thing on every rank.
/// The part's `mesh` is an ordinary Mesh in local numbers (what elements, loads and groups read);
/// global_node and global_cell give the whole mesh's numbers. With one rank the part is the
/// whole mesh, in its own order.
#include <unordered_map>
#include <vector>

#include "engine/mesh/mesh.hpp"

namespace lunaster::engine {

struct MeshPart {
  Mesh mesh;                     ///< the part, in local numbers
  std::vector<int> global_node;  ///< per local node: its number in the whole mesh
  std::vector<int> global_cell;  ///< per local cell: its number in the whole mesh
  std::vector<int> node_owner;   ///< per local node: the rank owning its equations
  std::vector<int> cell_part;    ///< per local cell: the rank assembling it; -1 below the mesh's dimension
  int n_owned_nodes = 0;         ///< local nodes [0, n_owned_nodes) are this rank's
  int n_global_nodes = 0;
  int n_global_cells = 0;
  int rank = 0;
  int parts = 1;

  bool owns(int local_node) const { return local_node < n_owned_nodes; }
};

/// How the whole mesh is cut among `parts` ranks: per cell of the whole mesh, the rank
/// assembling it (-1 for a cell below the mesh's dimension); per node, its owner (rank 0 for a
/// node outside every volume cell). No MPI. Throws SolveError when Scotch fails.
struct MeshCut {
  int parts = 1;
  std::vector<int> cell_part;
  std::vector<int> node_owner;
};
MeshCut cut_mesh(const Mesh& whole, int parts);

/// Part `rank` of `whole` cut by `cut` (no MPI).
MeshPart extract_part(const Mesh& whole, const MeshCut& cut, int rank);

/// Collective: rank 0 passes the whole mesh (the others nullptr), cuts it among the ranks of
/// the run and sends each rank its part; every rank returns its own. Rank 0 holds the whole
/// mesh and one part at a time while it sends. A failure of the cut (Scotch) is thrown on
/// every rank.
MeshPart distribute_mesh(const Mesh* whole);

/// A part with whole surfaces (docs/distributed-model.md, step 5: contact on a mesh in parts).
/// `part.mesh` holds the nodes of the part in their local numbers, then the other nodes of the
/// surfaces and of their volume cells (ghosts, owned by the ranks that own them in the whole
/// mesh), and as cells only the surfaces' cells and the volume cells each of them bounds (or,
/// for a layered list, touches), in the whole mesh's order; `lists` are the given cell lists in
/// its cell numbers.
struct SurfacePart {
  MeshPart part;
  std::vector<std::vector<int>> lists;
};

/// Collective: `lists` are cell lists of `part.mesh` (a contact zone's slave and master cells,
/// each rank those of its part); every rank gets the union over the ranks of each list, whole,
/// with every volume cell holding all the nodes of one of its cells. Each cell comes from the
/// ranks holding it (a part holds every cell touching a node it owns, so the volume cells of a
/// boundary cell it holds). The nodes of `part` keep their numbers: a vector of `part`'s nodes
/// is the first entries of one on the result's nodes. Node names are kept on the surfaces' nodes
/// only (the others are left empty: nothing on them is named). A list flagged in `layered` also
/// brings every volume cell around each of its nodes (given by the node's owner, which holds
/// them all) and their nodes: the whole stiffness columns of those nodes then have every row
/// on each rank (mortar's eliminations of the slave surface's unknowns).
SurfacePart with_whole_surfaces(const MeshPart& part, const std::vector<std::vector<int>>& lists,
                                const std::vector<char>& layered = {});

/// Per node that `part` holds, its local number, keyed by its number in the whole mesh.
std::unordered_map<int, int> local_nodes(const MeshPart& part);

/// `part` without its cells: its nodes (coordinates, names; without `names`, each name empty),
/// their numbers in the whole mesh and their owners. The nodes a run in parts numbers its
/// unknowns on when linear relations add nodes beyond the part and no contact surface does
/// (add_ghost_nodes).
MeshPart nodes_only(const MeshPart& part, bool names = true);

/// Collective: every rank passes the same `global_nodes` (numbers in the whole mesh, each held by
/// its owner's part). `numbered` begins with the nodes of this rank's part, in its numbers (the
/// part itself, nodes_only, with_whole_surfaces). Appends to it those it does not hold, as
/// ghosts (coordinates, name and owner from the owner), in the whole mesh's order after its
/// nodes, whose numbers stay. With `around` (this rank's part), also every node of the volume
/// cells around each listed node (its owner's part holds them all): the whole stiffness column
/// of a listed node then has every row here (linear relations solved for one of their
/// unknowns, ELIM_LAGR). No cell is added.
void add_ghost_nodes(MeshPart& numbered, const std::vector<int>& global_nodes, const MeshPart* around = nullptr);

}  // namespace lunaster::engine
