#pragma once
/// Where the contact conditions live: a discretisation turns the slave and master
/// surfaces of each zone into contact points (contact_point.hpp) and says how their
/// weights follow the geometry. It enforces nothing: that is the law's part
/// (contact_law.hpp). The shared part (contact_problem.hpp) pairs the points,
/// initialises and updates statuses through the law, and writes CONT_NOEU. Mortar's
/// segment-to-segment discretisation produces dual rows instead, one per slave node, which
/// a law may hold by elimination: mortar_segments.hpp, with its own shared part
/// (mortar_problem.hpp).
///
/// - NodeToSegment (node_to_segment.cpp): code_aster's FORMULATION='DISCRETE'
///   (R5.03.50). One point per slave vertex, weighted by its tributary length/area
///   (integral of its linear shape function over the slave cells; AXIS: times r, per
///   radian, so a discrete E_N is a spring per radian); quadratic cells are
///   linearised (vertices only on both sides); each QUAD8 face's mid-side nodes are tied
///   to the mean of their edge's vertices (linear relations, code_aster's CONTACT_8);
///   SEG3/TRIA6 mid-side nodes stay free (reported).
/// - IntegrationPoints (integration_points.cpp): code_aster's FORMULATION='CONTINUE'
///   (R5.03.52). The points of an integration rule on each slave cell
///   (integration_rules.hpp); every slave node carries LAGS_C; the weight is the rule's
///   weight times the slave Jacobian in the configuration of the pairing.
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/assembly/linear_relations.hpp"
#include "engine/contact/contact_definition.hpp"
#include "engine/contact/contact_point.hpp"
#include "engine/core/log.hpp"
#include "engine/mesh/mesh.hpp"

namespace lunaster::engine::contact {

class Discretisation {
 public:
  virtual ~Discretisation() = default;
  /// Points of zone `z` (appended; consecutive points of one slave cell share their nodes).
  virtual void build_points(const Mesh& mesh, int dim, int z, const ContactZone& zone,
                            std::vector<ContactPoint>& points) = 0;
  /// Linear relations the discretisation needs between displacement components (appended).
  virtual void build_relations(const Mesh& /*mesh*/, int /*dim*/, const ContactZone& /*zone*/,
                               LinearRelations& /*relations*/) {}
  /// True: master cells are used as their vertex-only linear cells.
  virtual bool linear_master() const = 0;
  /// True: one point per slave node (CONT_NOEU then reports the points themselves).
  virtual bool nodal() const = 0;
  /// True: the weight of a point follows the slave cell's Jacobian at each pairing.
  virtual bool weight_follows_geometry() const = 0;
  /// Diagnostics after the first pairing.
  virtual void report(const Log& /*log*/) const {}
};

/// `axisymmetric`: tributary areas in the AXIS measure r dl (per radian, reference radius).
std::unique_ptr<Discretisation> make_node_to_segment(bool axisymmetric = false);
std::unique_ptr<Discretisation> make_integration_points();

}  // namespace lunaster::engine::contact
