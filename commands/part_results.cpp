#include "commands/part_results.hpp"

#include <algorithm>

#include "engine/assembly/part_fields.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace {

namespace parallel = engine::parallel;

/// A nodal field's values and definition flags, node by node, `2 * components` to a node.
engine::NodalField gather_nodal(const engine::MeshPart& part, const engine::NodalField& f) {
  const int m = f.n_components();
  std::vector<double> packed(static_cast<size_t>(f.n_nodes) * 2 * m);
  for (int n = 0; n < f.n_nodes; ++n)
    for (int c = 0; c < m; ++c) {
      packed[(static_cast<size_t>(n) * 2) * m + c] = f.value(n, c);
      packed[(static_cast<size_t>(n) * 2 + 1) * m + c] = f.has(n, c) ? 1.0 : 0.0;
    }
  const std::vector<double> whole = engine::gather_nodes_to_root(part, packed, 2 * m);
  engine::NodalField out;
  out.components = f.components;
  if (parallel::rank() != 0) return out;
  out = engine::NodalField(f.components, part.n_global_nodes);
  for (int n = 0; n < part.n_global_nodes; ++n)
    for (int c = 0; c < m; ++c)
      if (whole[(static_cast<size_t>(n) * 2 + 1) * m + c] != 0.0)
        out.set(n, c, whole[(static_cast<size_t>(n) * 2) * m + c]);
  return out;
}

/// An ELNO field's rows, cell by cell: the row count, then the rows, padded to the most rows
/// any cell has on any rank.
engine::ElnoField gather_elno(const engine::MeshPart& part, const engine::ElnoField& f) {
  const int m = f.n_components();
  int most = 0;
  for (int c = 0; c < f.n_cells(); ++c) most = std::max(most, f.n_rows(c));
  most = static_cast<int>(parallel::max_over_ranks(most));
  const int block = 1 + most * m;
  std::vector<double> packed(static_cast<size_t>(f.n_cells()) * block, 0.0);
  for (int c = 0; c < f.n_cells(); ++c) {
    double* at = &packed[static_cast<size_t>(c) * block];
    at[0] = f.n_rows(c);
    std::copy_n(f.values.begin() + static_cast<long>(f.cell_offsets[c]) * m, static_cast<long>(f.n_rows(c)) * m,
                at + 1);
  }
  const std::vector<double> whole = engine::gather_cells_to_root(part, packed, block);
  engine::ElnoField out;
  out.components = f.components;
  if (parallel::rank() != 0) return out;
  for (int c = 0; c < part.n_global_cells; ++c) {
    const double* at = &whole[static_cast<size_t>(c) * block];
    const int rows = static_cast<int>(at[0]);
    out.values.insert(out.values.end(), at + 1, at + 1 + static_cast<long>(rows) * m);
    out.cell_offsets.push_back(out.cell_offsets.back() + rows);
  }
  return out;
}

}  // namespace

std::vector<engine::ResultStep> gather_steps_to_root(const engine::MeshPart& part,
                                                     const std::vector<engine::ResultStep>& steps) {
  std::vector<engine::ResultStep> out;
  for (const auto& step : steps) {
    engine::ResultStep& whole = out.emplace_back();
    whole.nume_ordre = step.nume_ordre;
    whole.inst = step.inst;
    // Every rank holds the same fields (the same commands made them), in the map's order.
    for (const auto& [name, f] : step.nodal) {
      engine::NodalField gathered = gather_nodal(part, f);
      if (parallel::rank() == 0) whole.nodal[name] = std::move(gathered);
    }
    for (const auto& [name, f] : step.elno) {
      engine::ElnoField gathered = gather_elno(part, f);
      if (parallel::rank() == 0) whole.elno[name] = std::move(gathered);
    }
  }
  return out;
}

}  // namespace lunaster::cmd
