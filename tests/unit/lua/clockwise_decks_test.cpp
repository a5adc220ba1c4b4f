// The orientation decks testcases/clockwise_2d_pressure.lua and clockwise_2d_contact.lua run through
// the real runner and handlers; every reading of a scene (counter-clockwise or clockwise cells,
// MED, Gmsh 2.2 or Gmsh 4.1) must give the same fields as the counter-clockwise MED reading, node
// by node and component by component, to 1e-12 of the largest magnitude of that component:
// DEPL (with the contact pressure LAGS_C), SIGM_NOEU and SIGM_ELNO (matched through the global
// node of each row, the reoriented cells listing their nodes in another order).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

#include "commands/concepts.hpp"
#include "commands/registry.hpp"
#include "lua/bridge.hpp"
#include "lua/runner.hpp"

using namespace lunaster;

namespace {

namespace fs = std::filesystem;

/// One deck run with its log captured, its Lua state kept for reading the results.
struct DeckRun {
  std::ostringstream out;
  Log log{out, 1};
  cmd::Session session{log};
  std::unique_ptr<lua::Runner> runner;

  explicit DeckRun(const std::string& name) {
    const fs::path deck = fs::path(LUNASTER_SOURCE_DIR) / "testcases" / (name + ".lua");
    session.deck_path = deck;
    session.output_dir = fs::path(LUNASTER_BINARY_DIR) / "test-scratch" / "clockwise_decks" / name;
    fs::remove_all(session.output_dir);
    runner = std::make_unique<lua::Runner>(session, [](const std::string& c) { return cmd::find_handler(c); });
    runner->run_file(deck);
  }

  /// RESULTS[group][label] of the Lua global table `table`.
  std::shared_ptr<cmd::EvolNoli> result(const std::string& table, const std::string& group, const std::string& label) {
    lua_State* L = runner->state();
    lua_getglobal(L, table.c_str());
    lua_getfield(L, -1, group.c_str());
    lua_getfield(L, -1, label.c_str());
    catalog::ConceptPtr* c = lua::to_concept(L, -1);
    auto r = c ? std::dynamic_pointer_cast<cmd::EvolNoli>(*c) : nullptr;
    lua_pop(L, 3);
    return r;
  }
};

/// Largest |value| of each component of a nodal field.
std::vector<double> magnitudes(const engine::NodalField& f) {
  std::vector<double> m(f.n_components(), 0.0);
  for (int n = 0; n < f.n_nodes; ++n)
    for (int k = 0; k < f.n_components(); ++k)
      if (f.has(n, k)) m[k] = std::max(m[k], std::abs(f.value(n, k)));
  return m;
}

void expect_same_nodal(const engine::NodalField& a, const engine::NodalField& b, bool loaded, const std::string& what) {
  ASSERT_EQ(a.components, b.components) << what;
  ASSERT_EQ(a.n_nodes, b.n_nodes) << what;
  const std::vector<double> scale = magnitudes(a);
  for (int k = 0; k < a.n_components(); ++k) {
    if (loaded) {
      EXPECT_GT(scale[k], 0.0) << what << " " << a.components[k] << ": a zero field compares nothing";
    }
    for (int n = 0; n < a.n_nodes; ++n) {
      ASSERT_EQ(a.has(n, k), b.has(n, k)) << what << " " << a.components[k] << " node " << n + 1;
      if (!a.has(n, k)) continue;
      EXPECT_LE(std::abs(a.value(n, k) - b.value(n, k)), 1e-12 * scale[k])
          << what << " " << a.components[k] << " node " << n + 1 << ": " << a.value(n, k) << " vs " << b.value(n, k);
    }
  }
}

void expect_same_elno(const engine::Mesh& ma, const engine::ElnoField& a, const engine::Mesh& mb,
                      const engine::ElnoField& b, bool loaded, const std::string& what) {
  ASSERT_EQ(a.components, b.components) << what;
  std::vector<double> scale(a.n_components(), 0.0);
  for (size_t i = 0; i < a.values.size(); ++i)
    scale[i % a.components.size()] = std::max(scale[i % a.components.size()], std::abs(a.values[i]));
  int rows = 0;
  for (int c = 0; c < a.n_cells(); ++c) {
    if (a.n_rows(c) == 0) continue;
    const int d = mb.find_cell(ma.cell_names[c]);
    ASSERT_GE(d, 0) << what << " " << ma.cell_names[c];
    ASSERT_EQ(a.n_rows(c), b.n_rows(d)) << what << " " << ma.cell_names[c];
    for (int i = 0; i < a.n_rows(c); ++i) {
      const int node = ma.cell(c)[i];
      const int* other = mb.cell(d);
      const int j = static_cast<int>(std::find(other, other + b.n_rows(d), node) - other);
      ASSERT_LT(j, b.n_rows(d)) << what << " " << ma.cell_names[c] << ": node " << node + 1 << " not in the cell";
      for (int k = 0; k < a.n_components(); ++k, ++rows)
        EXPECT_LE(std::abs(a.value(c, i, k) - b.value(d, j, k)), 1e-12 * scale[k])
            << what << " " << a.components[k] << " " << ma.cell_names[c] << " row " << i;
    }
  }
  EXPECT_GT(rows, 0) << what;
  for (size_t k = 0; k < scale.size() && loaded; ++k) EXPECT_GT(scale[k], 0.0) << what << " " << a.components[k];
}

/// Compares `other` with `reference`: same mesh nodes, same fields.
void expect_same_result(const cmd::EvolNoli& reference, const cmd::EvolNoli& other, const std::string& what) {
  const engine::Mesh& ma = *reference.modele->maillage->mesh;
  const engine::Mesh& mb = *other.modele->maillage->mesh;
  ASSERT_EQ(ma.coords, mb.coords) << what << ": the scenes must share their nodes";
  ASSERT_EQ(reference.steps.size(), other.steps.size()) << what;
  ASSERT_GT(reference.steps.back().inst, 0.0) << what;
  for (size_t s = 0; s < reference.steps.size(); ++s) {
    const auto& ra = reference.steps[s];
    const auto& rb = other.steps[s];
    for (const char* field : {"DEPL", "SIGM_NOEU"}) {
      ASSERT_TRUE(ra.nodal.count(field) && rb.nodal.count(field)) << what << " " << field;
      expect_same_nodal(ra.nodal.at(field), rb.nodal.at(field), ra.inst > 0.0, what + " " + field);
    }
    ASSERT_TRUE(ra.elno.count("SIGM_ELNO") && rb.elno.count("SIGM_ELNO")) << what;
    expect_same_elno(ma, ra.elno.at("SIGM_ELNO"), mb, rb.elno.at("SIGM_ELNO"), ra.inst > 0.0, what + " SIGM_ELNO");
  }
}

/// Number of occurrences of `text` in `s`.
int count(const std::string& s, const std::string& text) {
  int n = 0;
  for (size_t p = s.find(text); p != std::string::npos; p = s.find(text, p + 1)) ++n;
  return n;
}

TEST(ClockwiseDecks, PressureBlockSameFieldsEveryOrientationAndFormat) {
  DeckRun run("clockwise_2d_pressure");
  const std::string out = run.out.str();
  EXPECT_EQ(run.session.n_nook(), 0) << out;
  EXPECT_EQ(run.session.n_ok(), 2 * 6 * 8);
  EXPECT_EQ(run.log.n_warnings(), 0) << out;
  // 2 cell types x 3 files of clockwise cells, 9 QUAD8 / 18 TRIA6 each
  EXPECT_EQ(count(out, ": 9 clockwise cell(s) reoriented counter-clockwise"), 3) << out;
  EXPECT_EQ(count(out, ": 18 clockwise cell(s) reoriented counter-clockwise"), 3) << out;
  for (const char* cell : {"quad8", "tria6"}) {
    const auto reference = run.result("PRESSURE_RESULTS", cell, "ccw_med");
    ASSERT_TRUE(reference) << cell;
    for (const char* label : {"cw_med", "ccw_msh22", "cw_msh22", "ccw_msh41", "cw_msh41"}) {
      const auto other = run.result("PRESSURE_RESULTS", cell, label);
      ASSERT_TRUE(other) << cell << " " << label;
      expect_same_result(*reference, *other, std::string(cell) + " " + label);
    }
  }
}

TEST(ClockwiseDecks, ContactSameFieldsEveryOrientationAndFormat) {
  DeckRun run("clockwise_2d_contact");
  const std::string out = run.out.str();
  EXPECT_EQ(run.session.n_nook(), 0) << out;
  EXPECT_EQ(run.session.n_ok(), 9 * 2 * 9);
  EXPECT_EQ(run.log.n_warnings(), 0) << out << "\n(no master cell may need its normal reversed)";
  EXPECT_EQ(count(out, ": 32 clockwise cell(s) reoriented counter-clockwise"), 3) << out;  // lower block
  EXPECT_EQ(count(out, ": 36 clockwise cell(s) reoriented counter-clockwise"), 3) << out;  // upper block
  for (const char* formulation : {"CONTINUE", "DISCRETE"}) {
    const auto reference = run.result("CONTACT_RESULTS", formulation, "ccw_med");
    ASSERT_TRUE(reference) << formulation;
    for (const char* variant : {"ccw", "cw_master", "cw_slave"})
      for (const char* format : {"med", "msh22", "msh41"}) {
        const std::string label = std::string(variant) + "_" + format;
        if (label == "ccw_med") continue;
        const auto other = run.result("CONTACT_RESULTS", formulation, label);
        ASSERT_TRUE(other) << formulation << " " << label;
        expect_same_result(*reference, *other, std::string(formulation) + " " + label);
      }
  }
}

}  // namespace
