// Google Benchmark kernels: element assembly per type, each solver backend,
// and the full linear solve of the glued 2D SSNP121-like square at the target
// size (~544k unknowns: assemble + factorise + solve, goal < 4 s on 2 cores).
#include <algorithm>

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "engine/assembly/assembly.hpp"
#include "engine/assembly/dof_map.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/solver/linear_solver.hpp"
#include "lua/comm_convert.hpp"

namespace {

using namespace lunaster::engine;

/// Structured mesh of [-1,1]^2 (QUAD4) or [0,1]^3 (HEXA8/HEXA20 without mid
/// nodes sharing: HEXA20 mid nodes are created per edge) with n cells per side.
struct Block {
  Mesh mesh;
  std::vector<int> bottom_nodes;
};

Block quad_block(int n) {
  Block b;
  Mesh& m = b.mesh;
  m.dim = 2;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.coords.insert(m.coords.end(), {-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0});
      m.node_names.push_back("N" + std::to_string(m.node_names.size() + 1));
      if (j == 0) b.bottom_nodes.push_back(static_cast<int>(m.node_names.size()) - 1);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      m.cell_types.push_back(CellType::Quad4);
      m.cell_nodes.insert(m.cell_nodes.end(), {a, a + 1, a + n + 2, a + n + 1});
      m.cell_offsets.push_back(static_cast<int>(m.cell_nodes.size()));
      m.cell_names.push_back("M" + std::to_string(m.cell_types.size()));
    }
  return b;
}

Block hexa_block(int n, bool quadratic) {
  Block b;
  Mesh& m = b.mesh;
  m.dim = 3;
  const int s = quadratic ? 2 * n : n;  // quadratic: a 2n grid holds the mid-side nodes
  auto id = [&](int i, int j, int k) { return (k * (s + 1) + j) * (s + 1) + i; };
  for (int k = 0; k <= s; ++k)
    for (int j = 0; j <= s; ++j)
      for (int i = 0; i <= s; ++i) {
        m.coords.insert(m.coords.end(), {double(i) / s, double(j) / s, double(k) / s});
        m.node_names.push_back("N" + std::to_string(m.node_names.size() + 1));
        if (k == 0) b.bottom_nodes.push_back(id(i, j, k));
      }
  const int st = quadratic ? 2 : 1;
  const int ci[8] = {0, 0, 1, 1, 0, 0, 1, 1}, cj[8] = {0, 1, 1, 0, 0, 1, 1, 0}, ck[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  const int e[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int g[8][3];
        for (int q = 0; q < 8; ++q) {
          g[q][0] = st * (i + ci[q]), g[q][1] = st * (j + cj[q]), g[q][2] = st * (k + ck[q]);
          m.cell_nodes.push_back(id(g[q][0], g[q][1], g[q][2]));
        }
        if (quadratic)
          for (const auto& ed : e)
            m.cell_nodes.push_back(id((g[ed[0]][0] + g[ed[1]][0]) / 2, (g[ed[0]][1] + g[ed[1]][1]) / 2,
                                      (g[ed[0]][2] + g[ed[1]][2]) / 2));
        m.cell_types.push_back(quadratic ? CellType::Hexa20 : CellType::Hexa8);
        m.cell_offsets.push_back(static_cast<int>(m.cell_nodes.size()));
        m.cell_names.push_back("M" + std::to_string(m.cell_types.size()));
      }
  return b;
}

FeModel model_of(const Mesh& mesh, int dim) {
  FeModel model;
  model.mesh = &mesh;
  model.dim = dim;
  model.materials = {ElasticMaterial{2.0e6, 0.3, 0.0}};
  model.modelisation.assign(mesh.n_cells(), dim == 2 ? Modelisation::PlaneStrain : Modelisation::Solid3D);
  model.material.assign(mesh.n_cells(), 0);
  return model;
}

/// Stiffness with elastic supports (springs) on the bottom nodes: SPD.
SparseMatrix supported_stiffness(const Block& b, const FeModel& model, const DofMap& dofs) {
  std::vector<Triplet> t;
  assemble_stiffness(model, dofs, t);
  for (int node : b.bottom_nodes)
    for (int c = 0; c < model.dim; ++c) t.emplace_back(dofs.dof(node, c), dofs.dof(node, c), 1.0e9);
  SparseMatrix k(dofs.n_dofs(), dofs.n_dofs());
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

void BM_AssembleQuad4(benchmark::State& state) {
  const Block b = quad_block(static_cast<int>(state.range(0)));
  const FeModel model = model_of(b.mesh, 2);
  const DofMap dofs(b.mesh, model.volume_cells(), 2);
  std::vector<Triplet> t;
  for (auto _ : state) {
    t.clear();
    assemble_stiffness(model, dofs, t);
    SparseMatrix k(dofs.n_dofs(), dofs.n_dofs());
    k.setFromTriplets(t.begin(), t.end());
    benchmark::DoNotOptimize(k.nonZeros());
  }
  state.counters["cells"] = b.mesh.n_cells();
  state.counters["dofs"] = dofs.n_dofs();
}
BENCHMARK(BM_AssembleQuad4)->Arg(100)->Arg(521)->Unit(benchmark::kMillisecond);

/// The same matrix assembled straight into its compressed pattern (the solver's path).
void BM_AssembleQuad4Compressed(benchmark::State& state) {
  const Block b = quad_block(static_cast<int>(state.range(0)));
  const FeModel model = model_of(b.mesh, 2);
  const DofMap dofs(b.mesh, model.volume_cells(), 2);
  for (auto _ : state) {
    const SparseMatrix k = assemble_stiffness_matrix(model, dofs);
    benchmark::DoNotOptimize(k.nonZeros());
  }
  state.counters["cells"] = b.mesh.n_cells();
  state.counters["dofs"] = dofs.n_dofs();
}
BENCHMARK(BM_AssembleQuad4Compressed)->Arg(100)->Arg(521)->Unit(benchmark::kMillisecond);

void BM_AssembleHexa(benchmark::State& state) {
  const Block b = hexa_block(static_cast<int>(state.range(0)), state.range(1) != 0);
  const FeModel model = model_of(b.mesh, 3);
  const DofMap dofs(b.mesh, model.volume_cells(), 3);
  std::vector<Triplet> t;
  for (auto _ : state) {
    t.clear();
    assemble_stiffness(model, dofs, t);
    benchmark::DoNotOptimize(t.data());
  }
  state.counters["cells"] = b.mesh.n_cells();
}
BENCHMARK(BM_AssembleHexa)->Args({20, 0})->Args({10, 1})->Unit(benchmark::kMillisecond);

void BM_Factorize(benchmark::State& state) {
  const auto kind = static_cast<SolverKind>(state.range(1));
  const Block b = quad_block(static_cast<int>(state.range(0)));
  const FeModel model = model_of(b.mesh, 2);
  const DofMap dofs(b.mesh, model.volume_cells(), 2);
  const SparseMatrix k = supported_stiffness(b, model, dofs);
  const Vector f = Vector::Ones(dofs.n_dofs());
  for (auto _ : state) {
    auto solver = make_linear_solver(kind);
    solver->factorize(k, MatrixKind::SymmetricPositiveDefinite);
    benchmark::DoNotOptimize(solver->solve(f).data());
  }
  state.counters["dofs"] = dofs.n_dofs();
}
BENCHMARK(BM_Factorize)
    ->Args({150, static_cast<int>(SolverKind::Cholmod)})
    ->Args({150, static_cast<int>(SolverKind::Umfpack)})
    ->Args({150, static_cast<int>(SolverKind::Mumps)})
    ->Unit(benchmark::kMillisecond);

/// The target: 522 x 522 nodes (544,968 unknowns), assemble + factorise + solve with CHOLMOD.
void BM_Solve2DTarget(benchmark::State& state) {
  const Block b = quad_block(521);
  const FeModel model = model_of(b.mesh, 2);
  for (auto _ : state) {
    const DofMap dofs(b.mesh, model.volume_cells(), 2);
    const SparseMatrix k = supported_stiffness(b, model, dofs);
    auto solver = make_linear_solver(SolverKind::Cholmod);
    solver->factorize(k, MatrixKind::SymmetricPositiveDefinite);
    benchmark::DoNotOptimize(solver->solve(Vector::Ones(dofs.n_dofs())).data());
    state.counters["dofs"] = dofs.n_dofs();
  }
}
BENCHMARK(BM_Solve2DTarget)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// .comm -> Lua conversion of a 1,000-line code_aster study (the issue's figure: under 10 ms).
// The study: one SSNP121 A command set, as code_aster writes it, repeated with renamed
// concepts; tests/bench/convert_speed.sh times the whole `lunaster convert` process.
static void BM_ConvertComm1000Lines(benchmark::State& state) {
  const std::string block = R"(# SSNP121 A: two elastic blocks pressed together
MA@=LIRE_MAILLAGE(FORMAT='MED',);
MO@=AFFE_MODELE(MAILLAGE=MA@,
               AFFE=_F(TOUT='OUI',
                       PHENOMENE='MECANIQUE',
                       MODELISATION='D_PLAN',),);
MAT@=DEFI_MATERIAU(ELAS=_F(E=20.0E+05,
                          NU=0.0,),);
CHMAT@=AFFE_MATERIAU(MAILLAGE=MA@,
                    AFFE=_F(GROUP_MA=('PLAQUE1','PLAQUE2',),
                            MATER=MAT@,),);
CHA@=AFFE_CHAR_MECA(MODELE=MO@,
                    DDL_IMPO=(_F(GROUP_NO='CD', DX=0.0, DY=-0.1,),
                              _F(GROUP_NO='GH', DX=0.0, DY=0.0,),),);
CONT@=DEFI_CONTACT(MODELE=MO@, FORMULATION='CONTINUE',
                  ZONE=_F(GROUP_MA_ESCL='AB', GROUP_MA_MAIT='EF', INTEGRATION='SIMPSON',
                          ORDRE_INT=4, COEF_CONT=1000., CONTACT_INIT='NON'))
L_INST@=DEFI_LIST_REEL(DEBUT=0.0,
                      INTERVALLE=_F(JUSQU_A=1.0,
                                    NOMBRE=1,),);
RESU@=STAT_NON_LINE(MODELE=MO@, CHAM_MATER=CHMAT@, CONTACT=CONT@,
                   EXCIT=_F(CHARGE=CHA@,),
                   COMPORTEMENT=_F(RELATION='ELAS',),
                   INCREMENT=_F(LIST_INST=L_INST@,),);
TEST_RESU(RESU=(_F(NUME_ORDRE=1, RESULTAT=RESU@, NOM_CHAM='DEPL', GROUP_NO='O', NOM_CMP='LAGS_C',
                   VALE_CALC=-1.003593668221e+05, REFERENCE='ANALYTIQUE', VALE_REFE=-1.0E5, PRECISION=1.E-2,),),);

)";
  std::string study;
  int lines = 0;
  for (int copy = 0; lines < 1000; ++copy) {
    std::string b = block;
    for (auto at = b.find('@'); at != std::string::npos; at = b.find('@', at)) b.replace(at, 1, std::to_string(copy));
    study += b;
    lines += static_cast<int>(std::count(b.begin(), b.end(), '\n'));
  }
  for (auto _ : state) {
    auto converted = lunaster::lua::convert_comm(study);
    benchmark::DoNotOptimize(converted.lua.data());
  }
  state.counters["lines"] = lines;
}
BENCHMARK(BM_ConvertComm1000Lines)->Unit(benchmark::kMillisecond);
