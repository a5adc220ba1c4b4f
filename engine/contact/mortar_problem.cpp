#include "engine/contact/mortar_problem.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "engine/contact/contact_common.hpp"
#include "engine/core/error.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::engine::contact {

MortarProblem::MortarProblem(const ContactDefinition& definition, const Mesh& mesh, int dim,
                             std::unique_ptr<ContactLaw> law)
    : def_(definition),
      mesh_(mesh),
      dim_(dim),
      segments_(definition, mesh, dim),
      law_(std::move(law)),
      exact_(law_->exact_by_elimination()) {
  // Dual rows carry no multiplier unknown: a law either holds them exactly (elimination) or
  // acts on them through the gap alone (no alpha: a penalty).
  ContactPoint probe;
  probe.wjac = 1.0, probe.paired = probe.active = true;
  LUNASTER_ASSERT(exact_ || law_->coefficients(probe, 1.0).alpha == 0.0,
                  "mortar: a law whose multipliers enter the displacement equations needs a point discretisation");
  const double e = def_.modulus > 0.0 ? def_.modulus : 1.0;
  for (int z = 0; z < segments_.n_zones(); ++z) {
    const ContactZone& zone = def_.zones[z];
    h_.push_back(segments_.smallest_edge(z));
    const double rho = law_->coefficient(zone) * (law_->relative_coefficient() ? e / h_[z] : 1.0);
    if (!(law_->coefficient(zone) > 0.0) || !std::isfinite(rho))
      throw DeckError(zone_label(zone, z) + ": the " + (exact_ ? "complementarity" : "penalty") +
                      " coefficient must be a finite number > 0");
    rho_.push_back(rho);
  }
}

MortarProblem::MortarProblem(const ContactDefinition& definition, const Mesh& mesh, int dim)
    : MortarProblem(definition, mesh, dim, make_contact_law(definition.method.how)) {}

void MortarProblem::set_dirichlet(const std::vector<DirichletValue>& dirichlet) {
  for (const auto& d : dirichlet) imposed_.insert({d.node, d.component});
}

void MortarProblem::set_related(const std::vector<std::pair<int, int>>& node_components) {
  related_.insert(node_components.begin(), node_components.end());
}

void MortarProblem::add_dofs(DofMap& dofs) { dofs_ = dofs; }

void MortarProblem::share_among_ranks(const std::vector<char>& /*owned_nodes*/) { shared_ = parallel::size() > 1; }

void MortarProblem::pair(const Vector& u, const Log* log) {
  MortarPairingRows pairing = segments_.pair(dofs_, u, shared_);
  ++n_row_builds_;
  adopt(u, std::move(pairing), log);
}

void MortarProblem::adopt(const Vector& u, MortarPairingRows pairing, const Log* log) {
  // Statuses follow the nodes.
  for (auto& r : pairing.rows) {
    const int old = row_of_node_.empty() ? -1 : row_of_node_[r.node];
    r.active = old >= 0 && rows_[old].active;
  }
  rows_ = std::move(pairing.rows);
  master_terms_ = std::move(pairing.masters);
  u_at_pairing_ = u;
  row_of_node_.assign(mesh_.n_nodes(), -1);
  for (size_t i = 0; i < rows_.size(); ++i) row_of_node_[rows_[i].node] = static_cast<int>(i);
  lambda_.assign(rows_.size(), 0.0);
  ++pattern_version_;
  ++n_pairings_;
  // A slave node whose normal direction is imposed cannot also hold a contact condition.
  for (const auto& r : rows_) {
    int k_max = 0;
    for (int k = 1; k < dim_; ++k)
      if (std::abs(r.normal[k]) > std::abs(r.normal[k_max])) k_max = k;
    if (imposed_.count({r.node, k_max}))
      throw DeckError("slave node " + node_label(mesh_, r.node) + " of " + zone_label(def_.zones[r.zone], r.zone) +
                      " has an imposed displacement " + component_name(static_cast<Component>(k_max)) +
                      " along the normal to the contact surface: the contact condition and the imposed displacement "
                      "cannot both hold there; remove the node from the slave group (or from the imposed displacement)");
  }
  if (log && pairing.n_whole_cell > 0)
    log->info("mortar contact: " + std::to_string(pairing.n_whole_cell) +
              " partly covered slave cell(s) use the dual basis of the whole cell (their covered part cannot "
              "carry one): exact patch tests hold away from the edge of the master surface");
}

ContactPoint MortarProblem::as_point(size_t i) const {
  const MortarRow& r = rows_[i];
  ContactPoint p;
  p.zone = r.zone;
  p.weight = p.wjac = r.d;
  p.n_slave = 1;
  p.slave_nodes[0] = r.node;
  p.phi[0] = 1.0;
  p.paired = true;
  for (int k = 0; k < 3; ++k) p.normal[k] = r.normal[k];
  p.active = r.active;
  return p;
}

void MortarProblem::begin_step(const Vector& u, const Log& log) {
  first_iteration_ = true;
  n_geom_iter_ = 0;
  if (!first_step_) return;  // the pairing of the last converged state stands
  pair(u, &log);
  first_step_ = false;
  std::vector<int> rows_of_zone(def_.zones.size(), 0);
  for (const auto& r : rows_) ++rows_of_zone[r.zone];
  for (size_t z = 0; z < def_.zones.size(); ++z)
    if (rows_of_zone[z] == 0)
      throw DeckError(zone_label(def_.zones[z], static_cast<int>(z)) +
                      ": no slave cell overlaps a master cell facing it; give the slave and master groups as the two "
                      "sides of one interface, touching or nearly touching in the initial configuration");
  // CONTACT_INIT: 'INTERPENETRE' activates the rows that penetrate by more than 1e-6 h.
  int n_active = 0;
  for (auto& r : rows_) {
    r.active = law_->initial_status(def_.zones[r.zone].init, r.weighted_gap(u) / r.d, -1e-6 * h_[r.zone]);
    n_active += r.active;
  }
  segments_.report(rows_, n_active, log);
  // A linear relation on a slave node's normal component ties the very unknown the contact
  // condition acts on: both may hold (the relation then carries the force there and the
  // node's pressure reads 0), or contradict each other. Said once, naming the nodes.
  std::vector<std::string> tied;
  for (const auto& r : rows_) {
    int k_max = 0;
    for (int k = 1; k < dim_; ++k)
      if (std::abs(r.normal[k]) > std::abs(r.normal[k_max])) k_max = k;
    if (related_.count({r.node, k_max}))
      tied.push_back(node_label(mesh_, r.node) + " (" + component_name(static_cast<Component>(k_max)) + ")");
  }
  if (!tied.empty()) {
    std::string names;
    for (size_t i = 0; i < tied.size() && i < 5; ++i) names += (i ? ", " : "") + tied[i];
    if (tied.size() > 5) names += " and " + std::to_string(tied.size() - 5) + " more";
    log.warning("mortar contact: a linear relation ties the displacement along the contact normal of slave "
                "node(s) " + names + ": the relation and the contact condition act on the same unknown, so "
                "the relation carries the force there and the node's contact pressure (" + std::string(component_name(LAGS_C)) +
                ") reads 0 (or the two contradict each other); leave such nodes out of the relation or of the "
                "slave group");
  }
}

void MortarProblem::update_pressures(const Vector& residual) {
  const std::vector<double> rt = segments_.slave_basis_residual(rows_, row_of_node_, dofs_, residual);
  // Along an imposed component of the slave node the residual is the support's reaction,
  // not contact force (a node on a symmetry line whose normal is tilted from it): the
  // pressure comes from the free components, where the eliminated system makes the
  // residual parallel to the normal.
  for (size_t i = 0; i < rows_.size(); ++i) {
    double nr = 0.0, nn = 0.0;
    for (int k = 0; k < dim_; ++k) {
      if (imposed_.count({rows_[i].node, k})) continue;
      nr += rows_[i].normal[k] * rt[3 * i + k];
      nn += rows_[i].normal[k] * rows_[i].normal[k];
    }
    lambda_[i] = nn > 0.0 ? -nr / (rows_[i].d * nn) : 0.0;
  }
}

int MortarProblem::update_statuses(const Vector& u) {
  std::vector<ContactPoint> points(rows_.size());
  std::vector<double> lambda(rows_.size()), gap(rows_.size());
  for (size_t i = 0; i < rows_.size(); ++i) {
    points[i] = as_point(i);
    lambda[i] = -lambda_[i];  // the law's sign: negative in compression
    gap[i] = rows_[i].weighted_gap(u) / rows_[i].d;
  }
  const int changed = law_->update_statuses(points, StatusInputs{lambda, gap, h_}, rho_);
  for (size_t i = 0; i < rows_.size(); ++i) rows_[i].active = points[i].active;
  return changed;
}

void MortarProblem::build_eliminations(const Vector& u) {
  eliminations_.clear();
  std::unordered_map<int, int> relation_of;  // eliminated equation -> relation
  for (auto& r : rows_) {
    r.eliminated = -1;
    if (!r.active) continue;
    // The component along which the normal is largest, among the node's own free ones.
    int best = -1;
    double best_coef = 0.0;
    for (size_t k = 0; k < r.eq.size(); ++k)
      if (dofs_.node_of(r.eq[k]) == r.node && !imposed_.count({r.node, dofs_.component_of(r.eq[k])}) &&
          std::abs(r.coef[k]) > std::abs(best_coef))
        best = static_cast<int>(k), best_coef = r.coef[k];
    if (best < 0) continue;  // the node's displacement is imposed: the row cannot be eliminated
    Elimination e;
    e.eq = r.eq[best];
    e.value = -r.weighted_gap(u) / best_coef;
    for (size_t k = 0; k < r.eq.size(); ++k)
      if (static_cast<int>(k) != best) e.terms.emplace_back(r.eq[k], -r.coef[k] / best_coef);
    // Terms naming an equation eliminated before (a mid-edge node's vertices): substitute.
    std::vector<std::pair<int, double>> closed;
    for (const auto& [eq, a] : e.terms) {
      auto it = relation_of.find(eq);
      if (it == relation_of.end()) {
        closed.emplace_back(eq, a);
        continue;
      }
      const Elimination& prev = eliminations_[it->second];
      e.value += a * prev.value;
      for (const auto& t : prev.terms) closed.emplace_back(t.first, a * t.second);
    }
    std::sort(closed.begin(), closed.end());
    e.terms.clear();
    for (const auto& t : closed) {
      if (!e.terms.empty() && e.terms.back().first == t.first) e.terms.back().second += t.second;
      else e.terms.push_back(t);
    }
    LUNASTER_ASSERT(std::none_of(e.terms.begin(), e.terms.end(), [&](const auto& t) { return t.first == e.eq; }),
                    "mortar: an eliminated unknown names itself");
    r.eliminated = e.eq;
    relation_of[e.eq] = static_cast<int>(eliminations_.size());
    eliminations_.push_back(std::move(e));
  }
  // A relation built before a later one that names its equation (a master node that is the
  // slave node of another zone) would not be closed: refuse rather than solve the wrong system.
  for (const auto& e : eliminations_)
    for (const auto& t : e.terms)
      if (relation_of.count(t.first))
        throw DeckError("mortar contact: node " + node_label(mesh_, dofs_.node_of(t.first)) +
                        " is both a slave node in contact and a node of another zone's condition; give the zones "
                        "separate surfaces");
}

void MortarProblem::add_to_system(const Vector& u, std::vector<Triplet>& tangent, Vector& residual) {
  changed_in_newton_ = false;
  if (exact_) {
    update_pressures(residual);
    if (!first_iteration_) {
      const int changed = update_statuses(u);
      if (changed) {
        changed_in_newton_ = true;
        n_status_changes_ += changed;
        ++pattern_version_;  // the eliminated unknowns change the system's pattern
      }
    }
    for (size_t i = 0; i < rows_.size(); ++i) {
      if (!rows_[i].active) {
        lambda_[i] = 0.0;
        continue;
      }
      const MortarRow& r = rows_[i];
      for (size_t k = 0; k < r.eq.size(); ++k) residual[r.eq[k]] -= lambda_[i] * r.coef[k];
    }
    build_eliminations(u);
  } else {
    // Penalised rows: the law's status and pressure at each iteration; the first iteration of
    // an instant keeps the rows it starts with closed (CONTACT_INIT='OUI', or the last
    // instant's), so that a body held only by contact is held from the start.
    for (size_t i = 0; i < rows_.size(); ++i) {
      MortarRow& r = rows_[i];
      const double g = r.weighted_gap(u) / r.d, rho = rho_[r.zone];
      const bool active = law_->status(-lambda_[i], g, rho) || (first_iteration_ && r.active);
      if (active != r.active) r.active = active, changed_in_newton_ = true, ++n_status_changes_;
      const ContactPoint p = as_point(i);
      // The row pushes with the law's pressure (negative in compression) along grad g~.
      const double pressure = active ? law_->pressure(p, -lambda_[i], g, rho) : 0.0;
      lambda_[i] = -pressure;
      for (size_t k = 0; k < r.eq.size(); ++k) residual[r.eq[k]] += pressure * r.coef[k];
      // Tangent beta grad g grad g^T with grad g = grad g~ / D_j. Every row's block is emitted
      // (zeros when open): the pattern follows the pairing only.
      const double f = law_->coefficients(p, rho).beta / (r.d * r.d);
      for (size_t a = 0; a < r.eq.size(); ++a)
        for (size_t b = 0; b < r.eq.size(); ++b) tangent.emplace_back(r.eq[a], r.eq[b], f * r.coef[a] * r.coef[b]);
    }
  }
  first_iteration_ = false;
}

bool MortarProblem::newton_converged() const { return !changed_in_newton_; }

bool MortarProblem::settle(const Vector& u, const Log& log) {
  if (def_.reac_geom == GeometryUpdate::None) return true;
  // Converged when the nodes of the zones moved little since the last pairing.
  const double resi = geometric_residual(segments_.geometry_nodes(), dofs_, dim_, u, u_at_pairing_);
  if (resi <= def_.resi_geom) return true;
  // Otherwise pair again in the converged configuration; a pairing that gives the same rows
  // (a translation, small strain) leaves everything as it is. The rows of surfaces that all
  // moved by one vector (to 1e-10 of the smallest slave edge; on an AXIS model, along the
  // axis: r dl follows the radius) are those of the last pairing, without integrating them.
  if (moved_as_one(u)) return true;
  MortarPairingRows pairing = segments_.pair(dofs_, u, shared_);
  const std::vector<MortarRow>& rows = pairing.rows;
  ++n_row_builds_;
  // Same rows: same nodes, and coefficients equal to 1e-10 of the row's largest (a term at
  // round-off level, e.g. a zero-length overlap at coincident nodes, counts as zero).
  bool same = rows.size() == rows_.size();
  for (size_t i = 0; same && i < rows.size(); ++i) {
    const MortarRow &a = rows[i], &b = rows_[i];
    same = a.node == b.node && std::abs(a.d - b.d) <= 1e-10 * b.d;
    double scale = 0.0;
    for (double c : b.coef) scale = std::max(scale, std::abs(c));
    auto value = [](const MortarRow& r, int eq) {
      for (size_t k = 0; k < r.eq.size(); ++k)
        if (r.eq[k] == eq) return r.coef[k];
      return 0.0;
    };
    for (size_t k = 0; same && k < a.eq.size(); ++k) same = std::abs(a.coef[k] - value(b, a.eq[k])) <= 1e-10 * scale;
    for (size_t k = 0; same && k < b.eq.size(); ++k) same = std::abs(b.coef[k] - value(a, b.eq[k])) <= 1e-10 * scale;
  }
  if (same) return true;
  if (def_.reac_geom == GeometryUpdate::Controlled && n_pairings_ >= def_.nb_iter_geom) return true;
  if (++n_geom_iter_ > def_.iter_geom_maxi) {
    ConvergenceError err("mortar contact: the pairing still changed after " + std::to_string(def_.iter_geom_maxi) +
                             " re-pairings",
                         {"smaller load increments may help"});
    err.failure().what = Failure::What::GeometryLoop;
    err.failure().limit = def_.iter_geom_maxi;
    throw err;
  }
  adopt(u, std::move(pairing), nullptr);
  log.info("mortar contact: new pairing (geometry iteration " + std::to_string(n_geom_iter_) + ")");
  return false;
}

bool MortarProblem::moved_as_one(const Vector& u) const {
  if (segments_.geometry_nodes().empty() || u_at_pairing_.size() != u.size()) return false;
  const double tol = 1e-10 * *std::min_element(h_.begin(), h_.end());
  auto motion = [&](int node, int k) {
    const int eq = dofs_.dof(node, k);
    return eq >= 0 ? u[eq] - u_at_pairing_[eq] : 0.0;
  };
  double ref[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < dim_; ++k) ref[k] = motion(segments_.geometry_nodes()[0], k);
  if (def_.axisymmetric && !(std::abs(ref[0]) <= tol)) return false;
  for (int node : segments_.geometry_nodes())
    for (int k = 0; k < dim_; ++k)
      if (!(std::abs(motion(node, k) - ref[k]) <= tol)) return false;
  return true;
}

unsigned long long MortarProblem::status_key() const {
  unsigned long long h = 1469598103934665603ULL;
  for (const auto& r : rows_) h = (h ^ static_cast<unsigned long long>(r.active)) * 1099511628211ULL;
  return h;
}

int MortarProblem::n_active() const {
  return static_cast<int>(std::count_if(rows_.begin(), rows_.end(), [](const auto& r) { return r.active; }));
}

namespace {

/// What a mortar pairing is made of, kept by a snapshot: the rows (their statuses included),
/// the master terms, the configuration paired and the pressures.
struct MortarPairing {
  std::vector<MortarRow> rows;
  std::vector<std::vector<std::pair<int, double>>> masters;
  Vector u_at_pairing;
  std::vector<int> row_of_node;
  std::vector<double> lambda;
};

}  // namespace

ContactSnapshot MortarProblem::snapshot() const {
  ContactSnapshot s;
  s.first_step = first_step_;
  for (const auto& r : rows_) s.active.push_back(r.active);
  // begin_step keeps the last pairing after the first step: a step split after a failure
  // must start from the pairing of the step's start, not from the failed attempt's last one.
  if (!first_step_)
    s.pairing = std::make_shared<const MortarPairing>(
        MortarPairing{rows_, master_terms_, u_at_pairing_, row_of_node_, lambda_});
  return s;
}

void MortarProblem::restore(const ContactSnapshot& state) {
  // Before the first step: the next begin_step pairs again and applies CONTACT_INIT.
  first_step_ = state.first_step;
  if (state.pairing) {
    const auto& p = *static_cast<const MortarPairing*>(state.pairing.get());
    rows_ = p.rows;
    master_terms_ = p.masters;
    u_at_pairing_ = p.u_at_pairing;
    row_of_node_ = p.row_of_node;
    lambda_ = p.lambda;
  }
  ++pattern_version_;
}

namespace {

/// The index of LAGS_C in the displacements, the component added (undefined everywhere) if
/// they have none.
int lags_c_of(NodalField& depl) {
  const std::string name = component_name(LAGS_C);
  int lags = depl.component_index(name);
  if (lags >= 0) return lags;
  std::vector<std::string> components = depl.components;
  components.push_back(name);
  NodalField wider(components, depl.n_nodes);
  for (int node = 0; node < depl.n_nodes; ++node)
    for (int c = 0; c < depl.n_components(); ++c)
      if (depl.has(node, c)) wider.set(node, c, depl.value(node, c));
  depl = std::move(wider);
  return depl.component_index(name);
}

}  // namespace

void MortarProblem::write_initial_fields(ResultStep& step) const {
  // Before contact: no pressure at the nodes of the slave surfaces, where LAGS_C will live.
  NodalField& depl = step.nodal.at(kDisplacementField);
  const int lags = lags_c_of(depl);
  for (int z = 0; z < segments_.n_zones(); ++z)
    for (const OrientedCell& oc : segments_.slave_cells(z))
      for (int k = 0; k < oc.n; ++k) depl.set(oc.nodes[k], lags, 0.0);
}

void MortarProblem::write_fields(const Vector& u, ResultStep& step) const {
  // LAGS_C in DEPL: the nodal pressure, negative in compression (no unknown carries it).
  NodalField& depl = step.nodal.at(kDisplacementField);
  const int lags = lags_c_of(depl);
  std::vector<NodalContactState> states(rows_.size());
  for (size_t i = 0; i < rows_.size(); ++i) {
    const MortarRow& r = rows_[i];
    const double lambda = r.active ? lambda_[i] : 0.0;
    depl.set(r.node, lags, -lambda);
    NodalContactState& s = states[i];
    s.node = r.node;
    s.active = r.active;
    s.gap = r.weighted_gap(u) / r.d;
    for (int k = 0; k < dim_; ++k) s.force[k] = -lambda * r.d * r.normal[k];  // -lambda D_j n_j
    s.pressure = -lambda;
  }
  step.nodal[kContactStateField] = nodal_contact_field(states, mesh_.n_nodes(), dim_);
}

}  // namespace lunaster::engine::contact
