/// Stiffness and internal-force assembly for linear elasticity. One pass over
/// the volume cells with fixed-size element matrices; the triplet array is
/// sized up front and filled by two threads writing disjoint slices.
#include "engine/assembly/assembly.hpp"

#include <algorithm>
#include <thread>

#include "engine/assembly/element_kernels.hpp"

namespace lunaster::engine {
namespace {

using kernels::dispatch_volume;

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

/// Element stiffness K_e = sum_q B^T D B |det J| w_q (thickness 1 in 2D).
template <int NN, int DIM>
void element_stiffness(const FeModel& model, int cell, Eigen::Matrix<double, NN * DIM, NN * DIM>& ke) {
  constexpr int NS = kernels::kVoigt<DIM>;
  const Mesh& mesh = *model.mesh;
  const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
  const auto x = kernels::cell_coordinates<NN, DIM>(mesh, cell);
  const auto d = kernels::cell_hooke<DIM>(model, cell);
  Eigen::Matrix<double, NN, DIM> g;
  Eigen::Matrix<double, NS, NN * DIM> b;
  Eigen::Matrix<double, NS, NN * DIM> db;
  ke.setZero();
  double sign = 0.0;
  for (int q = 0; q < re.n_qp; ++q) {
    const double det = kernels::physical_gradients<NN, DIM>(re, q, x, g);
    kernels::check_jacobian(det, sign, mesh, cell);
    kernels::strain_matrix<NN, DIM>(g, b);
    db.noalias() = (std::abs(det) * re.weight[q]) * (d * b);
    ke.noalias() += b.transpose() * db;
  }
}

/// Stiffness triplets of cells[begin, end) written at out[offset[i] ...].
void stiffness_range(const FeModel& model, const DofMap& dofs, const std::vector<int>& cells,
                     const std::vector<size_t>& offset, size_t begin, size_t end, Triplet* out) {
  for (size_t i = begin; i < end; ++i) {
    const int cell = cells[i];
    dispatch_volume(model.mesh->cell_types[cell], [&](auto nn, auto dim) {
      constexpr int NN = decltype(nn)::value, DIM = decltype(dim)::value, ND = NN * DIM;
      Eigen::Matrix<double, ND, ND> ke;
      element_stiffness<NN, DIM>(model, cell, ke);
      int eq[ND];
      cell_equations<NN, DIM>(*model.mesh, dofs, cell, eq);
      Triplet* t = out + offset[i];
      for (int c = 0; c < ND; ++c)
        for (int r = 0; r < ND; ++r) *t++ = Triplet(eq[r], eq[c], ke(r, c));
    });
  }
}

}  // namespace

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
  std::exception_ptr failure;
  std::thread helper([&] {
    try {
      stiffness_range(model, dofs, cells, offset, half, cells.size(), out.data());
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    stiffness_range(model, dofs, cells, offset, 0, half, out.data());
  } catch (...) {
    helper.join();
    throw;
  }
  helper.join();
  if (failure) std::rethrow_exception(failure);
}

void assemble_internal_forces(const FeModel& model, const DofMap& dofs, const Vector& u, Vector& f_int) {
  LUNASTER_ASSERT(model.mesh != nullptr, "assemble_internal_forces: model without mesh");
  f_int = Vector::Zero(dofs.n_dofs());
  const Mesh& mesh = *model.mesh;
  for (int cell : model.volume_cells()) {
    dispatch_volume(mesh.cell_types[cell], [&](auto nn, auto dim) {
      constexpr int NN = decltype(nn)::value, DIM = decltype(dim)::value, ND = NN * DIM;
      constexpr int NS = kernels::kVoigt<DIM>;
      int eq[ND];
      cell_equations<NN, DIM>(mesh, dofs, cell, eq);
      Eigen::Matrix<double, ND, 1> ue, fe = Eigen::Matrix<double, ND, 1>::Zero();
      for (int r = 0; r < ND; ++r) ue(r) = u(eq[r]);
      const ReferenceElement& re = reference_element(mesh.cell_types[cell]);
      const auto x = kernels::cell_coordinates<NN, DIM>(mesh, cell);
      const auto d = kernels::cell_hooke<DIM>(model, cell);
      Eigen::Matrix<double, NN, DIM> g;
      Eigen::Matrix<double, NS, ND> b;
      double sign = 0.0;
      for (int q = 0; q < re.n_qp; ++q) {
        const double det = kernels::physical_gradients<NN, DIM>(re, q, x, g);
        kernels::check_jacobian(det, sign, mesh, cell);
        kernels::strain_matrix<NN, DIM>(g, b);
        const Eigen::Matrix<double, NS, 1> sigma = d * (b * ue);
        fe.noalias() += (std::abs(det) * re.weight[q]) * (b.transpose() * sigma);
      }
      for (int r = 0; r < ND; ++r) f_int(eq[r]) += fe(r);
    });
  }
}

}  // namespace lunaster::engine
