// ContactProblem's Coulomb friction (coulomb_law.hpp): the points' blocks through their slip
// gaps, the states committed per step, the friction bounds Newton waits for (RESI_FROT), what a
// failed iteration is told, and the friction parts of the results. The frictionless parts are
// in contact_problem.cpp.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/contact/contact_problem.hpp"
#include "engine/contact/surface_element.hpp"

namespace lunaster::engine::contact {

void ContactProblem::slip_gaps(const ContactPoint& p, LinearGap* slips) const {
  double t[2][3];
  tangent_frame(p.normal, dim_, t);
  const MasterSurface& master = *masters_[p.zone];
  const int k = master.local_index(p.master_cell);
  double nm[kMaxSurfaceNodes];
  surface_shape(master.geometry_type(k), p.xi_master, nm, nullptr, nullptr);
  const auto& mnodes = master.cell_nodes(k);
  for (int a = 0; a < dim_ - 1; ++a)
    slips[a] = make_linear_gap(mesh_.coords, dofs_, dim_, p.slave_nodes, p.phi, p.n_slave, mnodes.data(), nm,
                               static_cast<int>(mnodes.size()), t[a]);
}

void ContactProblem::frictional_point(size_t i, const Vector& u, Vector& residual, LocalTangent* local,
                                      bool condensed) {
  const ContactPoint& p = points_[i];
  const int nt = dim_ - 1;
  LinearGap slips[2];  // built once, for the kinematics and the terms
  PointKinematics in = kinematics(p, u, u_start_.size() == u.size() ? u_start_ : u, p.paired ? nt : 0, slips);
  in.n_tangents = nt;  // an unpaired point still holds its tangential multipliers' rows
  PointState state = states_.present(i);
  state.status = p.active ? PointStatus::Stick : PointStatus::Open;  // the normal status, the loops' own
  const PointResponse r = friction_->evaluate(in, states_.start(i), state);
  states_.present(i) = state;
  if (status_trail_.size() == points_.size()) {
    const char letter = "OSG"[static_cast<int>(r.status)];
    std::string& trail = status_trail_[i];
    if (trail.empty() || trail.back() != letter) trail.push_back(letter);
  }
  const LinearGap* gaps[3] = {&p.gap, &slips[0], &slips[1]};
  for (int q = 0; q < r.n_q; ++q)
    if (r.r_q[q] != 0.0) add_gradient(*gaps[q], r.r_q[q], residual);
  const int n_z = static_cast<int>(friction_components_.size());
  for (int k = 0; k < n_z; ++k)
    for (int a = 0; a < p.n_slave; ++a) residual[dofs_.dof(p.slave_nodes[a], friction_components_[k])] += p.phi[a] * r.r_z[k];
  if (!local) return;
  // Every entry the pairing allows, zeros included: the pattern follows the pairing only.
  for (int q = 0; q < r.n_q; ++q)
    for (int j = 0; j < r.n_q; ++j) local->add_outer(*gaps[q], *gaps[j], r.k_qq[q][j]);
  int lz[kMaxPointMultipliers][8];
  double on[kMaxPointMultipliers];
  for (int k = 0; k < n_z; ++k) {
    on[k] = condensed && friction_components_[k] == LAGS_C ? 0.0 : 1.0;
    for (int a = 0; a < p.n_slave; ++a) lz[k][a] = local->index(dofs_.dof(p.slave_nodes[a], friction_components_[k]));
  }
  for (int q = 0; q < r.n_q; ++q) {
    const LinearGap& g = *gaps[q];
    int lg[LinearGap::kMaxTerms];
    for (int m = 0; m < g.n; ++m) lg[m] = local->index(g.eq[m]);
    for (int k = 0; k < n_z; ++k)
      for (int a = 0; a < p.n_slave; ++a) {
        const double qz = on[k] * r.k_qz[q][k] * p.phi[a], zq = on[k] * r.k_zq[k][q] * p.phi[a];
        for (int m = 0; m < g.n; ++m) {
          local->add_at(lg[m], lz[k][a], qz * g.coef[m]);
          local->add_at(lz[k][a], lg[m], zq * g.coef[m]);
        }
      }
  }
  for (int k = 0; k < n_z; ++k)
    for (int l = 0; l < n_z; ++l)
      for (int a = 0; a < p.n_slave; ++a)
        for (int b = 0; b < p.n_slave; ++b)
          local->add_at(lz[k][a], lz[l][b], on[k] * on[l] * r.k_zz[k][l] * p.phi[a] * p.phi[b]);
}

std::vector<std::string> ContactProblem::failure_hints() const {
  std::vector<std::string> hints;
  if (!friction_) return hints;
  int closed = 0, slipping = 0;
  for (size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].active) continue;
    ++closed;
    slipping += states_.present(i).status == PointStatus::Slip;
  }
  if (closed > 0 && slipping == closed)
    hints.push_back("all " + std::to_string(closed) + " closed contact points slip at the last iterate: Coulomb "
                    "friction holds at most mu times the normal force, and a larger tangential load lets the body "
                    "slide with nothing to stop it");
  // Points whose status went back and forth within the step.
  static const char* const names[] = {"open", "stick", "slip"};
  int listed = 0, cycling = 0;
  std::string list;
  for (size_t i = 0; i < status_trail_.size(); ++i) {
    const std::string& trail = status_trail_[i];
    if (trail.size() < 4) continue;
    ++cycling;
    if (listed == 5) continue;
    const ContactPoint& p = points_[i];
    int node = p.slave_nodes[0];
    for (int a = 1; a < p.n_slave; ++a)
      if (p.phi[a] > p.phi[0]) node = p.slave_nodes[a];
    std::string sequence;
    for (size_t k = 0; k < trail.size() && k < 12; ++k)
      sequence += std::string(k ? ", " : "") + names[std::string("OSG").find(trail[k])];
    if (trail.size() > 12) sequence += ", ...";
    list += std::string(listed ? "; " : "") + "at slave node " + node_label(mesh_, node) +
            (p.slave_cell >= 0 ? " (cell " + cell_label(mesh_, p.slave_cell) + ")" : "") + ": " + sequence;
    ++listed;
  }
  if (cycling > 0)
    hints.push_back(std::to_string(cycling) + " contact point(s) changed friction status 3 times or more in this "
                    "step (stick/slip cycling): " + list +
                    "; smaller load increments, or a smaller augmentation of the friction multipliers, may settle them");
  return hints;
}

bool ContactProblem::newton_converged() const {
  return !friction_ || !(def_.resi_frot > 0.0) || bound_change_ <= def_.resi_frot;
}

void ContactProblem::track_bounds(const Vector& u) {
  if (u_of_bounds_.size() == u.size() && u == u_of_bounds_) return;  // the same iterate again
  std::vector<double> bounds(points_.size(), 0.0);
  double largest = 0.0, change = 0.0;
  for (size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    if (p.active && p.wjac > 0.0) bounds[i] = -law_->pressure(p, multiplier(u, p), p.gap.value(u), rho(p.zone));
    largest = std::max(largest, std::abs(bounds[i]));
  }
  const bool known = bounds_.size() == bounds.size();
  for (size_t i = 0; known && i < bounds.size(); ++i) change = std::max(change, std::abs(bounds[i] - bounds_[i]));
  bound_change_ = known && largest > 0.0 ? change / largest : 0.0;
  bounds_.swap(bounds);
  u_of_bounds_ = u;
}

void ContactProblem::add_frictional_terms(const Vector& u, std::vector<Triplet>* tangent, Vector& residual) {
  if (def_.resi_frot > 0.0) track_bounds(u);
  const bool condensed = !coupled();
  LocalTangent local;
  int group = -1;
  for (size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    const int key = p.slave_cell >= 0 ? p.slave_cell : -2 - static_cast<int>(i);
    if (tangent && key != group) local.flush(*tangent), group = key;
    if (p.wjac == 0.0) continue;
    frictional_point(i, u, residual, tangent && !(shared_ && !touches_mine_[i]) ? &local : nullptr, condensed);
  }
  if (tangent) local.flush(*tangent);
}

void ContactProblem::commit_step(const Vector& u) {
  if (!friction_) return;
  // The states at the converged u (the last evaluation may have been at another iterate).
  Vector residual = Vector::Zero(u.size());
  add_frictional_terms(u, nullptr, residual);
  // The step as its results report it (write_fields comes after the commit).
  const PointStates::Snapshot before = states_.snapshot();
  reported_start_ = before.start;
  reported_u_start_ = u_start_;
  states_.commit();
}

ContactProblem::PointFriction ContactProblem::friction_at(size_t i, const Vector& u) const {
  const ContactPoint& p = points_[i];
  PointFriction f;
  if (!p.paired || p.wjac == 0.0) return f;
  const int nt = dim_ - 1;
  // The step that ended at u: from its start (kept by commit_step) to u.
  const bool committed = reported_start_.size() == points_.size() && reported_u_start_.size() == u.size();
  const Vector& from = committed ? reported_u_start_ : u_start_.size() == u.size() ? u_start_ : u;
  PointKinematics in = kinematics(p, u, from, nt);
  PointState state = states_.present(i);
  state.status = p.active ? PointStatus::Stick : PointStatus::Open;
  const PointResponse r = friction_->evaluate(in, committed ? reported_start_[i] : states_.start(i), state);
  f.status = static_cast<int>(r.status);
  double t[2][3];
  tangent_frame(p.normal, dim_, t);
  for (int a = 0; a < nt; ++a) {
    f.slip[a] = in.dq_step[1 + a];
    // The force on the slave from the master: minus the force conjugate to its slip.
    for (int k = 0; k < 3; ++k) f.tangential[k] -= r.r_q[1 + a] * t[a][k];
  }
  return f;
}

void ContactProblem::report_semi_multipliers(const Vector& u, ResultStep& step) const {
  // The unknowns LAGS_F1[, LAGS_F2] are tangential tractions (Pa); DEPL reports them as
  // code_aster's, over the node's bound mu p (p = -LAGS_C): |LAGS_F| <= 1, 1 in slip, 0 where
  // the node carries no pressure.
  auto it = step.nodal.find(kDisplacementField);
  if (it == step.nodal.end() || !law_->has_multipliers()) return;
  NodalField& depl = it->second;
  std::vector<int> zone_of(mesh_.n_nodes(), -1);
  for (const auto& p : points_)
    for (int a = 0; a < p.n_slave; ++a) zone_of[p.slave_nodes[a]] = p.zone;
  for (int component : friction_components_) {
    if (component == LAGS_C) continue;
    const int column = depl.component_index(component_name(component));
    if (column < 0) continue;
    for (int node : multiplier_nodes_) {
      const double bound = -mu_[zone_of[node]] * u[dofs_.dof(node, LAGS_C)];
      depl.set(node, column, bound > 0.0 ? u[dofs_.dof(node, component)] / bound : 0.0);
    }
  }
}

}  // namespace lunaster::engine::contact
