#pragma once
/// One contact condition ("row"): a slave point, its pairing with the master
/// surface and its status. Every discretisation produces these and nothing else;
/// every law enforces them (contact_law.hpp).
///
/// The slave point is x_s = sum_a phi_a X(slave_nodes[a]) and the contact
/// pressure at the point is interpolated from the LAGS_C unknowns of the same
/// nodes with the same weights: lambda = sum_a phi_a LAGS_C(slave_nodes[a]).
/// A node-to-segment point is one slave node (phi = 1); an integration point
/// lies on a slave cell.
#include "engine/contact/linear_gap.hpp"

namespace lunaster::engine::contact {

struct ContactPoint {
  int zone = 0;
  int slave_cell = -1;       ///< slave cell of an integration point; -1 for a nodal point
  double xi[2] = {0.0, 0.0}; ///< reference coordinates on the slave cell
  double weight = 0.0;       ///< reference integration weight, or the tributary length/area of a nodal point (m, m^2)
  int n_slave = 0;
  int slave_nodes[8] = {};
  double phi[8] = {};        ///< slave shape functions at xi (also the LAGS_C interpolation)
  // ---- pairing (frozen between two pairings) ----
  bool paired = false;
  int master_cell = -1;
  double xi_master[2] = {0.0, 0.0};
  double normal[3] = {0.0, 0.0, 0.0};  ///< outward unit master normal
  double wjac = 0.0;         ///< weight in the current configuration (m or m^2); 0 when unpaired
  LinearGap gap;             ///< g(u) = g0 + c . u, m, > 0 open
  // ---- status ----
  bool active = false;
};

}  // namespace lunaster::engine::contact
