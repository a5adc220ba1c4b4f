#include "engine/contact/compatibility.hpp"

#include <map>

#include "engine/contact/contact_common.hpp"
#include "engine/contact/integration_rules.hpp"
#include "engine/contact/surface_element.hpp"

namespace lunaster::engine {

bool contact_pairing_compatible(CellType slave, CellType master) {
  const bool quad_slave = slave == CellType::Quad4 || slave == CellType::Quad8;
  return !(quad_slave && master == CellType::Tria6);
}

std::string contact_pairing_warning(int zone_index, CellType slave, const std::string& slave_cell, CellType master,
                                    const std::string& master_cell) {
  return "contact zone " + std::to_string(zone_index + 1) + ": slave " + contact::surface_type_name(slave) +
         " cell " + slave_cell + " faces master " + contact::surface_type_name(master) + " cell " + master_cell +
         ": this pairing does not satisfy the compatibility conditions for integrating the contact terms "
         "(R5.03.52), the contact pressure may be wrong; use the same element type on both surfaces "
         "(QUAD8/QUAD8, TRIA6/TRIA6) or a triangle slave on a quadrangle master (e.g. TRIA6 slave on QUAD8 master)";
}

std::vector<std::string> check_contact_zone_compatibility(const Mesh& mesh, const ContactZone& zone,
                                                          int zone_index) {
  std::map<CellType, int> slave_first, master_first;
  for (int c : zone.slave_cells) slave_first.emplace(mesh.cell_types[c], c);
  for (int c : zone.master_cells) master_first.emplace(mesh.cell_types[c], c);
  std::vector<std::string> out;
  for (const auto& [st, sc] : slave_first)
    for (const auto& [mt, mc] : master_first)
      if (!contact_pairing_compatible(st, mt))
        out.push_back(contact_pairing_warning(zone_index, st, contact::cell_label(mesh, sc), mt,
                                              contact::cell_label(mesh, mc)));
  return out;
}

namespace {

/// True when every point of `rule` is a vertex of the reference cell of `type`.
bool at_vertices_only(CellType type, const std::vector<contact::ContactQuadPoint>& rule) {
  const bool simplex = type == CellType::Tria3 || type == CellType::Tria6;
  for (const auto& q : rule) {
    bool vertex = true;
    for (int d = 0; d < 2; ++d) {
      const double x = q.xi[d];
      vertex = vertex && (simplex ? (x == 0.0 || x == 1.0) : (x == -1.0 || x == 1.0 || (d == 1 && (type == CellType::Seg2 || type == CellType::Seg3))));
    }
    if (!vertex) return false;
  }
  return true;
}

}  // namespace

std::vector<IntegrationWarning> check_contact_zone_integration(const Mesh& mesh, const ContactZone& zone,
                                                               int zone_index) {
  std::map<CellType, int> slave_first;
  for (int c : zone.slave_cells) slave_first.emplace(mesh.cell_types[c], c);
  std::vector<IntegrationWarning> out;
  std::map<CellType, int> quadratic_master;
  for (int c : zone.master_cells)
    if (cell_info(mesh.cell_types[c]).order == 2) quadratic_master.emplace(mesh.cell_types[c], c);
  for (const auto& [type, cell] : slave_first) {
    const auto rule = contact::contact_integration_rule(type, zone.integration, zone.integration_order, zone.sub_elements);
    const size_t n_points = rule.size();
    if (cell_info(type).order == 1 && !quadratic_master.empty() && at_vertices_only(type, rule)) {
      const auto& [mtype, mcell] = *quadratic_master.begin();
      out.push_back({IntegrationWarning::Kind::VerticesOnlyOnQuadraticMaster,
                     "contact zone " + std::to_string(zone_index + 1) + ": linear slave " +
                    contact::surface_type_name(type) + " cell " + contact::cell_label(mesh, cell) +
                    " is integrated at its vertices only against quadratic master " +
                    contact::surface_type_name(mtype) + " cell " + contact::cell_label(mesh, mcell) +
                    ": where slave vertices fall on master vertices the master mid-side nodes receive no "
                    "contact force and the pressure is wrong; use a rule with interior points, or a "
                    "quadratic slave surface"});
    }
    const int n_multipliers = cell_info(type).n_nodes;
    if (n_points < static_cast<size_t>(n_multipliers))
      out.push_back({IntegrationWarning::Kind::TooFewPoints,
                     "contact zone " + std::to_string(zone_index + 1) + ": the integration rule has " +
                    std::to_string(n_points) + " point(s) on slave " + contact::surface_type_name(type) + " cell " +
                    contact::cell_label(mesh, cell) + ", which carries " + std::to_string(n_multipliers) +
                    " " + component_name(LAGS_C) + " unknowns: the contact pressure is under-determined (singular system or wrong "
                    "values); raise the rule's order or use the automatic, Simpson or Newton-Cotes rule"});
  }
  return out;
}

}  // namespace lunaster::engine
