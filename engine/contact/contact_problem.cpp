#include "engine/contact/contact_problem.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include <Eigen/SparseCholesky>

#include "engine/contact/compatibility.hpp"
#include "engine/contact/coulomb_law.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/core/two_workers.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine::contact {

/// The multiplier rows of a condensed pass: M LAGS_C = b with M = sum kappa phi phi^T
/// (SPD on the nodes that some paired point touches), factorised once per pairing.
struct ContactProblem::Recovery {
  std::vector<int> local;                     ///< multiplier node index -> row of M, -1 if untouched
  SparseMatrix m;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
  bool ready = false;
};

ContactProblem::ContactProblem(const ContactDefinition& definition, const Mesh& mesh, int dim,
                               std::unique_ptr<Discretisation> discretisation, std::unique_ptr<ContactLaw> law)
    : def_(definition), mesh_(mesh), dim_(dim), disc_(std::move(discretisation)), law_(std::move(law)),
      recovery_(std::make_shared<Recovery>()) {
  LUNASTER_ASSERT(dim == 2 || dim == 3, "contact: dimension must be 2 or 3");
  std::set<int> geometry, mult;
  for (size_t z = 0; z < def_.zones.size(); ++z) {
    const ContactZone& zone = def_.zones[z];
    const double coefficient = law_->coefficient(zone);
    if (!(coefficient > 0.0) || !std::isfinite(coefficient))
      throw DeckError("contact zone " + std::to_string(z + 1) + ": the " + law_->name() +
                      " coefficient must be a finite number > 0, got " + std::to_string(coefficient));
    rho_.push_back(coefficient);
    for (int c : zone.slave_cells) {
      const CellType t = mesh.cell_types[c];
      if (!is_surface_type(t) || topological_dim(t) != dim - 1)
        throw DeckError("contact zone " + std::to_string(z + 1) + ": slave cell " + cell_label(mesh, c) +
                        " is a " + surface_type_name(t) + ", expected a boundary cell of dimension " +
                        std::to_string(dim - 1));
    }
    masters_.push_back(std::make_unique<MasterSurface>(mesh, zone.master_cells, disc_->linear_master()));
    min_edge_.push_back(smallest_edge(mesh, zone.slave_cells));
    const size_t first = points_.size();
    disc_->build_points(mesh, dim, static_cast<int>(z), zone, points_);
    disc_->build_relations(mesh, dim, zone, relations_);
    for (size_t i = first; i < points_.size(); ++i)
      for (int a = 0; a < points_[i].n_slave; ++a) mult.insert(points_[i].slave_nodes[a]);
    for (int c : zone.master_cells)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) geometry.insert(mesh.cell(c)[a]);
    for (int c : zone.slave_cells)
      for (int a = 0; a < mesh.cell_n_nodes(c); ++a) geometry.insert(mesh.cell(c)[a]);
  }
  if (law_->has_multipliers()) multiplier_nodes_.assign(mult.begin(), mult.end());
  geometry_nodes_.assign(geometry.begin(), geometry.end());
  if (def_.friction != FrictionEnforcement::None) {
    friction_ = make_coulomb_law(*law_, def_.friction, def_.method.how == ContactEnforcement::Springs);
    friction_components_ = friction_->multipliers(dim_);
    for (size_t z = 0; z < def_.zones.size(); ++z) {
      const ContactZone& zone = def_.zones[z];
      if (!(zone.mu >= 0.0) || !std::isfinite(zone.mu) || !(zone.coef_frot > 0.0) || !std::isfinite(zone.coef_frot))
        throw DeckError("contact zone " + std::to_string(z + 1) + ": friction needs a coefficient >= 0 and a " +
                        "tangential coefficient > 0, got " + std::to_string(zone.mu) + " and " +
                        std::to_string(zone.coef_frot));
      mu_.push_back(zone.mu);
      // The augmented Lagrangian's COEF_FROT is relative, times E / h: a traction per slip of the
      // order of the stiffness next to the interface. An absolute 100 Pa/m against E = 2e11 Pa
      // left its multiplier rows 14 orders below the displacements' and a factorisation found
      // them singular.
      const double e = def_.modulus > 0.0 ? def_.modulus : 1.0;
      coef_t_.push_back(def_.friction == FrictionEnforcement::AugmentedLagrangian ? zone.coef_frot * e / min_edge_[z]
                                                                                 : zone.coef_frot);
    }
    states_.resize(points_.size());
    if (!friction_components_.empty() && multiplier_nodes_.empty())
      multiplier_nodes_.assign(mult.begin(), mult.end());
  }
}

void ContactProblem::set_dirichlet(const std::vector<DirichletValue>& dirichlet) {
  for (const auto& d : dirichlet) imposed_.insert({d.node, d.component});
}

std::vector<LinearRelation> ContactProblem::take_relations(const std::function<bool(const LinearRelation&)>& which) {
  std::vector<LinearRelation> taken, kept;
  for (const LinearRelation& r : relations_.relations()) (!which || which(r) ? taken : kept).push_back(r);
  relations_ = LinearRelations(std::move(kept));
  return taken;
}

void ContactProblem::add_dofs(DofMap& dofs) {
  if (law_->has_multipliers())
    for (int node : multiplier_nodes_) multiplier_eqs_.push_back(dofs.add(node, LAGS_C));
  for (int component : friction_components_)
    if (component != LAGS_C)
      for (int node : multiplier_nodes_) dofs.add(node, component);
  relations_.add_dofs(dofs, imposed_);
  dofs_ = dofs;
}

double ContactProblem::interpolate(const Vector& u, const ContactPoint& p, int component) const {
  double value = 0.0;
  for (int a = 0; a < p.n_slave; ++a) {
    const int eq = dofs_.dof(p.slave_nodes[a], component);
    if (eq >= 0) value += p.phi[a] * u[eq];
  }
  return value;
}

double ContactProblem::multiplier(const Vector& u, const ContactPoint& p) const {
  if (multiplier_nodes_.empty() || !law_->has_multipliers()) return 0.0;
  double lambda = 0.0;
  for (int a = 0; a < p.n_slave; ++a) {
    const int eq = dofs_.dof(p.slave_nodes[a], LAGS_C);
    if (eq >= 0) lambda += p.phi[a] * u[eq];
  }
  return lambda;
}

void ContactProblem::set_all_active(bool active) {
  for (auto& p : points_) p.active = active && p.paired;
}

unsigned long long ContactProblem::status_key() const {
  unsigned long long h = 1469598103934665603ULL;  // FNV-1a over the statuses
  for (const auto& p : points_) h = (h ^ static_cast<unsigned long long>(p.active)) * 1099511628211ULL;
  return h;
}

int ContactProblem::n_active() const {
  return static_cast<int>(std::count_if(points_.begin(), points_.end(), [](const auto& p) { return p.active; }));
}

bool ContactProblem::statuses_in_newton() const {
  return def_.status_loop == FixedPointOrNewton::Newton && law_->statuses_in_newton_allowed();
}

bool ContactProblem::coupled() const {
  if (multiplier_nodes_.empty() || !law_->has_multipliers()) return false;
  if (!allow_condensation_) return true;
  for (const auto& p : points_)
    if (p.paired && p.active && law_->coefficients(p, rho(p.zone)).alpha != 0.0) return true;
  return false;
}

const std::vector<int>& ContactProblem::condensed_equations() const {
  return coupled() ? ContactHook::condensed_equations() : multiplier_eqs_;
}

std::vector<int> ContactProblem::surface_equations() const {
  // The pairing couples slave nodes to master nodes of the zones (geometry_nodes_), through
  // their displacements, their LAGS_C and the multipliers of the QUAD8 ties.
  std::vector<int> eqs;
  for (int node : geometry_nodes_)
    for (int c = 0; c < N_COMPONENTS; ++c)
      if (dofs_.dof(node, c) >= 0) eqs.push_back(dofs_.dof(node, c));
  for (const LinearRelation& r : relations_.relations())
    if (r.multiplier >= 0) eqs.push_back(r.multiplier);
  std::sort(eqs.begin(), eqs.end());
  eqs.erase(std::unique(eqs.begin(), eqs.end()), eqs.end());
  return eqs;
}

std::array<bool, 3> ContactProblem::displacement_components() const {
  // The QUAD8 ties relate every component of their nodes.
  if (!relations_.empty()) return {true, true, true};
  // A rule with fewer points than a slave cell has nodes (GAUSS-3 on TRIA6, which
  // DEFI_CONTACT warns of) leaves some LAGS_C undetermined, and what a solver returns for
  // them is arbitrary (make study, SSNP121 E with GAUSS-3: LAGS_C 0.6 % off at ff5b5f4,
  // 1,094 % with this rule, 707 % on an interface of some components). Such zones take
  // every component, so no interface of some components.
  const bool continuous = def_.method == ContactMethod::Continuous || def_.method == ContactMethod::ContinuousPenalty;
  for (size_t z = 0; continuous && z < def_.zones.size(); ++z)
    for (const IntegrationWarning& w : check_contact_zone_integration(mesh_, def_.zones[z], static_cast<int>(z)))
      if (w.kind == IntegrationWarning::Kind::TooFewPoints) return {true, true, true};
  std::array<bool, 3> reached{};
  for (const ContactPoint& p : points_)
    if (p.paired)
      for (int k = 0; k < dim_; ++k) reached[k] = reached[k] || std::abs(p.normal[k]) > kNormalRoundOff;
  return reached;
}

MatrixKind ContactProblem::matrix_kind() const {
  if (!law_->symmetric() || (friction_ && !friction_->symmetric())) return MatrixKind::General;
  if (coupled() || !relations_.empty()) return MatrixKind::SymmetricIndefinite;
  return MatrixKind::SymmetricPositiveDefinite;
}

void ContactProblem::share_among_ranks(const std::vector<char>& owned_nodes) {
  shared_ = parallel::size() > 1;
  if (shared_ && friction_)
    throw DeckError("contact with friction runs on one process: the friction states of the contact points are "
                    "not shared among the ranks of an MPI run (run it without mpirun)");
  point_rank_.assign(points_.size(), 0);
  if (!shared_) return;
  // The projections go to the ranks in equal consecutive blocks of points, whatever the
  // partition (which often puts a whole slave surface on one rank: two bodies, two ranks).
  const size_t n = points_.size(), parts = static_cast<size_t>(parallel::size());
  for (size_t i = 0; i < n; ++i) point_rank_[i] = static_cast<int>(i * parts / std::max<size_t>(n, 1));
  owned_ = owned_nodes;
}

void ContactProblem::pair(const Vector& u) {
  const std::vector<double> xyz = current_coordinates(mesh_, dofs_, dim_, u);
  for (auto& m : masters_) m->update(xyz);
  recovery_->ready = false;
  std::vector<int> which;
  which.reserve(points_.size());
  n_kept_ = 0;
  for (auto& known : motion_known_) std::fill(known.begin(), known.end(), 0);  // since the last pairing
  for (size_t i = 0; i < points_.size(); ++i) {
    if (shared_ && point_rank_[i] != parallel::rank()) continue;
    if (moved_as_one(points_[i], u)) {
      ++n_kept_;
      continue;
    }
    which.push_back(static_cast<int>(i));
  }
  pair_points(xyz, which);
  if (shared_) {
    double kept = n_kept_;
    parallel::sum_over_ranks(&kept, 1);
    n_kept_ = static_cast<int>(kept);
    share_pairing();
  }
  u_paired_ = u;
  // Every point kept: the same pairing, so the same positions and values of the terms.
  if (n_kept_ < static_cast<int>(points_.size()) || points_.empty()) ++pattern_version_;
}

bool ContactProblem::moved_as_one(const ContactPoint& p, const Vector& u) {
  // A paired point whose slave nodes, master cell and the master cells around it all moved
  // by one vector since the last pairing (to 1e-10 of the smallest slave edge) keeps its
  // pairing: a translation changes neither the projection (master cell, xi, normal) nor the
  // gap, which is written in the reference coordinates. The cells around the master cell are
  // those that could have come nearer.
  if (!p.paired || u_paired_.size() != u.size()) return false;
  const double tol = 1e-10 * min_edge_[p.zone];
  double ref[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < dim_; ++k) {
    const int eq = dofs_.dof(p.slave_nodes[0], k);
    if (eq >= 0) ref[k] = u[eq] - u_paired_[eq];
  }
  auto same = [&](int node) {
    for (int k = 0; k < dim_; ++k) {
      const int eq = dofs_.dof(node, k);
      const double d = eq >= 0 ? u[eq] - u_paired_[eq] : 0.0;
      if (!(std::abs(d - ref[k]) <= tol)) return false;
    }
    return true;
  };
  // AXIS: the weight r dl follows the radius, which a radial translation changes.
  if (def_.axisymmetric && !(std::abs(ref[0]) <= tol)) return false;
  for (int a = 1; a < p.n_slave; ++a)
    if (!same(p.slave_nodes[a])) return false;
  // Every node around the master cell within tol of ref: the bounds of their motions are
  // (computed once per cell and pairing, the points of a cell sharing them).
  const CellMotion& m = cell_motion(p.zone, p.master_cell, u);
  for (int k = 0; k < dim_; ++k)
    if (!(m.hi[k] - ref[k] <= tol) || !(ref[k] - m.lo[k] <= tol)) return false;
  return true;
}

const ContactProblem::CellMotion& ContactProblem::cell_motion(int zone, int master_cell, const Vector& u) {
  const std::vector<int>& around = neighbourhood(zone, master_cell);
  const int k = masters_[zone]->local_index(master_cell);
  if (motion_known_.size() != masters_.size()) {
    motion_known_.assign(masters_.size(), {});
    motions_.assign(masters_.size(), {});
  }
  if (motion_known_[zone].empty()) {
    motion_known_[zone].assign(masters_[zone]->cells().size(), 0);
    motions_[zone].resize(masters_[zone]->cells().size());
  }
  CellMotion& m = motions_[zone][k];
  if (motion_known_[zone][k]) return m;
  for (int c = 0; c < 3; ++c) m.lo[c] = 1e300, m.hi[c] = -1e300;
  for (int node : around)
    for (int c = 0; c < dim_; ++c) {
      const int eq = dofs_.dof(node, c);
      const double d = eq >= 0 ? u[eq] - u_paired_[eq] : 0.0;
      m.lo[c] = std::min(m.lo[c], d), m.hi[c] = std::max(m.hi[c], d);
    }
  motion_known_[zone][k] = 1;
  return m;
}

const std::vector<int>& ContactProblem::neighbourhood(int zone, int master_cell) {
  // Per zone, built once: the nodes of each master cell and of the master cells sharing a
  // node with it.
  if (neighbourhoods_.size() != masters_.size()) neighbourhoods_.assign(masters_.size(), {});
  auto& per_cell = neighbourhoods_[zone];
  const MasterSurface& master = *masters_[zone];
  const int n_cells = static_cast<int>(master.cells().size());
  if (per_cell.empty() && n_cells > 0) {
    std::unordered_map<int, std::vector<int>> cells_of_node;
    for (int k = 0; k < n_cells; ++k)
      for (int node : master.cell_nodes(k)) cells_of_node[node].push_back(k);
    per_cell.resize(n_cells);
    for (int k = 0; k < n_cells; ++k) {
      std::vector<int>& nodes = per_cell[k];
      for (int node : master.cell_nodes(k))
        for (int other : cells_of_node[node])
          for (int m : master.cell_nodes(other)) nodes.push_back(m);
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    }
  }
  return per_cell[master.local_index(master_cell)];
}

void ContactProblem::pair_points(const std::vector<double>& xyz, const std::vector<int>& which) {
  // Each point is paired on its own (the surfaces are only read): two threads share the
  // points when there are many (32,400 Simpson points on the 3D benchmark).
  auto pair_range = [&](size_t begin, size_t end, size_t& failed_at) {
    double slave_xyz[3 * kMaxSurfaceNodes];
    for (size_t q = begin; q < end; ++q) {
      failed_at = q;
      ContactPoint& p = points_[which[q]];
      double x[3];
      bool regular = true;
      if (p.slave_cell >= 0) {
        const CellType t = mesh_.cell_types[p.slave_cell];
        for (int a = 0; a < p.n_slave; ++a)
          for (int i = 0; i < 3; ++i) slave_xyz[3 * a + i] = xyz[3 * static_cast<size_t>(p.slave_nodes[a]) + i];
        const SurfacePoint sp = surface_point(t, slave_xyz, p.xi);
        std::copy(sp.x, sp.x + 3, x);
        // AXIS: the measure r dl (per radian) at the point's current radius; a point on the
        // axis (a slave line lying on it) has no area.
        const double radius = def_.axisymmetric ? sp.x[0] : 1.0;
        regular = sp.jacobian > 0.0 && std::isfinite(sp.jacobian) && radius > 0.0;
        p.wjac = regular ? p.weight * sp.jacobian * radius : 0.0;
      } else {
        for (int i = 0; i < 3; ++i) {
          x[i] = 0.0;
          for (int a = 0; a < p.n_slave; ++a) x[i] += p.phi[a] * xyz[3 * static_cast<size_t>(p.slave_nodes[a]) + i];
        }
        p.wjac = p.weight;
      }
      const MasterSurface& master = *masters_[p.zone];
      const MasterProjection mp = master.project(x, def_.zones[p.zone].tole_proj_ext);
      p.paired = mp.found && regular;
      p.gap = LinearGap{};
      if (!p.paired) {
        p.active = false;
        p.master_cell = -1;
        continue;
      }
      p.master_cell = mp.cell;
      p.xi_master[0] = mp.xi[0], p.xi_master[1] = mp.xi[1];
      std::copy(mp.normal, mp.normal + 3, p.normal);
      set_gap(p);
    }
    failed_at = SIZE_MAX;
  };
  constexpr size_t kPointsForTwoThreads = 2000;
  const size_t n = which.size();
  if (n < kPointsForTwoThreads) {
    size_t failed_at = SIZE_MAX;
    pair_range(0, n, failed_at);
    return;
  }
  run_two_workers([&](int w, size_t& failed_at) { pair_range(w == 0 ? 0 : n / 2, w == 0 ? n / 2 : n, failed_at); });
}

void ContactProblem::set_gap(ContactPoint& p) const {
  const MasterSurface& master = *masters_[p.zone];
  const int k = master.local_index(p.master_cell);
  double nm[kMaxSurfaceNodes];
  surface_shape(master.geometry_type(k), p.xi_master, nm, nullptr, nullptr);
  const auto& mnodes = master.cell_nodes(k);
  p.gap = make_linear_gap(mesh_.coords, dofs_, dim_, p.slave_nodes, p.phi, p.n_slave, mnodes.data(), nm,
                          static_cast<int>(mnodes.size()), p.normal);
}

void ContactProblem::share_pairing() {
  // What a projection found, per point, from the rank that paired it (the others send
  // zeros, so the sum is that rank's value exactly); each rank then builds the gaps of the
  // other ranks' points, which costs little beside the projections.
  constexpr int kValues = 8;  // paired, master cell, xi_master (2), normal (3), wjac
  const int me = parallel::rank();
  std::vector<double> v(kValues * points_.size(), 0.0);
  for (size_t i = 0; i < points_.size(); ++i) {
    if (point_rank_[i] != me) continue;
    const ContactPoint& p = points_[i];
    double* x = &v[kValues * i];
    x[0] = p.paired ? 1.0 : 0.0, x[1] = p.master_cell;
    x[2] = p.xi_master[0], x[3] = p.xi_master[1];
    x[4] = p.normal[0], x[5] = p.normal[1], x[6] = p.normal[2], x[7] = p.wjac;
  }
  parallel::sum_over_ranks(v.data(), static_cast<long long>(v.size()));
  touches_mine_.assign(points_.size(), 0);
  for (size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& p = points_[i];
    if (point_rank_[i] != me) {
      const double* x = &v[kValues * i];
      p.paired = x[0] != 0.0;
      p.master_cell = static_cast<int>(x[1]);
      p.xi_master[0] = x[2], p.xi_master[1] = x[3];
      p.normal[0] = x[4], p.normal[1] = x[5], p.normal[2] = x[6];
      p.wjac = x[7];
      p.gap = LinearGap{};
      if (p.paired) {
        set_gap(p);
      } else {
        p.active = false;
        p.master_cell = -1;
      }
    }
    char mine = 0;
    for (int a = 0; a < p.n_slave && !mine; ++a) mine = owned_[p.slave_nodes[a]];
    for (int k = 0; k < p.gap.n && !mine; ++k) mine = owned_[dofs_.node_of(p.gap.eq[k])];
    touches_mine_[i] = mine;
  }
}

void ContactProblem::pair_and_record(const Vector& u) {
  pair(u);
  u_at_pairing_ = u;
  ++n_pairings_;
}

void ContactProblem::first_pairing_report(const Log& log) const {
  // Incompatible slave/master cell types (compatibility.hpp) are reported once, by the
  // command defining the zone, not again here.
  for (size_t z = 0; z < masters_.size(); ++z)
    if (masters_[z]->n_flipped() > 0)
      log.warning("contact zone " + std::to_string(z + 1) + ": " + std::to_string(masters_[z]->n_flipped()) +
                  " master cell(s) oriented towards their own body; their normal was reversed "
                  "(orient the master surface outwards)");
  disc_->report(log);
}

void ContactProblem::init_statuses(const Vector& u, const Log& log) {
  int n_active = 0, n_unpaired = 0;
  for (auto& p : points_) {
    const ContactZone& zone = def_.zones[p.zone];
    p.active = p.paired && law_->initial_status(zone.init, p.gap.value(u), 1e-6 * min_edge_[p.zone]);
    n_active += p.active;
    n_unpaired += !p.paired;
  }
  std::ostringstream msg;
  msg << "contact: " << points_.size() << (disc_->nodal() ? " slave nodes, " : " contact points, ") << n_active
      << " initially in contact, " << n_unpaired << " not paired with the master surface";
  log.info(msg.str());
  u_at_init_ = u;
}

int ContactProblem::update_statuses(const Vector& u) {
  std::vector<double> lambda(points_.size()), gap(points_.size());
  for (size_t i = 0; i < points_.size(); ++i) {
    lambda[i] = multiplier(u, points_[i]);
    gap[i] = points_[i].paired ? points_[i].gap.value(u) : 0.0;
  }
  return law_->update_statuses(points_, StatusInputs{lambda, gap, min_edge_}, rho_);
}

void ContactProblem::begin_step(const Vector& u, const Log& log) {
  u_start_ = u;
  bounds_.clear(), u_of_bounds_.resize(0), bound_change_ = 0.0;
  if (friction_) status_trail_.assign(points_.size(), std::string());
  n_status_iter_ = 0;
  n_geom_iter_ = 0;
  n_pairings_ = 0;
  pair_and_record(u);
  if (first_step_) {
    first_pairing_report(log);
    init_statuses(u, log);
    first_step_ = false;
  }
}

ContactSnapshot ContactProblem::snapshot() const {
  ContactSnapshot s;
  s.first_step = first_step_;
  s.active.reserve(points_.size());
  for (const auto& p : points_) s.active.push_back(p.active);
  // Every point's state (status and history) in the hook's own part of the snapshot. The
  // frictionless laws keep their status in the point and no history: at a step's start the
  // state there is the state at the step's end. Friction keeps its own states (the normal
  // statuses stay in `active`).
  if (friction_) {
    s.pairing = std::make_shared<PointStates::Snapshot>(states_.snapshot());
    return s;
  }
  auto states = std::make_shared<PointStates::Snapshot>();
  states->present.resize(points_.size());
  for (size_t i = 0; i < points_.size(); ++i)
    states->present[i].status = points_[i].active ? PointStatus::Stick : PointStatus::Open;
  states->start = states->present;
  s.pairing = std::move(states);
  return s;
}

void ContactProblem::restore(const ContactSnapshot& state) {
  if (state.active.size() != points_.size()) return;  // a snapshot of nothing (taken before add_dofs)
  first_step_ = state.first_step;
  const auto* states = static_cast<const PointStates::Snapshot*>(state.pairing.get());
  if (friction_) {
    if (states) states_.restore(*states);
    for (size_t i = 0; i < points_.size(); ++i) points_[i].active = state.active[i] != 0;
    return;
  }
  for (size_t i = 0; i < points_.size(); ++i)
    points_[i].active = states ? states->present[i].status != PointStatus::Open : state.active[i] != 0;
}

bool ContactProblem::settle(const Vector& u, const Log& log) {
  // Status loop (inside the geometry loop, as code_aster's fixed points).
  const int changed = update_statuses(u);
  if (changed > 0) {
    ++n_status_iter_;
    std::ostringstream msg;
    msg << "contact: " << changed << " status change(s), status iteration " << n_status_iter_;
    log.info(msg.str());
    const int per_point = def_.status_iterations_per_point;
    const int limit = per_point > 0 ? per_point * static_cast<int>(points_.size()) : def_.iter_cont_maxi;
    if (n_status_iter_ > limit) {
      ConvergenceError err("contact status loop did not settle after " + std::to_string(limit) + " iterations: " +
                               std::to_string(changed) + " contact point(s) still change status",
                           {per_point > 0 ? "the active set changes one contact point per iteration: more iterations "
                                            "per point, or fewer points active at the start, may settle it"
                                          : "points cycling between contact and no contact: statuses updated inside "
                                            "Newton, another coefficient, or a finer/compatible mesh may settle them"});
      err.failure().what = Failure::What::StatusLoop;
      err.failure().limit = limit;
      err.failure().count = changed;
      err.failure().per_point = per_point;
      throw err;
    }
    return false;
  }
  if (def_.geometry_loop == FixedPointOrNewton::Newton) return true;  // paired at every iteration
  switch (def_.reac_geom) {
    case GeometryUpdate::None: return true;
    case GeometryUpdate::Controlled:
      if (n_pairings_ >= def_.nb_iter_geom) return true;
      break;
    case GeometryUpdate::Automatic: {
      const double resi = geometric_residual(geometry_nodes_, dofs_, dim_, u, u_at_pairing_);
      std::ostringstream msg;
      msg << "contact: geometric residual " << resi << " (tolerance " << def_.resi_geom << ")";
      log.info(msg.str());
      if (resi <= def_.resi_geom) return true;
      if (n_geom_iter_ >= def_.iter_geom_maxi) {
        ConvergenceError err("contact geometry loop did not converge after " + std::to_string(def_.iter_geom_maxi) +
                                 " re-pairings: geometric residual " + std::to_string(resi) + " > tolerance " +
                                 std::to_string(def_.resi_geom),
                             {"more re-pairings, smaller load increments or pairing inside Newton may help"});
        err.failure().what = Failure::What::GeometryLoop;
        err.failure().limit = def_.iter_geom_maxi;
        err.failure().value = resi;
        err.failure().tolerance = def_.resi_geom;
        throw err;
      }
      break;
    }
  }
  ++n_geom_iter_;
  n_status_iter_ = 0;
  pair_and_record(u);
  std::string kept;
  if (n_kept_ > 0)
    kept = "; " + std::to_string(n_kept_) + " of " + std::to_string(points_.size()) +
           " points keep their pairing (they and the master cells around them moved as one)";
  log.info("contact: new pairing (geometry iteration " + std::to_string(n_geom_iter_) + ")" + kept);
  return false;
}

void ContactProblem::update_statuses_in_newton(const Vector& u) {
  if (u_at_init_.size() > 0) {
    if (u_at_init_.size() == u.size() && u == u_at_init_) return;
    u_at_init_.resize(0);
  }
  if (statuses_in_newton())
    for (auto& p : points_) p.active = p.paired && law_->status(multiplier(u, p), p.gap.value(u), rho(p.zone));
}

bool ContactProblem::add_residual(const Vector& u, Vector& residual) {
  if (def_.geometry_loop == FixedPointOrNewton::Newton) return false;  // it pairs at every add_to_system
  update_statuses_in_newton(u);
  std::vector<Triplet> relation_terms;  // a few per QUAD8 face: not worth a residual-only path
  relations_.add_to_system(dofs_, u, relation_terms, residual);
  if (friction_) {
    add_frictional_terms(u, nullptr, residual);
    return true;
  }
  for (const ContactPoint& p : points_) {
    if (p.wjac == 0.0) continue;
    add_point_residual(p, respond(p, multiplier(u, p), p.gap.value(u)), residual);
  }
  return true;
}

PointResponse ContactProblem::respond(const ContactPoint& p, double lambda, double g) const {
  PointKinematics in;
  in.q[0] = g;
  in.z[0] = lambda;
  in.weight = p.wjac;
  in.coefficient = rho(p.zone);
  PointState state;
  state.status = p.active ? PointStatus::Stick : PointStatus::Open;
  const PointState start = state;
  return law_->evaluate(in, start, state);
}

PointKinematics ContactProblem::kinematics(const ContactPoint& p, const Vector& u, const Vector& u_start,
                                           int n_tangents, LinearGap* slips_out) const {
  PointKinematics in;
  in.n_tangents = n_tangents;
  in.q[0] = p.gap.value(u);
  in.dq_step[0] = in.q[0] - p.gap.value(u_start);
  in.z[0] = multiplier(u, p);
  in.weight = p.wjac;
  in.coefficient = rho(p.zone);
  if (friction_) {
    in.mu = mu_[p.zone], in.coefficient_t = coef_t_[p.zone];
    // The multipliers in the frictional law's order (LAGS_C first when the normal law has it).
    for (size_t k = 0; k < friction_components_.size(); ++k) in.z[k] = interpolate(u, p, friction_components_[k]);
  }
  if (n_tangents == 0 || !p.paired) return in;
  LinearGap own[2];
  LinearGap* slips = slips_out ? slips_out : own;
  slip_gaps(p, slips);
  for (int a = 0; a < n_tangents; ++a) {
    in.q[1 + a] = slips[a].value(u);
    in.dq_step[1 + a] = in.q[1 + a] - slips[a].value(u_start);
  }
  return in;
}

void ContactProblem::add_point_residual(const ContactPoint& p, const PointResponse& r, Vector& residual) const {
  if (r.r_q[0] != 0.0) add_gradient(p.gap, r.r_q[0], residual);
  if (multiplier_nodes_.empty()) return;
  for (int a = 0; a < p.n_slave; ++a) residual[dofs_.dof(p.slave_nodes[a], LAGS_C)] += p.phi[a] * r.r_z[0];
}

void ContactProblem::add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) {
  if (def_.geometry_loop == FixedPointOrNewton::Newton) pair(u);
  update_statuses_in_newton(u);
  relations_.add_to_system(dofs_, u, tangent, residual);
  if (friction_) {
    add_frictional_terms(u, &tangent, residual);
    return;
  }
  const bool condensed = !coupled();
  // The points of a slave cell are consecutive and share their DOFs: their terms are
  // summed per cell and emitted once.
  LocalTangent local;
  int group = -1;
  int leq[8];
  // The tangent's length is known only at the end. Growing it by doubling copied it about
  // twice over onto fresh pages (1.3 million triplets on the 3D benchmark): once an eighth
  // of the points is in, room for the rest is reserved in proportion, with a margin.
  const size_t first = tangent.size(), probe = std::max<size_t>(points_.size() / 8, 1);
  bool reserved = false;
  for (size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    const int key = p.slave_cell >= 0 ? p.slave_cell : -2 - static_cast<int>(i);
    if (key != group) {
      local.flush(tangent), group = key;
      if (!reserved && i >= probe) {
        reserved = true;
        const size_t expected = first + (tangent.size() - first) * points_.size() / i * 9 / 8;
        if (expected > tangent.capacity()) {
          tangent.reserve(expected);
          advise_huge_pages(tangent.data(), sizeof(Triplet) * expected);
        }
      }
    }
    if (p.wjac == 0.0) continue;  // unpaired inactive points still hold their multiplier rows
    const PointResponse c = respond(p, multiplier(u, p), p.gap.value(u));
    add_point_residual(p, c, residual);
    if (shared_ && !touches_mine_[i]) continue;  // the driver would drop every term of it
    // Every entry the pairing allows is emitted, zeros included (flush emits the whole block):
    // the pattern then depends on the pairing only, not on the statuses.
    local.add_outer(p.gap, p.gap, c.k_qq[0][0]);
    if (multiplier_nodes_.empty()) continue;
    for (int a = 0; a < p.n_slave; ++a) leq[a] = dofs_.dof(p.slave_nodes[a], LAGS_C);
    // Condensed: the multiplier rows are solved in recover(); their entries stay zero here.
    const double on = condensed ? 0.0 : 1.0;
    int la[8], lk[LinearGap::kMaxTerms];
    for (int a = 0; a < p.n_slave; ++a) la[a] = local.index(leq[a]);
    for (int k = 0; k < p.gap.n; ++k) lk[k] = local.index(p.gap.eq[k]);
    for (int a = 0; a < p.n_slave; ++a) {
      const double kappa_a = on * c.k_zz[0][0] * p.phi[a], sigma_a = on * c.k_zq[0][0] * p.phi[a],
                   alpha_a = on * c.k_qz[0][0] * p.phi[a];
      for (int b = 0; b < p.n_slave; ++b) local.add_at(la[a], la[b], kappa_a * p.phi[b]);
      for (int k = 0; k < p.gap.n; ++k) {
        local.add_at(la[a], lk[k], sigma_a * p.gap.coef[k]);
        local.add_at(lk[k], la[a], alpha_a * p.gap.coef[k]);
      }
    }
  }
  local.flush(tangent);
}

void ContactProblem::recover(Vector& u) {
  if (multiplier_nodes_.empty() || coupled()) return;
  Recovery& r = *recovery_;
  const int n_mult = static_cast<int>(multiplier_nodes_.size());
  auto mult_index = [&](int eq) {
    return static_cast<int>(std::lower_bound(multiplier_eqs_.begin(), multiplier_eqs_.end(), eq) - multiplier_eqs_.begin());
  };
  if (!r.ready) {
    // kappa depends on the weights only (not on the statuses): one factorisation per pairing.
    std::vector<Triplet> t;
    std::vector<char> touched(n_mult, 0);
    for (const auto& p : points_) {
      if (p.wjac == 0.0) continue;
      const double kappa = law_->coefficients(p, rho(p.zone)).kappa;
      for (int a = 0; a < p.n_slave; ++a) {
        const int ia = mult_index(dofs_.dof(p.slave_nodes[a], LAGS_C));
        touched[ia] = 1;
        for (int b = 0; b < p.n_slave; ++b)
          t.emplace_back(ia, mult_index(dofs_.dof(p.slave_nodes[b], LAGS_C)), kappa * p.phi[a] * p.phi[b]);
      }
    }
    r.local.assign(n_mult, -1);
    int n_local = 0;
    for (int i = 0; i < n_mult; ++i)
      if (touched[i]) r.local[i] = n_local++;
    for (auto& x : t) x = Triplet(r.local[x.row()], r.local[x.col()], x.value());
    r.m = SparseMatrix(n_local, n_local);
    r.m.setFromTriplets(t.begin(), t.end());
    r.ldlt.compute(r.m);
    if (r.ldlt.info() != Eigen::Success)
      throw InternalError("contact: the multiplier recovery matrix could not be factorised");
    r.ready = true;
  }
  Vector b = Vector::Zero(r.m.rows());
  for (const auto& p : points_) {
    if (!p.paired || p.wjac == 0.0) continue;
    const double sigma = law_->coefficients(p, rho(p.zone)).sigma;
    if (sigma == 0.0) continue;
    const double g = p.gap.value(u);
    for (int a = 0; a < p.n_slave; ++a) b[r.local[mult_index(dofs_.dof(p.slave_nodes[a], LAGS_C))]] += sigma * g * p.phi[a];
  }
  const Vector lambda = r.ldlt.solve(b);
  for (int i = 0; i < n_mult; ++i) u[multiplier_eqs_[i]] = r.local[i] >= 0 ? lambda[r.local[i]] : 0.0;
}

void ContactProblem::write_fields(const Vector& u, ResultStep& step) const {
  if (friction_) report_semi_multipliers(u, step);
  // Nodal contact forces on the slave nodes: f_a = -sum w p phi_a n over the active points.
  const size_t n_nodes = static_cast<size_t>(mesh_.n_nodes());
  std::vector<double> force(3 * n_nodes, 0.0);
  for (const auto& p : points_) {
    if (!p.active) continue;
    const double pressure = law_->pressure(p, multiplier(u, p), p.gap.value(u), rho(p.zone));
    for (int a = 0; a < p.n_slave; ++a)
      for (int k = 0; k < 3; ++k)
        force[3 * static_cast<size_t>(p.slave_nodes[a]) + k] -= p.wjac * pressure * p.phi[a] * p.normal[k];
  }
  // With friction: the tangential forces, and per node the status and slip of the point that
  // weighs most there (the node's own point for node-to-segment).
  std::vector<PointFriction> at(friction_ ? points_.size() : 0);
  std::vector<double> tangential(friction_ ? 3 * n_nodes : 0, 0.0), weight_at(friction_ ? n_nodes : 0, 0.0);
  std::vector<int> point_of(friction_ ? n_nodes : 0, -1);
  for (size_t i = 0; i < at.size(); ++i) {
    const ContactPoint& p = points_[i];
    at[i] = friction_at(i, u);
    for (int a = 0; a < p.n_slave; ++a) {
      const size_t node = static_cast<size_t>(p.slave_nodes[a]);
      for (int k = 0; k < 3; ++k) tangential[3 * node + k] += p.phi[a] * at[i].tangential[k];
      if (p.phi[a] > weight_at[node]) weight_at[node] = p.phi[a], point_of[node] = static_cast<int>(i);
    }
  }
  const bool friction = friction_ != nullptr;
  if (disc_->nodal()) {
    // One point per slave node: its status, frozen-pairing gap and pressure.
    std::vector<NodalContactState> states(points_.size());
    for (size_t i = 0; i < points_.size(); ++i) {
      const ContactPoint& p = points_[i];
      NodalContactState& s = states[i];
      s.node = p.slave_nodes[0];
      s.active = p.active;
      s.gap = p.paired ? p.gap.value(u) : 0.0;
      for (int k = 0; k < 3; ++k) s.force[k] = force[3 * static_cast<size_t>(s.node) + k];
      s.pressure = p.active ? law_->pressure(p, multiplier(u, p), s.gap, rho(p.zone)) : 0.0;
      if (!friction) continue;
      s.status = at[i].status;
      for (int k = 0; k < 3; ++k) s.tangential[k] = tangential[3 * static_cast<size_t>(s.node) + k];
      s.slip[0] = at[i].slip[0], s.slip[1] = at[i].slip[1];
    }
    step.nodal[kContactStateField] = nodal_contact_field(states, mesh_.n_nodes(), dim_, friction);
    return;
  }
  NodalField field(contact_state_components(dim_, false, friction), mesh_.n_nodes());
  auto set_force = [&](int node) {
    const double* f = &force[3 * static_cast<size_t>(node)];
    field.set(node, 2, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    for (int k = 0; k < dim_; ++k) field.set(node, 3 + k, f[k]);
  };
  // Integration points: each slave node projected on the master surface in the current configuration.
  const std::vector<double> xyz = current_coordinates(mesh_, dofs_, dim_, u);
  std::vector<std::unique_ptr<MasterSurface>> current;
  for (const auto& m : masters_) {
    current.push_back(std::make_unique<MasterSurface>(*m));
    current.back()->update(xyz);
  }
  std::vector<int> zone_of(mesh_.n_nodes(), -1);
  for (const auto& p : points_)
    for (int a = 0; a < p.n_slave; ++a) zone_of[p.slave_nodes[a]] = p.zone;
  for (int node : multiplier_nodes_) {
    const int z = zone_of[node];
    const MasterProjection mp = current[z]->project(&xyz[3 * static_cast<size_t>(node)], def_.zones[z].tole_proj_ext);
    double gap = 0.0;
    if (mp.found)
      for (int k = 0; k < 3; ++k) gap += (xyz[3 * static_cast<size_t>(node) + k] - mp.x[k]) * mp.normal[k];
    const double lambda = law_->has_multipliers() ? u[dofs_.dof(node, LAGS_C)] : 0.0;
    const bool closed = mp.found && law_->status(lambda, gap, rho(z));
    field.set(node, 0, closed ? 1.0 : 0.0);
    field.set(node, 1, gap);
    set_force(node);
    if (!friction) continue;
    const int i = point_of[node];
    const double none[2] = {0.0, 0.0};
    set_friction_components(field, node, dim_, closed && i >= 0 ? std::max(at[i].status, 1) : 0,
                            i >= 0 ? at[i].slip : none, &tangential[3 * static_cast<size_t>(node)],
                            &force[3 * static_cast<size_t>(node)]);
  }
  step.nodal[kContactStateField] = std::move(field);
}

}  // namespace lunaster::engine::contact
