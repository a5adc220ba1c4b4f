/// Integration-point discretisation of the continuous formulation: the points of an
/// integration rule on each slave cell (discretisation.hpp).
#include <algorithm>
#include <cstddef>
#include <map>
#include <vector>

#include "engine/contact/discretisation.hpp"
#include "engine/contact/integration_rules.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/memory.hpp"

namespace lunaster::engine::contact {

namespace {

class IntegrationPoints final : public Discretisation {
 public:
  bool linear_master() const override { return false; }
  bool nodal() const override { return false; }
  bool weight_follows_geometry() const override { return true; }

  void build_points(const Mesh& mesh, int /*dim*/, int z, const ContactZone& zone,
                    std::vector<ContactPoint>& points) override {
    // One rule per cell type of the zone. The points are sized once: a point is about 800
    // bytes (its linear gap), and growing the vector by doubling copied the 32,400 points of
    // the 3D benchmark twice over onto fresh pages.
    std::map<CellType, std::vector<ContactQuadPoint>> rules;
    size_t count = points.size();
    for (int c : zone.slave_cells) {
      auto [it, added] = rules.try_emplace(mesh.cell_types[c]);
      if (added) it->second = contact_integration_rule(it->first, zone.integration, zone.integration_order, zone.sub_elements);
      count += it->second.size();
    }
    points.reserve(count);
    advise_huge_pages(points.data(), sizeof(ContactPoint) * count);
    for (int c : zone.slave_cells) {
      const CellType t = mesh.cell_types[c];
      for (const auto& q : rules.at(t)) {
        ContactPoint p;
        p.zone = z;
        p.slave_cell = c;
        p.xi[0] = q.xi[0], p.xi[1] = q.xi[1];
        p.weight = q.weight;
        p.n_slave = surface_n_nodes(t);
        std::copy(mesh.cell(c), mesh.cell(c) + p.n_slave, p.slave_nodes);
        surface_shape(t, p.xi, p.phi, nullptr, nullptr);
        points.push_back(p);
      }
    }
  }
};

}  // namespace

std::unique_ptr<Discretisation> make_integration_points() { return std::make_unique<IntegrationPoints>(); }

}  // namespace lunaster::engine::contact
