// A mesh file cut among the ranks (docs/distributed-model.md, step 1): how long rank 0 takes
// to cut and send, and what each rank holds against the whole mesh.
// Usage: mpirun -np N build/tests/bench/bench_mesh_part MESH.med
// Prints, per rank: its nodes (owned), cells, the size of its part as sent (bytes of the mesh
// block) against the whole mesh's, the time of distribute_mesh and of the cut alone.
#include <chrono>
#include <cstdio>

#include "engine/assembly/mesh_part.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/mesh/mesh_bytes.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace parallel = lunaster::engine::parallel;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: mpirun -np N %s MESH.med\n", argv[0]);
    return 2;
  }
  parallel::ensure_initialised();
  lunaster::engine::Mesh whole;
  double whole_mb = 0.0, read_s = 0.0;
  if (parallel::rank() == 0) {
    const auto t0 = std::chrono::steady_clock::now();
    whole = lunaster::engine::read_med(argv[1]);
    read_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    whole_mb = lunaster::engine::mesh_to_bytes(whole).size() / 1e6;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const lunaster::engine::MeshPart part = lunaster::engine::distribute_mesh(parallel::rank() == 0 ? &whole : nullptr);
  const double cut_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int part_kb = static_cast<int>(lunaster::engine::mesh_to_bytes(part.mesh).size() / 1000);
  const std::vector<int> all =
      parallel::gather_to_root(std::vector<int>{part.mesh.n_nodes(), part.n_owned_nodes, part.mesh.n_cells(), part_kb});
  if (parallel::rank() == 0) {
    // The cut alone, again (the same parts): how much of the time above is Scotch's.
    const auto t1 = std::chrono::steady_clock::now();
    lunaster::engine::cut_mesh(whole, part.parts);
    const double again_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    std::printf("the cut alone (Scotch and the owners), again: %.2f s\n", again_s);
    std::printf("whole mesh: %d nodes, %d cells, %.1f MB; read in %.2f s, cut and sent in %.2f s\n", whole.n_nodes(),
                whole.n_cells(), whole_mb, read_s, cut_s);
    for (size_t r = 0; r < all.size() / 4; ++r)
      std::printf("rank %zu of %d: %d nodes (%d owned), %d cells, part %.1f MB\n", r, part.parts, all[4 * r],
                  all[4 * r + 1], all[4 * r + 2], all[4 * r + 3] / 1000.0);
  }
  parallel::finalise();
  return 0;
}
