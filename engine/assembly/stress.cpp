/// Stress post-processing. SIGM_ELNO: stresses are computed at the
/// full-integration points and extrapolated to the cell nodes with the
/// least-squares vertex fit of reference_element.hpp (code_aster's rule: exact
/// for fields of the linear space, e.g. bilinear extrapolation from the 2x2
/// points of a QUAD4; mid-side nodes take the mean of their edge's vertices).
#include "engine/assembly/stress.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "engine/assembly/element_response.hpp"
#include "engine/assembly/halo.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine {
namespace {

/// Stresses at the Gauss points of one cell, n_qp x n_out (SIXX SIYY SIZZ SIXY [SIXZ SIYZ]):
/// the cell's behaviour from a zero state at the strain of `u` (AXIS: radial, axial, hoop, rz).
/// Nodal values come from extrapolating these: nothing is evaluated at a node, so nodes on
/// the axis of an AXIS model need no special case.
Eigen::MatrixXd gauss_stresses(const FeModel& model, const CellBehaviours& behaviours, const DofMap& dofs,
                               const Vector& u, int cell) {
  return kernels::with_small_strain(model, cell, [&](auto& kin) {
    using Kin = std::decay_t<decltype(kin)>;
    constexpr int NN = Kin::kNodes, DIM = Kin::kDim;
    const Behaviour& behaviour = behaviours.of(cell);
    Eigen::Matrix<double, Kin::kDofs, 1> ue;
    const int* nodes = model.mesh->cell(cell);
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < DIM; ++k) ue(DIM * a + k) = u(dofs.dof(nodes[a], k));
    Eigen::MatrixXd out;
    kernels::CellRequest<Kin> req;
    req.ue = &ue;
    req.point_stresses = &out;
    kernels::cell_response(behaviour, model.modelisation[cell], cell, kin, req);
    return out;
  });
}

}  // namespace

ElnoField compute_sigm_elno(const FeModel& model, const DofMap& dofs, const Vector& u,
                            const std::vector<int>* cell_rank) {
  LUNASTER_ASSERT(model.mesh != nullptr, "compute_sigm_elno: model without mesh");
  const Mesh& mesh = *model.mesh;
  ElnoField f;
  f.components = model.dim == 2 ? std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY"}
                                : std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
  const int nc = f.n_components();
  std::vector<unsigned char> is_volume(mesh.n_cells(), 0);
  for (int c : model.volume_cells()) is_volume[c] = 1;
  f.cell_offsets.assign(mesh.n_cells() + 1, 0);
  for (int c = 0; c < mesh.n_cells(); ++c) f.cell_offsets[c + 1] = f.cell_offsets[c] + (is_volume[c] ? mesh.cell_n_nodes(c) : 0);
  f.values.assign(static_cast<size_t>(f.cell_offsets.back()) * nc, 0.0);
  const int rank = cell_rank ? parallel::rank() : 0;
  const CellBehaviours behaviours(model);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (!is_volume[c] || (cell_rank && (*cell_rank)[c] != rank)) continue;
    const Eigen::MatrixXd sg = gauss_stresses(model, behaviours, dofs, u, c);
    const ReferenceElement& re = reference_element(mesh.cell_types[c]);
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> e(
        re.extrapolation.data(), re.n_nodes, re.n_qp);
    const Eigen::MatrixXd sn = e * sg;  // n_nodes x nc
    for (int a = 0; a < re.n_nodes; ++a)
      for (int k = 0; k < nc; ++k) f.values[(static_cast<size_t>(f.cell_offsets[c]) + a) * nc + k] = sn(a, k);
  }
  // Each row was computed by one rank, the others hold zeros there: the sum is exact.
  if (cell_rank) parallel::sum_over_ranks(f.values.data(), static_cast<long long>(f.values.size()));
  return f;
}

NodalField elno_to_noeu(const Mesh& mesh, const ElnoField& elno) {
  const int nc = elno.n_components();
  const int n_nodes = static_cast<int>(mesh.coords.size() / 3);
  NodalField out(elno.components, n_nodes);
  std::vector<double> sum(static_cast<size_t>(n_nodes) * nc, 0.0);
  std::vector<int> count(n_nodes, 0);
  for (int c = 0; c < elno.n_cells(); ++c) {
    const int rows = elno.n_rows(c);
    if (rows == 0) continue;
    LUNASTER_ASSERT(rows == mesh.cell_n_nodes(c), "elno_to_noeu: ELNO rows do not match the cell's nodes");
    const int* nodes = mesh.cell(c);
    for (int a = 0; a < rows; ++a) {
      ++count[nodes[a]];
      for (int k = 0; k < nc; ++k) sum[static_cast<size_t>(nodes[a]) * nc + k] += elno.value(c, a, k);
    }
  }
  for (int n = 0; n < n_nodes; ++n) {
    if (count[n] == 0) continue;
    for (int k = 0; k < nc; ++k) out.set(n, k, sum[static_cast<size_t>(n) * nc + k] / count[n]);
  }
  return out;
}

NodalField elno_to_noeu(const MeshPart& part, const ElnoField& elno) {
  NodalField out = elno_to_noeu(part.mesh, elno);
  NodeHalo(part).copy_to_ghosts(out.values, out.n_components());
  return out;
}

ElnoField compute_sieq_elno(const ElnoField& sigm) {
  auto col = [&](const char* name) { return sigm.component_index(name); };
  const int ixx = col("SIXX"), iyy = col("SIYY"), izz = col("SIZZ"), ixy = col("SIXY");
  const int ixz = col("SIXZ"), iyz = col("SIYZ");
  LUNASTER_ASSERT(ixx >= 0 && iyy >= 0 && izz >= 0 && ixy >= 0, "compute_sieq_elno: SIGM field lacks components");
  ElnoField out;
  out.components = {"VMIS", "TRESCA", "PRIN_1", "PRIN_2", "PRIN_3", "VMIS_SG", "TRSIG"};
  out.cell_offsets = sigm.cell_offsets;
  const size_t rows = static_cast<size_t>(sigm.cell_offsets.back());
  const int nin = sigm.n_components(), nout = out.n_components();
  out.values.assign(rows * nout, 0.0);
  for (size_t r = 0; r < rows; ++r) {
    const double* s = &sigm.values[r * nin];
    Eigen::Matrix3d t;
    const double sxz = ixz >= 0 ? s[ixz] : 0.0, syz = iyz >= 0 ? s[iyz] : 0.0;
    t << s[ixx], s[ixy], sxz, s[ixy], s[iyy], syz, sxz, syz, s[izz];
    const Eigen::Vector3d p = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t, Eigen::EigenvaluesOnly).eigenvalues();
    const double trace = t.trace();
    const Eigen::Matrix3d dev = t - trace / 3.0 * Eigen::Matrix3d::Identity();
    const double vmis = std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
    double* o = &out.values[r * nout];
    o[0] = vmis;
    o[1] = p(2) - p(0);
    o[2] = p(0);
    o[3] = p(1);
    o[4] = p(2);
    o[5] = trace < 0 ? -vmis : vmis;
    o[6] = trace;
  }
  return out;
}

}  // namespace lunaster::engine
