/// Stiffness and internal-force assembly for linear elasticity. One pass over
/// the volume cells with fixed-size element matrices. The triplet array is
/// sized up front and filled by two threads writing disjoint slices; the
/// compressed matrix gets its pattern from the connectivity first and is then
/// filled by two threads that own disjoint column ranges.
#include "engine/assembly/assembly.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <thread>

#include "engine/core/memory.hpp"
#include "engine/core/two_workers.hpp"
#include "engine/assembly/element_response.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {
namespace {

using kernels::with_small_strain;

/// Global equations of a cell's displacement DOFs, node by node.
template <int NN, int DIM>
void cell_equations(const Mesh& mesh, const DofMap& dofs, int cell, int* eq) {
  const int* nodes = mesh.cell(cell);
  for (int a = 0; a < NN; ++a)
    for (int k = 0; k < DIM; ++k) {
      eq[DIM * a + k] = dofs.dof(nodes[a], k);
      LUNASTER_DASSERT(eq[DIM * a + k] >= 0, "cell node without displacement DOF");
    }
}

/// Calls f(kinematics, equations) with a volume cell's small-strain kinematics and the global
/// equations of its displacement DOFs (node by node).
template <class F>
void with_cell(const FeModel& model, const DofMap& dofs, int cell, F&& f) {
  with_small_strain(model, cell, [&](auto& kin) {
    using Kin = std::decay_t<decltype(kin)>;
    int eq[Kin::kDofs];
    cell_equations<Kin::kNodes, Kin::kDim>(*model.mesh, dofs, cell, eq);
    f(kin, static_cast<const int*>(eq));
  });
}

/// with_cell under the cell's kinematics in `behaviours` (small strain or total Lagrangian).
template <class F>
void with_cell(const CellBehaviours& behaviours, const DofMap& dofs, int cell, F&& f) {
  const FeModel& model = behaviours.model();
  kernels::with_kinematics(model, behaviours.kinematics(cell), cell, [&](auto& kin) {
    using Kin = std::decay_t<decltype(kin)>;
    int eq[Kin::kDofs];
    cell_equations<Kin::kNodes, Kin::kDim>(*model.mesh, dofs, cell, eq);
    f(kin, static_cast<const int*>(eq));
  });
}

/// Element stiffness K_e = sum_q B^T D B w_q from the cell's behaviour at rest (thickness 1
/// in 2D; AXIS: per radian, weight r = x).
template <class Kin>
void element_stiffness(const FeModel& model, const CellBehaviours& behaviours, int cell, Kin& kin,
                       Eigen::Matrix<double, Kin::kDofs, Kin::kDofs>& ke) {
  kernels::CellRequest<Kin> req;
  req.ke = &ke;
  kernels::cell_response(behaviours.of(cell), model.modelisation[cell], cell, kin, req);
}

/// Stiffness triplets of cells[begin, end) written at out[offset[i] ...].
void stiffness_range(const FeModel& model, const CellBehaviours& behaviours, const DofMap& dofs,
                     const std::vector<int>& cells, const std::vector<size_t>& offset, size_t begin, size_t end,
                     Triplet* out) {
  for (size_t i = begin; i < end; ++i) {
    const int cell = cells[i];
    with_cell(model, dofs, cell, [&](auto& kin, const int* eq) {
      using Kin = std::decay_t<decltype(kin)>;
      constexpr int ND = Kin::kDofs;
      Eigen::Matrix<double, ND, ND> ke;
      element_stiffness(model, behaviours, cell, kin, ke);
      Triplet* t = out + offset[i];
      for (int c = 0; c < ND; ++c)
        for (int r = 0; r < ND; ++r) *t++ = Triplet(eq[r], eq[c], ke(r, c));
    });
  }
}

/// Compressed pattern of the stiffness: column (node b, component k) holds, for every node
/// a sharing a cell with b in increasing equation order, the rows of a's DIM components.
/// The DIM columns of a node have the same rows. Displacement DOFs of a node are
/// consecutive equations (DofMap numbers them node by node).
void stiffness_pattern(const Mesh& mesh, const DofMap& dofs, const std::vector<int>& cells,
                       const std::vector<char>* owned, SparseMatrix& k) {
  const int n_nodes = mesh.n_nodes(), dim = dofs.dim(), n = dofs.n_dofs();
  Mesh::NodeCells around = mesh.node_cells(cells);
  const std::vector<int>& cell_start = around.start;
  // Coupled nodes of each node, sorted by their first equation.
  std::vector<int> adj_start(static_cast<size_t>(n_nodes) + 1, 0), adj;
  adj.reserve(around.positions.size() * 3);
  std::vector<int> mark(n_nodes, -1);
  auto by_equation = [&dofs](int x, int y) { return dofs.dof(x, 0) < dofs.dof(y, 0); };
  for (int v = 0; v < n_nodes; ++v) {
    const size_t first = adj.size();
    if (owned && !(*owned)[v]) {  // another rank's columns: left empty
      adj_start[v + 1] = static_cast<int>(adj.size());
      continue;
    }
    for (int p = cell_start[v]; p < cell_start[v + 1]; ++p) {
      const int c = cells[around.positions[p]];
      for (int a = 0, nn = mesh.cell_n_nodes(c); a < nn; ++a) {
        const int w = mesh.cell(c)[a];
        if (mark[w] != v) mark[w] = v, adj.push_back(w);
      }
    }
    std::sort(adj.begin() + static_cast<std::ptrdiff_t>(first), adj.end(), by_equation);
    adj_start[v + 1] = static_cast<int>(adj.size());
    if (adj.size() > first)
      for (int k = 1; k < dim; ++k)
        LUNASTER_ASSERT(dofs.dof(v, k) == dofs.dof(v, 0) + k, "stiffness pattern: node DOFs are not consecutive");
  }
  around = Mesh::NodeCells();  // freed before the matrix is allocated (cell_start is not read below)
  // Columns: DIM rows per coupled node; none for the other unknowns (multipliers) and the nodes
  // beyond the mesh's (a part's whole contact surfaces, DofMap::add_nodes).
  k = SparseMatrix(n, n);
  int* outer = k.outerIndexPtr();
  outer[0] = 0;
  for (int eq = 0; eq < n; ++eq) {
    const int v = dofs.node_of(eq);
    const long long rows = is_displacement(dofs.component_of(eq)) && v < n_nodes
                               ? static_cast<long long>(dim) * (adj_start[v + 1] - adj_start[v])
                               : 0;
    LUNASTER_ASSERT(outer[eq] + rows <= std::numeric_limits<int>::max(), "stiffness pattern: more than 2^31 entries");
    outer[eq + 1] = outer[eq] + static_cast<int>(rows);
  }
  k.resizeNonZeros(outer[n]);
  advise_huge_pages(k.innerIndexPtr(), sizeof(int) * static_cast<std::size_t>(outer[n]));
  advise_huge_pages(k.valuePtr(), sizeof(double) * static_cast<std::size_t>(outer[n]));
  int* inner = k.innerIndexPtr();
  for (int eq = 0; eq < n; ++eq) {
    if (outer[eq + 1] == outer[eq]) continue;
    const int v = dofs.node_of(eq);
    int* r = inner + outer[eq];
    for (int p = adj_start[v]; p < adj_start[v + 1]; ++p)
      for (int l = 0, row = dofs.dof(adj[p], 0); l < dim; ++l) *r++ = row + l;
  }
}

/// Adds an element matrix into the columns [col_begin, col_end) of a compressed matrix whose
/// pattern holds the cell's entries (stiffness_pattern's); empty columns (another rank's) stay empty.
template <int NN, int DIM>
void add_element_matrix(const int* eq, const Eigen::Matrix<double, NN * DIM, NN * DIM>& ke, int col_begin,
                        int col_end, SparseMatrix& k) {
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  double* values = k.valuePtr();
  for (int b = 0; b < NN; ++b) {
    const int j0 = eq[DIM * b];
    if (j0 < col_begin || j0 >= col_end || outer[j0] == outer[j0 + 1]) continue;  // not ours, or another rank's
    const int* col = inner + outer[j0];
    const int* col_end_ptr = inner + outer[j0 + 1];
    for (int a = 0; a < NN; ++a) {
      // Offset of node a's rows in the columns of node b (the same in its DIM columns).
      const int offset = static_cast<int>(std::lower_bound(col, col_end_ptr, eq[DIM * a]) - col);
      LUNASTER_DASSERT(col + offset < col_end_ptr && col[offset] == eq[DIM * a], "stiffness entry outside its pattern");
      for (int kk = 0; kk < DIM; ++kk) {
        double* v = values + outer[j0 + kk] + offset;
        for (int l = 0; l < DIM; ++l) v[l] += ke(DIM * a + l, DIM * b + kk);
      }
    }
  }
}

/// Adds the stiffness of cells[i] for the cells touching columns [col_begin, col_end) of k,
/// in cell order, into those columns only. `failed_at` is set to the position of a cell
/// whose stiffness throws.
void stiffness_columns(const FeModel& model, const CellBehaviours& behaviours, const DofMap& dofs,
                       const std::vector<int>& cells, int col_begin, int col_end, SparseMatrix& k,
                       size_t& failed_at) {
  const int* outer = k.outerIndexPtr();
  std::fill(k.valuePtr() + outer[col_begin], k.valuePtr() + outer[col_end], 0.0);
  size_t i = 0;
  try {
    for (; i < cells.size(); ++i) {
      const int cell = cells[i];
      with_cell(model, dofs, cell, [&](auto& kin, const int* eq) {
        using Kin = std::decay_t<decltype(kin)>;
        constexpr int NN = Kin::kNodes, DIM = Kin::kDim, ND = Kin::kDofs;
        bool mine = false;
        for (int b = 0; b < NN && !mine; ++b) mine = eq[DIM * b] >= col_begin && eq[DIM * b] < col_end;
        if (!mine) return;
        Eigen::Matrix<double, ND, ND> ke;
        element_stiffness(model, behaviours, cell, kin, ke);
        add_element_matrix<NN, DIM>(eq, ke, col_begin, col_end, k);
      });
    }
  } catch (...) {
    failed_at = i;
    throw;
  }
}

}  // namespace

MaterialStates make_material_states(const CellBehaviours& behaviours) {
  const FeModel& model = behaviours.model();
  const int n = model.mesh->n_cells();
  std::vector<int> points(n, 0), variables(n, 0);
  for (int c : model.volume_cells()) {
    points[c] = reference_element(model.mesh->cell_types[c]).n_qp;
    variables[c] = behaviours.of(c).n_variables();
  }
  return MaterialStates(tensor_size(model.dim), points, variables);
}

bool assemble_internal_force(const CellBehaviours& behaviours, const DofMap& dofs, const Vector& u,
                             MaterialStates& states, Vector* f_int, SparseMatrix* k_t) {
  const FeModel& model = behaviours.model();
  LUNASTER_ASSERT(model.mesh != nullptr, "assemble_internal_force: model without mesh");
  const Mesh& mesh = *model.mesh;
  const std::vector<int> cells = model.volume_cells();
  if (f_int) *f_int = Vector::Zero(dofs.n_dofs());
  if (k_t) {
    stiffness_pattern(mesh, dofs, cells, nullptr, *k_t);
    std::fill(k_t->valuePtr(), k_t->valuePtr() + k_t->nonZeros(), 0.0);
  }
  bool ok = true;
  for (size_t i = 0; i < cells.size() && ok; ++i) {
    const int cell = cells[i];
    with_cell(behaviours, dofs, cell, [&](auto& kin, const int* eq) {
      using Kin = std::decay_t<decltype(kin)>;
      constexpr int NN = Kin::kNodes, DIM = Kin::kDim, ND = Kin::kDofs;
      Eigen::Matrix<double, ND, 1> ue, fe;
      Eigen::Matrix<double, ND, ND> ke;
      for (int r = 0; r < ND; ++r) ue(r) = u(eq[r]);
      kernels::CellRequest<Kin> req;
      req.ue = &ue;
      req.states = &states;
      req.fe = f_int ? &fe : nullptr;
      req.ke = k_t ? &ke : nullptr;
      const Behaviour& behaviour = behaviours.of(cell);
      if (kernels::cell_response(behaviour, model.modelisation[cell], cell, kin, req) != IntegrationStatus::Ok) {
        ok = false;
        return;
      }
      if (f_int)
        for (int r = 0; r < ND; ++r) (*f_int)(eq[r]) += fe(r);
      if (k_t) add_element_matrix<NN, DIM>(eq, ke, 0, dofs.n_dofs(), *k_t);
    });
  }
  return ok;
}

SparseMatrix assemble_stiffness_matrix(const FeModel& model, const DofMap& dofs, const std::vector<char>* owned_nodes) {
  LUNASTER_ASSERT(model.mesh != nullptr, "assemble_stiffness_matrix: model without mesh");
  return assemble_stiffness_matrix(CellBehaviours(model), dofs, owned_nodes);
}

SparseMatrix assemble_stiffness_matrix(const CellBehaviours& behaviours, const DofMap& dofs,
                                       const std::vector<char>* owned_nodes) {
  const FeModel& model = behaviours.model();
  std::vector<int> cells = model.volume_cells();
  if (owned_nodes) {  // the cells of the owned nodes
    const Mesh& mesh = *model.mesh;
    cells.erase(std::remove_if(cells.begin(), cells.end(),
                               [&](int c) {
                                 for (int a = 0, nn = mesh.cell_n_nodes(c); a < nn; ++a)
                                   if ((*owned_nodes)[mesh.cell(c)[a]]) return false;
                                 return true;
                               }),
                cells.end());
  }
  SparseMatrix k;
  stiffness_pattern(*model.mesh, dofs, cells, owned_nodes, k);
  // Two column ranges of about half the entries each. Each worker computes the element
  // matrices of the cells that touch its columns (those straddling the split twice) and
  // writes its columns only: no two threads write one entry, and each entry sums its
  // cells in cell order whatever the split.
  const int n = static_cast<int>(k.cols());
  const int* outer = k.outerIndexPtr();
  int split = static_cast<int>(std::lower_bound(outer, outer + n, outer[n] / 2) - outer);
  while (split < n && dofs.component_of(split) != DX && is_displacement(dofs.component_of(split))) ++split;  // a node's columns together
  run_two_workers([&](int w, size_t& failed_at) {
    stiffness_columns(model, behaviours, dofs, cells, w == 0 ? 0 : split, w == 0 ? split : n, k, failed_at);
  });
  return k;
}

void assemble_stiffness(const FeModel& model, const DofMap& dofs, std::vector<Triplet>& out) {
  LUNASTER_ASSERT(model.mesh != nullptr, "assemble_stiffness: model without mesh");
  const std::vector<int> cells = model.volume_cells();
  std::vector<size_t> offset(cells.size() + 1, out.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    const size_t nd = static_cast<size_t>(cell_n_nodes(model.mesh->cell_types[cells[i]])) * model.dim;
    offset[i + 1] = offset[i] + nd * nd;
  }
  out.resize(offset.back());
  // Two workers on disjoint halves (the target machine has 2 cores); an
  // exception in the helper thread is re-thrown here.
  const size_t half = cells.size() / 2;
  const CellBehaviours behaviours(model);
  std::exception_ptr failure;
  std::thread helper([&] {
    try {
      stiffness_range(model, behaviours, dofs, cells, offset, half, cells.size(), out.data());
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    stiffness_range(model, behaviours, dofs, cells, offset, 0, half, out.data());
  } catch (...) {
    helper.join();
    throw;
  }
  helper.join();
  if (failure) std::rethrow_exception(failure);
}

void assemble_internal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, Vector& f_int,
                              const std::vector<int>* cell_rank) {
  LUNASTER_ASSERT(model.mesh != nullptr, "assemble_internal_forces: model without mesh");
  f_int = Vector::Zero(dofs.n_dofs());
  const CellBehaviours behaviours(model);
  const int rank = cell_rank ? parallel::rank() : 0;
  for (int cell : model.volume_cells()) {
    if (cell_rank && (*cell_rank)[cell] != rank) continue;
    with_cell(model, dofs, cell, [&](auto& kin, const int* eq) {
      using Kin = std::decay_t<decltype(kin)>;
      constexpr int ND = Kin::kDofs;
      Eigen::Matrix<double, ND, 1> ue, fe;
      for (int r = 0; r < ND; ++r) ue(r) = u(eq[r]);
      kernels::CellRequest<Kin> req;
      req.ue = &ue;
      req.fe = &fe;
      kernels::cell_response(behaviours.of(cell), model.modelisation[cell], cell, kin, req);
      for (int r = 0; r < ND; ++r) f_int(eq[r]) += fe(r);
    });
  }
}

}  // namespace lunaster::engine
