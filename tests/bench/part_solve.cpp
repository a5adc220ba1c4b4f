// A block's static solve on a mesh in parts against the same solve on the model shared among the
// ranks (docs/distributed-model.md, step 3): each rank's time and, from /usr/bin/time around each
// rank, its peak memory.
// Usage: mpirun -np N build/tests/bench/bench_part_solve MESH.med parts|shared [BOOMER|GAMG]
// The mesh is a block of lunaster-meshgen (--block hexa8:N): clamped on BOTTOM, pressed on TOP,
// linear elasticity, CG with the algebraic multigrid named (BOOMER by default) to RESI_RELA 1e-8.
// shared: rank 0 reads the mesh and sends it whole to every rank, as LIRE_MAILLAGE does under
// mpirun, and STAT_NON_LINE's solver shares the model (every rank its own nodes' columns, whole
// vectors); parts: rank 0 reads the mesh and sends each rank its part (distribute_mesh), and the
// solver runs on the parts (StaticSolver::set_part).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "engine/assembly/mesh_part.hpp"
#include "engine/core/log.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/mesh/mesh_bytes.hpp"
#include "engine/nonlinear/static_solver.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace engine = lunaster::engine;
namespace parallel = lunaster::engine::parallel;

namespace {

engine::FeModel elastic_model(const engine::Mesh& mesh) {
  engine::FeModel model;
  model.mesh = &mesh;
  model.dim = mesh.dim;
  model.materials = {{2.0e11, 0.3, 0.0}};
  model.modelisation.assign(mesh.n_cells(), engine::Modelisation::None);
  model.material.assign(mesh.n_cells(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (engine::cell_info(mesh.cell_types[c]).dim == mesh.dim) {
      model.modelisation[c] = mesh.dim == 3 ? engine::Modelisation::Solid3D : engine::Modelisation::PlaneStrain;
      model.material[c] = 0;
    }
  return model;
}

engine::MechanicalLoads block_loads(const engine::Mesh& mesh) {
  engine::MechanicalLoads loads;
  loads.multipliers = {[](double t) { return t; }};
  std::vector<char> bottom(mesh.n_nodes(), 0);
  for (int c : mesh.cell_groups.at("BOTTOM"))
    for (int a = 0; a < mesh.cell_n_nodes(c); ++a) bottom[mesh.cell(c)[a]] = 1;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (bottom[v])
      for (int k = 0; k < mesh.dim; ++k) loads.dirichlet.push_back({v, k, 0.0, 0});
  loads.pressures.push_back({mesh.cell_groups.at("TOP"), 1.0e8, 0});
  return loads;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || (std::strcmp(argv[2], "parts") != 0 && std::strcmp(argv[2], "shared") != 0)) {
    std::fprintf(stderr, "usage: mpirun -np N %s MESH.med parts|shared [BOOMER|GAMG]\n", argv[0]);
    return 2;
  }
  const bool in_parts = std::strcmp(argv[2], "parts") == 0;
  const bool gamg = argc > 3 && std::strcmp(argv[3], "GAMG") == 0;
  parallel::ensure_initialised();
  const auto t0 = std::chrono::steady_clock::now();
  engine::Mesh whole;
  if (parallel::rank() == 0) whole = engine::read_med(argv[1]);
  engine::MeshPart part;
  if (in_parts) {
    part = engine::distribute_mesh(parallel::rank() == 0 ? &whole : nullptr);
    whole = engine::Mesh();  // rank 0 keeps its part only
  } else {
    std::string bytes = parallel::rank() == 0 ? engine::mesh_to_bytes(whole) : std::string();
    parallel::broadcast(bytes);
    if (parallel::rank() != 0) whole = engine::mesh_from_bytes(bytes);
  }
  const double mesh_s = seconds_since(t0);
  const engine::Mesh& mesh = in_parts ? part.mesh : whole;
  const engine::FeModel model = elastic_model(mesh);
  const engine::MechanicalLoads loads = block_loads(mesh);
  engine::NewtonOptions options;
  options.solver = engine::SolverKind::Petsc;
  options.resi_glob_rela = 1e-6;
  options.iterative.krylov = engine::IterativeSettings::Krylov::CG;
  options.iterative.preconditioner =
      gamg ? engine::IterativeSettings::Preconditioner::Gamg : engine::IterativeSettings::Preconditioner::Boomer;
  options.iterative.relative_residual = 1e-8;
  std::ostringstream log_text;
  const lunaster::Log log(log_text, 1);
  engine::StaticSolver solver(model, loads, options, nullptr, log);
  if (in_parts) solver.set_part(&part);
  const auto t1 = std::chrono::steady_clock::now();
  const std::vector<engine::ResultStep> steps = solver.run({0.0, 1.0});
  const double solve_s = seconds_since(t1);
  // The largest displacement, from every rank's nodes: the same answer both ways.
  double largest = 0.0;
  const engine::NodalField& depl = steps.back().nodal.at("DEPL");
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int k = 0; k < mesh.dim; ++k)
      if (depl.has(v, k)) largest = std::max(largest, std::abs(depl.value(v, k)));
  largest = parallel::max_over_ranks(largest);
  const engine::SolverStats& stats = solver.stats();
  const std::vector<double> times = parallel::gather_to_root(std::vector<double>{
      mesh_s, solve_s, stats.assemble_seconds, stats.factorize_seconds, stats.solve_seconds});
  if (parallel::rank() == 0) {
    const engine::SolverStats& s = stats;
    std::printf("%s, %d rank(s), CG + %s: %d unknowns, %d Krylov iterations, largest |u| %.9e\n",
                in_parts ? "mesh in parts" : "shared model", parallel::size(), gamg ? "GAMG" : "BOOMER", s.n_dofs,
                s.krylov_iterations, largest);
    for (size_t r = 0; r < times.size() / 5; ++r)
      std::printf("rank %zu: mesh read and sent %.2f s, STAT_NON_LINE's solver %.2f s (assembly %.2f s, "
                  "preconditioner %.2f s, Krylov %.2f s)\n",
                  r, times[5 * r], times[5 * r + 1], times[5 * r + 2], times[5 * r + 3], times[5 * r + 4]);
  }
  return 0;
}
