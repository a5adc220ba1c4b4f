#pragma once
// Test helper: a pressurised quarter ring (a = 0.5, b = 0.75) in a sleeve (c = 1), plane strain,
// E 2e11 / 1e11, nu 0.3 / 0.25, symmetry conditions on x = 0 and y = 0, and mortar contact of
// the ring's outer arc (slave) on the sleeve's inner arc (testcases/ring_sleeve_mortar.lua).
#include <string>

#include "engine/contact/contact_definition.hpp"
#include "engine/fe/fe_model.hpp"
#include "engine/nonlinear/loads.hpp"
#include "tools/ssnp121_mesh.hpp"
#include "two_blocks.hpp"

namespace contact_test {

struct RingSleeve {
  Mesh mesh;
  FeModel model;
  ContactDefinition contact;  ///< mortar LAGRANGIEN, CONTACT_INIT='OUI'
  MechanicalLoads loads;      ///< pressure `p` on the ring's inner arc, ramped with t
};

/// `ring`, `sleeve`: cell specs ("quad4:12x2"); equal arc counts make the interface match.
inline void make_ring_sleeve_scene(RingSleeve& s, const std::string& ring, const std::string& sleeve, double p) {
  lunaster::tools::RingOptions opt;
  opt.ring = lunaster::tools::parse_block_cells(ring, 2);
  opt.sleeve = lunaster::tools::parse_block_cells(sleeve, 2);
  s.mesh = lunaster::tools::make_ring_sleeve(opt);
  s.model = make_model(s.mesh, 2e11, 0.3);
  s.model.materials.push_back({1e11, 0.25, 0.0});
  for (int c : s.mesh.cell_groups.at("SLEEVE")) s.model.material[c] = 1;
  s.contact = ContactDefinition{};
  s.contact.method = ContactMethod::MortarLagrange;
  ContactZone zone;
  zone.slave_cells = s.mesh.cell_groups.at("RING_OUT");
  zone.master_cells = s.mesh.cell_groups.at("SLEEVE_IN");
  zone.init = ContactInit::Yes;
  zone.coef_cont = 100.0;
  s.contact.zones.push_back(zone);
  s.contact.modulus = 2e11;
  s.loads = MechanicalLoads{};
  s.loads.multipliers.push_back([](double t) { return t; });
  for (const char* g : {"X0_RING", "X0_SLEEVE"})
    for (int n : s.mesh.nodes_of_cells(s.mesh.cell_groups.at(g))) s.loads.dirichlet.push_back({n, DX, 0.0, 0});
  for (const char* g : {"Y0_RING", "Y0_SLEEVE"})
    for (int n : s.mesh.nodes_of_cells(s.mesh.cell_groups.at(g))) s.loads.dirichlet.push_back({n, DY, 0.0, 0});
  s.loads.pressures.push_back({s.mesh.cell_groups.at("INNER"), p, 0});
}

}  // namespace contact_test
