#pragma once
// Test helpers: the SSNP121 2D geometry (two blocks [-1,1]x[0,1] over
// [-1,1]x[-1,0], independent meshes) and one load step through the production
// Newton driver (engine/nonlinear/static_solver: elimination, solver choice,
// condensation, refinement, contact loops).
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "engine/assembly/assembly.hpp"
#include "engine/contact/contact_factory.hpp"
#include "engine/core/error.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/mesh/mesh.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "engine/solver/linear_solver.hpp"

namespace contact_test {

using namespace lunaster::engine;

struct TwoBlocks {
  Mesh mesh;
  std::vector<int> ab, ef, cd, gh;  // boundary cells: AB, EF contact edges, CD top, GH bottom
  std::vector<int> cd_nodes, gh_nodes;
  int node_a = -1, node_b = -1, node_o = -1;  // upper block interface: x = -1, +1, 0
  int node_e = -1, node_f = -1;               // lower block interface ends
};

/// Structured block [-1,1] x [y0, y0+1], n x n cells, QUAD4 or QUAD8. Returns node grid
/// (row-major, (2n+1)^2 positions for QUAD8 with -1 at cell centres).
inline std::vector<int> add_block(Mesh& mesh, int n, double y0, bool quadratic) {
  const int m = quadratic ? 2 * n : n;
  std::vector<int> grid((m + 1) * (m + 1), -1);
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      if (quadratic && i % 2 == 1 && j % 2 == 1) continue;
      grid[j * (m + 1) + i] = mesh.add_node(-1.0 + 2.0 * i / m, y0 + double(j) / m, 0.0);
    }
  auto at = [&](int i, int j) { return grid[j * (m + 1) + i]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!quadratic) {
        mesh.add_cell(CellType::Quad4, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        const int I = 2 * i, J = 2 * j;
        mesh.add_cell(CellType::Quad8, {at(I, J), at(I + 2, J), at(I + 2, J + 2), at(I, J + 2), at(I + 1, J),
                                        at(I + 2, J + 1), at(I + 1, J + 2), at(I, J + 1)});
      }
    }
  return grid;
}

/// Edge cells along row j of a block grid, from x = -1 to x = +1 (forward) or reversed.
inline std::vector<int> add_edges(Mesh& mesh, const std::vector<int>& grid, int n, bool quadratic, int row,
                                  bool forward) {
  const int m = quadratic ? 2 * n : n, step = quadratic ? 2 : 1;
  std::vector<int> cells;
  for (int i = 0; i < m; i += step) {
    int a = grid[row * (m + 1) + i], b = grid[row * (m + 1) + i + step];
    if (!forward) std::swap(a, b);
    if (quadratic) cells.push_back(mesh.add_cell(CellType::Seg3, {a, b, grid[row * (m + 1) + i + 1]}));
    else cells.push_back(mesh.add_cell(CellType::Seg2, {a, b}));
  }
  return cells;
}

/// Upper block n_up x n_up QUAD4, lower block n_low x n_low (QUAD4 or QUAD8).
/// Edges oriented outward (counter-clockwise traversal of each block).
inline TwoBlocks make_two_blocks(int n_up, int n_low, bool lower_quadratic) {
  TwoBlocks tb;
  tb.mesh.dim = 2;
  const std::vector<int> up = add_block(tb.mesh, n_up, 0.0, false);
  const std::vector<int> low = add_block(tb.mesh, n_low, -1.0, lower_quadratic);
  const int ml = lower_quadratic ? 2 * n_low : n_low;
  tb.ab = add_edges(tb.mesh, up, n_up, false, 0, true);
  tb.cd = add_edges(tb.mesh, up, n_up, false, n_up, false);
  tb.ef = add_edges(tb.mesh, low, n_low, lower_quadratic, ml, false);
  tb.gh = add_edges(tb.mesh, low, n_low, lower_quadratic, 0, true);
  for (int i = 0; i <= n_up; ++i) tb.cd_nodes.push_back(up[n_up * (n_up + 1) + i]);
  for (int i = 0; i <= ml; ++i) tb.gh_nodes.push_back(low[i]);
  tb.node_a = up[0], tb.node_b = up[n_up];
  tb.node_o = n_up % 2 == 0 ? up[n_up / 2] : -1;
  tb.node_e = low[ml * (ml + 1)], tb.node_f = low[ml * (ml + 1) + ml];
  return tb;
}

inline FeModel make_model(const Mesh& mesh, double young, double poisson) {
  FeModel model;
  model.mesh = &mesh;
  model.dim = 2;
  model.modelisation.assign(mesh.n_cells(), Modelisation::None);
  model.material.assign(mesh.n_cells(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.cell_types[c] == CellType::Quad4 || mesh.cell_types[c] == CellType::Quad8)
      model.modelisation[c] = Modelisation::PlaneStrain, model.material[c] = 0;
  model.materials.push_back({young, poisson, 0.0});
  return model;
}

struct Imposed { int node, component; double value; };

/// SSNP121's loading: CD pushed down by 0.1 m, GH fixed, DX = 0 on both.
inline std::vector<Imposed> displacement_bcs(const TwoBlocks& tb) {
  std::vector<Imposed> bcs;
  for (int n : tb.cd_nodes) bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, -0.1});
  for (int n : tb.gh_nodes) bcs.push_back({n, DX, 0.0}), bcs.push_back({n, DY, 0.0});
  return bcs;
}

/// One zone AB (slave) on EF (master) with `method`: SIMPSON ORDRE_INT=4, COEF_CONT=1000,
/// COEF_PENA=1e9, REAC_GEOM='CONTROLE' with two pairings, as SSNP121 A.
inline ContactDefinition zone_ab_on_ef(const TwoBlocks& tb, ContactMethod method, ContactInit init) {
  ContactDefinition def;
  def.method = method;
  def.reac_geom = GeometryUpdate::Controlled;
  def.nb_iter_geom = 2;
  ContactZone z;
  z.slave_cells = tb.ab;
  z.master_cells = tb.ef;
  z.integration = IntegrationScheme::Simpson;
  z.integration_order = 4;
  z.coef_cont = 1000.0;
  z.coef_pena = 1e9;
  z.init = init;
  def.zones.push_back(z);
  return def;
}

/// A log that prints nothing.
inline lunaster::Log quiet_log() {
  static std::ostringstream sink;
  return lunaster::Log(sink, 0);
}

struct SolveResult {
  DofMap dofs;
  Vector u;
  int n_settle = 0;  ///< contact passes (calls to settle)
  SolverStats stats;
};

/// One load step from u = 0 to the imposed values and pressures, through StaticSolver.
inline SolveResult solve(const FeModel& model, const std::vector<Imposed>& imposed,
                         const std::vector<std::pair<std::vector<int>, double>>& pressures, ContactHook& hook,
                         const lunaster::Log& log, NewtonOptions options = {}) {
  MechanicalLoads loads;
  loads.multipliers.push_back([](double t) { return t; });
  for (const auto& d : imposed) loads.dirichlet.push_back({d.node, d.component, d.value, 0});
  for (const auto& [cells, p] : pressures) loads.pressures.push_back({cells, p, 0});
  options.resi_glob_rela = 1e-8;  // 100 times the default; round-off leaves ~1e-10
  options.iter_glob_maxi = 25;
  StaticSolver solver(model, loads, options, &hook, log);
  const std::vector<ResultStep> steps = solver.run({0.0, 1.0});
  SolveResult res;
  res.dofs = solver.dofs();
  res.n_settle = solver.stats().contact_passes;
  res.stats = solver.stats();
  // The unknowns back from the DEPL field (LAGR_* relation multipliers are not results).
  const NodalField& depl = steps.back().nodal.at("DEPL");
  res.u = Vector::Zero(res.dofs.n_dofs());
  for (int eq = 0; eq < res.dofs.n_dofs(); ++eq) {
    const int cmp = res.dofs.component_of(eq);
    if (cmp > LAGS_C) continue;
    res.u[eq] = depl.value(res.dofs.node_of(eq), depl.component_index(component_name(cmp)));
  }
  return res;
}

/// DY of a node, LAGS_C of a node.
inline double dy(const SolveResult& r, int node) { return r.u[r.dofs.dof(node, DY)]; }
inline double lags_c(const SolveResult& r, int node) { return r.u[r.dofs.dof(node, LAGS_C)]; }

}  // namespace contact_test
