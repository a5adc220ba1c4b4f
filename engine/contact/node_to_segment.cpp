/// Node-to-segment (2D) / node-to-facet (3D) discretisation: one contact point per
/// slave vertex (discretisation.hpp).
#include <map>
#include <set>

#include "engine/contact/contact_common.hpp"
#include "engine/contact/discretisation.hpp"
#include "engine/contact/integration_rules.hpp"
#include "engine/contact/surface_element.hpp"

namespace lunaster::engine::contact {

namespace {

class NodeToSegment final : public Discretisation {
 public:
  explicit NodeToSegment(bool axisymmetric) : axisymmetric_(axisymmetric) {}
  bool linear_master() const override { return true; }
  bool nodal() const override { return true; }
  bool weight_follows_geometry() const override { return false; }

  void build_points(const Mesh& mesh, int /*dim*/, int z, const ContactZone& zone,
                    std::vector<ContactPoint>& points) override {
    // Tributary areas of the slave vertices: integral of the linear shape functions.
    std::map<int, double> area;
    for (int c : zone.slave_cells) {
      const CellType t = linear_type(mesh.cell_types[c]);
      const int nv = surface_n_nodes(t);
      double xyz[3 * kMaxSurfaceNodes], n[kMaxSurfaceNodes];
      for (int a = 0; a < nv; ++a)
        for (int i = 0; i < 3; ++i) xyz[3 * a + i] = mesh.node(mesh.cell(c)[a])[i];
      for (const auto& q : contact_integration_rule(t, IntegrationScheme::Gauss, 2)) {
        const SurfacePoint sp = surface_point(t, xyz, q.xi);
        surface_shape(t, q.xi, n, nullptr, nullptr);
        const double radius = axisymmetric_ ? sp.x[0] : 1.0;  // AXIS: r dl per radian
        for (int a = 0; a < nv; ++a) area[mesh.cell(c)[a]] += q.weight * sp.jacobian * radius * n[a];
      }
    }
    points.reserve(points.size() + area.size());
    for (const auto& [node, a] : area) {
      ContactPoint p;
      p.zone = z;
      p.weight = a;
      p.n_slave = 1;
      p.slave_nodes[0] = node;
      p.phi[0] = 1.0;
      points.push_back(p);
    }
  }

  void build_relations(const Mesh& mesh, int dim, const ContactZone& zone, LinearRelations& relations) override {
    // QUAD8 faces on either side: tie each mid-side node to its edge (code_aster CONTACT_8),
    // u_m - (u_a + u_b) / 2 = 0, scaled by the squared edge length (conditioning only).
    std::vector<int> faces = zone.slave_cells;
    faces.insert(faces.end(), zone.master_cells.begin(), zone.master_cells.end());
    for (int c : faces) {
      const CellType type = mesh.cell_types[c];
      free_mid_side_ |= linear_type(type) != type && type != CellType::Quad8;  // SEG3, TRIA6
      if (type != CellType::Quad8) continue;
      const int* nodes = mesh.cell(c);
      for (int e = 0; e < 4; ++e) {
        const int mid = nodes[4 + e], a = nodes[e], b = nodes[(e + 1) % 4];
        if (!tied_.insert(mid).second) continue;
        double scale = 0.0;
        for (int i = 0; i < 3; ++i) {
          const double d = mesh.node(a)[i] - mesh.node(b)[i];
          scale += d * d;
        }
        for (int k = 0; k < dim; ++k) {
          LinearRelation r;
          r.terms = {{mid, k, scale}, {a, k, -0.5 * scale}, {b, k, -0.5 * scale}};
          r.carrier_node = mid;
          r.carrier_component = LAGR_DX + k;
          r.label = "discrete contact's tie of QUAD8 mid-side node " + node_label(mesh, mid) + " (D" +
                    static_cast<char>('X' + k) + ")";
          relations.add(std::move(r));
        }
      }
    }
  }

  void report(const Log& log) const override {
    if (!tied_.empty())
      log.info("discrete contact on QUAD8 faces: " + std::to_string(tied_.size()) +
               " mid-side node(s) tied to the mean of their edge's vertices (linear relations); only vertex "
               "nodes are slave nodes");
    if (free_mid_side_)
      log.warning("discrete contact on quadratic SEG3/TRIA6 faces: only vertex nodes are slave nodes and master "
                  "cells are linearised; their mid-side nodes are not constrained and may penetrate (the "
                  "continuous formulation integrates quadratic faces)");
  }

 private:
  bool axisymmetric_;
  std::set<int> tied_;
  bool free_mid_side_ = false;
};

}  // namespace

std::unique_ptr<Discretisation> make_node_to_segment(bool axisymmetric) {
  return std::make_unique<NodeToSegment>(axisymmetric);
}

}  // namespace lunaster::engine::contact
