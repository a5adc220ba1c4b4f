#pragma once
/// Mortar's discretisation (DEFI_CONT, APPARIEMENT='MORTAR'): segment-to-segment integration
/// of one weighted-gap row per slave node, with dual (biorthogonal) multipliers. Like the
/// point discretisations (discretisation.hpp) it says where the conditions live and enforces
/// nothing: the law does (contact_law.hpp), through the shared part for dual rows
/// (mortar_problem.hpp). Facts and sources: mortar_integration.hpp and the project's research
/// notes.
///
/// Rows. For slave node j, with Phi_j its dual function, N~ the slave shape functions
/// (transformed on TRIA6/QUAD8 slave cells, mortar_integration.hpp), n_j the nodal normal
/// (outward from the slave body, the average of the adjacent slave cells' normals):
///   D_j  = sum over slave cells of the integral of N~_j over the covered part,
///   M_jl = sum over slave/master overlaps of the integral of Phi_j N_l,
///   g~_j(u) = n_j . (sum_l M_jl x_l - D_j x~_j),  x = X + u, x~_j the transformed slave position,
/// frozen between two pairings, so g~_j is linear in u (g~ > 0 open). The nodal gap is
/// g_j = g~_j / D_j (m) and the nodal pressure lambda_j acts on the slave as -lambda_j grad g~_j.
/// Because the multipliers are dual, D is diagonal: each row is its slave node's own
/// condition, which is what lets a law hold it exactly by eliminating one of that node's
/// unknowns (no multiplier unknown, an SPD system).
///
/// AXIS models (ContactDefinition::axisymmetric): every overlap weight is multiplied by the
/// radius of its slave point, so D_j, M_jl and the dual basis are those of the measure r dl
/// (per radian, as the AXIS elements), and LAGS_C stays a pressure.
#include <array>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "engine/assembly/dof_map.hpp"
#include "engine/contact/contact_definition.hpp"
#include "engine/core/linalg.hpp"
#include "engine/core/log.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::contact {

/// A surface cell of a zone with its nodes in the order whose normal points out of its body.
struct OrientedCell {
  int cell = -1;
  CellType type = CellType::Seg2;
  int n = 0;
  int nodes[8] = {};
};

/// One weighted-gap condition (a slave node of one zone) and its status.
struct MortarRow {
  int zone = 0;
  int node = -1;                 ///< slave node
  double d = 0.0;                ///< D_j (m in 2D, m^2 in 3D)
  double normal[3] = {0, 0, 0};  ///< n_j, outward from the slave body
  std::vector<int> eq;           ///< displacement equations of g~_j
  std::vector<double> coef;      ///< d g~_j / d u_eq (m or m^2 per m)
  double g0 = 0.0;               ///< g~_j at u = 0
  bool active = false;
  int eliminated = -1;           ///< equation eliminated by an active exact row

  double weighted_gap(const Vector& u) const {
    double g = g0;
    for (size_t k = 0; k < eq.size(); ++k) g += coef[k] * u[eq[k]];
    return g;
  }
};

/// The rows of one pairing and what their integration found.
struct MortarPairingRows {
  std::vector<MortarRow> rows;                                ///< statuses all inactive
  std::vector<std::vector<std::pair<int, double>>> masters;   ///< per row, M_jl as (master node, value)
  int n_whole_cell = 0;  ///< partly covered slave cells given the dual basis of the whole cell
};

namespace detail {
class MasterGrid;
struct ZoneIntegrals;
struct OverlapScratch;
}  // namespace detail

/// "contact zone 2 (slave 'AB', master 'EF')".
std::string zone_label(const ContactZone& zone, int z);

class MortarSegments {
 public:
  /// Orients the zones' surfaces and checks them (boundary cells of the model, one zone per
  /// slave node); throws DeckError naming the zone and the cell.
  MortarSegments(const ContactDefinition& definition, const Mesh& mesh, int dim);

  /// The rows in the configuration u. `shared`: a model shared among MPI ranks, each rank
  /// integrating one block of the slave cells and the ranks summing D and M (collective).
  MortarPairingRows pair(const DofMap& dofs, const Vector& u, bool shared) const;

  /// The residual in the slave nodes' transformed basis (TRIA6/QUAD8/SEG3 slave cells), 3 values
  /// per row: r~_v = r_v + alpha sum r_m over the mid-edge nodes of the edges at vertex v, r~_m =
  /// (1 - 2 alpha) r_m. An exact row's pressure comes from it, the node's own equilibrium.
  std::vector<double> slave_basis_residual(const std::vector<MortarRow>& rows, const std::vector<int>& row_of_node,
                                           const DofMap& dofs, const Vector& residual) const;

  /// Diagnostics of the first pairing: the slave surface that the master surface covers.
  void report(const std::vector<MortarRow>& rows, int n_active, const Log& log) const;

  int n_zones() const { return static_cast<int>(slave_cells_.size()); }
  /// Smallest slave edge of a zone (m).
  double smallest_edge(int zone) const { return h_[zone]; }
  /// Nodes of the slave and master cells of every zone (sorted).
  const std::vector<int>& geometry_nodes() const { return geometry_nodes_; }
  /// The oriented slave cells of a zone.
  const std::vector<OrientedCell>& slave_cells(int zone) const { return slave_cells_[zone]; }

 private:
  /// D, M and the count of whole-cell dual bases of a zone, each rank having integrated its
  /// own slave cells, made whole on every rank (collective).
  static void share_overlaps(std::vector<double>& d, std::vector<std::vector<std::pair<int, double>>>& m,
                             int& n_whole_cell);
  /// The overlaps of slave cell `s` of zone `z` with the master cells (search, clipping, dual
  /// basis) added to `zi`. Returns true when the cell took the dual basis of the whole cell.
  bool integrate_slave_cell(size_t z, size_t s, const std::vector<double>& xyz, detail::MasterGrid& grid,
                            detail::ZoneIntegrals& zi, detail::OverlapScratch& scratch) const;
  /// The rows of zone `z` from its integrals, appended to `out`.
  void zone_rows(size_t z, detail::ZoneIntegrals& zi, const DofMap& dofs, const std::unordered_map<int, int>& mid_index,
                 MortarPairingRows& out) const;

  const Mesh& mesh_;
  const int dim_;
  const bool axisymmetric_;
  std::vector<ContactZone> zones_;
  std::vector<double> h_;  ///< per zone, smallest slave edge (m)
  std::vector<std::vector<OrientedCell>> slave_cells_, master_cells_;  ///< per zone, oriented outwards
  /// Mid-edge slave nodes of transformed cells: (mid node, vertex 1, vertex 2).
  std::vector<std::array<int, 3>> mid_edges_;
  std::vector<int> geometry_nodes_;
};

}  // namespace lunaster::engine::contact
