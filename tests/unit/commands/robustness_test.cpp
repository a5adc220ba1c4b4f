// Robustness of the commands, run through the real catalogue (validation and
// defaults) and the real handlers: mesh warnings (nodes in no cell, coincident
// slave nodes on a contact surface) and atomic output (a failing IMPR_RESU never
// replaces a good file and leaves no temporary behind; IMPR_MESURE appends through one).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "catalog/args.hpp"
#include "catalog/spec.hpp"
#include "commands/concepts.hpp"
#include "commands/registry.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/mesh/orientation.hpp"

namespace lunaster::cmd {
namespace {

namespace fs = std::filesystem;
using catalog::KwNode;
using catalog::Value;

const fs::path kMeshes = fs::path(LUNASTER_SOURCE_DIR) / "testcases" / "errors" / "meshes";

/// One session with its log captured; decks are "located" in testcases/errors/.
struct Harness {
  std::ostringstream out;
  Log log{out, 1};
  Session session{log};
  explicit Harness(const std::string& name) {
    session.deck_path = fs::path(LUNASTER_SOURCE_DIR) / "testcases" / "errors" / (name + ".lua");
    session.output_dir = fs::path(LUNASTER_BINARY_DIR) / "test-scratch" / "robustness" / name;
    fs::remove_all(session.output_dir);
    fs::create_directories(session.output_dir);
  }
  /// Validates `node` against the catalogue entry of `command` and runs its handler.
  ConceptPtr run(const std::string& command, KwNode node) {
    const catalog::CommandSpec* spec = catalog::find_command(command);
    EXPECT_NE(spec, nullptr) << command;
    catalog::validate(*spec, node);
    session.current.command = command;
    const catalog::Args args(node, spec->body);
    return find_handler(command)(args, session);
  }
};

KwNode simple(std::initializer_list<std::pair<const char*, Value>> values) {
  KwNode node;
  for (const auto& [k, v] : values) node.simple[k] = {v};
  return node;
}

ConceptPtr read_gmsh(Harness& h, const std::string& file) {
  return h.run("LIRE_MAILLAGE", simple({{"FORMAT", std::string("GMSH")}, {"FICHIER", "meshes/" + file}}));
}

ConceptPtr plane_model(Harness& h, const ConceptPtr& mesh) {
  KwNode node = simple({{"MAILLAGE", mesh}});
  node.factors["AFFE"] = {simple({{"TOUT", std::string("OUI")},
                                  {"PHENOMENE", std::string("MECANIQUE")},
                                  {"MODELISATION", std::string("D_PLAN")}})};
  return h.run("AFFE_MODELE", node);
}

TEST(MeshWarnings, UnreferencedNodesAreNamedWithTheFile) {
  Harness h("unreferenced");
  read_gmsh(h, "unreferenced_nodes.msh");
  const std::string out = h.out.str();
  EXPECT_EQ(h.log.n_warnings(), 1) << out;
  EXPECT_NE(out.find("<A> LIRE_MAILLAGE: mesh file '"), std::string::npos) << out;
  EXPECT_NE(out.find("unreferenced_nodes.msh': 2 node(s) belong to no cell and carry no unknown: N7, N8"),
            std::string::npos)
      << out;
}

TEST(MeshWarnings, CleanMeshHasNoWarning) {
  Harness h("clean");
  read_gmsh(h, "block.msh");
  EXPECT_EQ(h.log.n_warnings(), 0) << h.out.str();
}

TEST(MeshOrientation, ClockwiseCellIsReorientedAndReportedOnce) {
  Harness h("clockwise");
  auto ma = std::dynamic_pointer_cast<Maillage>(read_gmsh(h, "clockwise_cell.msh"));
  const std::string out = h.out.str();
  EXPECT_EQ(h.log.n_warnings(), 0) << out;
  EXPECT_NE(out.find("  mesh clockwise_cell.msh: 1 clockwise cell(s) reoriented counter-clockwise (node order "
                     "reversed): M6\n"),
            std::string::npos)
      << out;
  const engine::Mesh& mesh = *ma->mesh;
  const int m6 = mesh.find_cell("M6");
  ASSERT_GE(m6, 0);
  EXPECT_NEAR(engine::cell_measure(mesh, m6), 1.0, 1e-15);
  EXPECT_NEAR(engine::cell_measure(mesh, mesh.find_cell("M5")), 1.0, 1e-15);
  // the file lists M6 as N2 N5 N6 N3 (clockwise): reversed, N2 stays first
  std::vector<std::string> names;
  for (int k = 0; k < 4; ++k) names.push_back(mesh.node_names[mesh.cell(m6)[k]]);
  EXPECT_EQ(names, (std::vector<std::string>{"N2", "N3", "N6", "N5"}));
  // a counter-clockwise mesh gets no such line
  Harness clean("clockwise_clean");
  read_gmsh(clean, "block.msh");
  EXPECT_EQ(clean.out.str().find("reoriented"), std::string::npos) << clean.out.str();
}

TEST(MeshOrientation, MirroredHexaIsReorientedAndReported) {
  // A unit HEXA8 in Gmsh order with bottom and top swapped: the mirror image of a valid cell.
  Harness h("mirrored");
  const fs::path file = h.session.output_dir / "mirrored.msh";
  std::ofstream(file) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n"
                         "4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n$Elements\n1\n"
                         "3 5 0 5 6 7 8 1 2 3 4\n$EndElements\n";
  auto ma = std::dynamic_pointer_cast<Maillage>(h.run(
      "LIRE_MAILLAGE", simple({{"FORMAT", std::string("GMSH")}, {"FICHIER", file.string()}})));
  const std::string out = h.out.str();
  EXPECT_EQ(h.log.n_warnings(), 0) << out;
  EXPECT_NE(out.find("  mesh mirrored.msh: 1 mirrored cell(s) reoriented (node order mirrored to MED's): M3\n"),
            std::string::npos)
      << out;
  EXPECT_NEAR(engine::cell_measure(*ma->mesh, 0), 1.0, 1e-15);
}

ConceptPtr contact_on(Harness& h, const ConceptPtr& model, const std::string& slave, const std::string& master) {
  KwNode node = simple({{"MODELE", model}, {"FORMULATION", std::string("DISCRETE")}});
  node.factors["ZONE"] = {simple({{"GROUP_MA_ESCL", slave}, {"GROUP_MA_MAIT", master}})};
  return h.run("DEFI_CONTACT", node);
}

TEST(MeshWarnings, CoincidentSlaveNodesOnAContactSurface) {
  Harness h("coincident");
  auto model = plane_model(h, read_gmsh(h, "duplicate_slave_nodes.msh"));
  ASSERT_EQ(h.log.n_warnings(), 0) << h.out.str();
  contact_on(h, model, "SLAVE", "MASTER");
  const std::string out = h.out.str();
  EXPECT_EQ(h.log.n_warnings(), 1) << out;
  EXPECT_NE(out.find("DEFI_CONTACT: ZONE[1].GROUP_MA_ESCL: slave surface 'SLAVE' of mesh file '"), std::string::npos)
      << out;
  EXPECT_NE(out.find("duplicate_slave_nodes.msh' has 1 pair(s) of distinct nodes at the same position: N2 and N7 at "
                     "(1, 0, 0)"),
            std::string::npos)
      << out;
}

TEST(MeshWarnings, MasterAsSlaveHasNoCoincidentNodes) {
  // The master surface is one connected line: its nodes are all distinct.
  Harness h("distinct");
  auto model = plane_model(h, read_gmsh(h, "duplicate_slave_nodes.msh"));
  contact_on(h, model, "MASTER", "SLAVE");
  EXPECT_EQ(h.log.n_warnings(), 0) << h.out.str();
}

/// A result with two steps of DEPL on the mesh of block.msh (values = step * node index).
std::shared_ptr<EvolNoli> make_result(Harness& h) {
  auto ma = std::dynamic_pointer_cast<Maillage>(read_gmsh(h, "block.msh"));
  auto resu = std::make_shared<EvolNoli>();
  resu->user_name = "RESU";
  resu->modele = std::make_shared<Modele>();
  resu->modele->maillage = ma;
  resu->modele->dim = 2;
  for (int k = 1; k <= 2; ++k) {
    engine::ResultStep step;
    step.nume_ordre = k;
    step.inst = 0.5 * k;
    engine::NodalField depl({"DX", "DY"}, ma->mesh->n_nodes());
    for (int n = 0; n < ma->mesh->n_nodes(); ++n) depl.set(n, 1, 1e-3 * k * n);
    step.nodal["DEPL"] = depl;
    resu->steps.push_back(step);
  }
  return resu;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Files in `dir` other than `keep` (temporaries left behind).
std::vector<std::string> strays(const fs::path& dir, const std::string& keep) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != keep) out.push_back(e.path().filename().string());
  return out;
}

TEST(AtomicOutput, FailingTableWriteKeepsThePreviousFile) {
  Harness h("atomic_table");
  auto resu = make_result(h);
  KwNode good = simple({{"FORMAT", std::string("RESULTAT")}, {"FICHIER", std::string("r.resu")}});
  good.factors["RESU"] = {simple({{"RESULTAT", resu}})};
  h.run("IMPR_RESU", good);
  const fs::path file = h.session.output_dir / "r.resu";
  const std::string before = slurp(file);
  ASSERT_NE(before.find("CHAMP DEPL  NUME_ORDRE 2"), std::string::npos) << before;

  // Second write: the first occurrence is written, the second names an unknown group.
  resu->steps[1].nodal["DEPL"].set(4, 1, 99.0);
  KwNode bad = good;
  bad.factors["RESU"].push_back(simple({{"RESULTAT", resu}, {"GROUP_NO", std::string("NOPE")}}));
  EXPECT_THROW(h.run("IMPR_RESU", bad), DeckError);
  EXPECT_EQ(slurp(file), before);
  EXPECT_TRUE(strays(h.session.output_dir, "r.resu").empty());
}

TEST(AtomicOutput, FailingMedWriteKeepsThePreviousFile) {
  Harness h("atomic_med");
  auto resu = make_result(h);
  KwNode node = simple({{"FICHIER", std::string("r.rmed")}});
  node.factors["RESU"] = {simple({{"RESULTAT", resu}})};
  h.run("IMPR_RESU", node);
  const fs::path file = h.session.output_dir / "r.rmed";
  const std::string before = slurp(file);

  // A result name too long for a MED field name: the writer fails after the mesh is written.
  resu->user_name = std::string(80, 'R');
  EXPECT_THROW(h.run("IMPR_RESU", node), Error);
  EXPECT_EQ(slurp(file), before);
  EXPECT_TRUE(strays(h.session.output_dir, "r.rmed").empty());
  // And the old file still reads back, values included.
  const auto steps = engine::read_med_nodal_field(file.string(), "RESU____DEPL");
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_DOUBLE_EQ(steps[1].field.value(5, 1), 1e-3 * 2 * 5);
}

TEST(AtomicOutput, MeasureRowsAreAppendedThroughATemporary) {
  Harness h("atomic_measure");
  auto resu = make_result(h);
  const auto row = [&](const std::string& label) {
    KwNode node = simple({{"FICHIER", std::string("m.csv")}, {"RESULTAT", resu}});
    node.simple["PARA"] = {Value(std::string("case"))};
    node.simple["VALE_K"] = {Value(label)};
    return node;
  };
  h.run("IMPR_MESURE", row("first"));
  h.run("IMPR_MESURE", row("second"));
  const fs::path file = h.session.output_dir / "m.csv";
  std::istringstream lines(slurp(file));
  std::string header, first, second, extra;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_EQ(header.rfind("case,nodes,unknowns,", 0), 0u) << header;
  EXPECT_NE(header.find(",resi_glob_rela,solve_resid_raw,solve_resid,refinements"), std::string::npos) << header;
  EXPECT_EQ(first.rfind("first,", 0), 0u) << first;
  EXPECT_EQ(second.rfind("second,", 0), 0u) << second;
  EXPECT_FALSE(std::getline(lines, extra));
  EXPECT_TRUE(strays(h.session.output_dir, "m.csv").empty());
  // Another set of columns is refused before anything is written.
  const std::string before = slurp(file);
  KwNode other = row("third");
  other.simple["PARA"] = {Value(std::string("method"))};
  EXPECT_THROW(h.run("IMPR_MESURE", other), DeckError);
  EXPECT_EQ(slurp(file), before);
}

/// DY at node group `group` of every step of field `field` in a MED file.
std::vector<double> dy_at(const fs::path& file, const std::string& field, const std::string& group) {
  const engine::Mesh mesh = engine::read_med(file.string());
  const int node = mesh.node_groups.at(group).at(0);
  std::vector<double> out;
  for (const auto& step : engine::read_med_nodal_field(file.string(), field)) out.push_back(step.field.value(node, 1));
  return out;
}

TEST(FailedSolve, EarlierFilesIntactAndConvergedStepsSaved) {
  // testcases/errors/contact_step_no_subdivision.lua: IMPR_RESU of a first result (0 -> 0.25),
  // then a second STAT_NON_LINE that converges at 0.25 and fails on 0.25 -> 1.
  const fs::path exe = fs::path(LUNASTER_BINARY_DIR) / "lunaster";
  ASSERT_TRUE(fs::exists(exe)) << "build the lunaster executable first";
  const fs::path deck = fs::path(LUNASTER_SOURCE_DIR) / "testcases" / "errors" / "contact_step_no_subdivision.lua";
  const fs::path out = fs::path(LUNASTER_BINARY_DIR) / "test-scratch" / "robustness" / "failed_solve";
  fs::remove_all(out);
  fs::create_directories(out);
  const std::string command = exe.string() + " run " + deck.string() + " --out " + out.string() + " > " +
                              (out / "log.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3) << slurp(out / "log.txt");

  // The file written before the failure reads back: initial state and INST 0.25.
  const auto before = dy_at(out / "before.rmed", "BEFORE__DEPL", "O");
  ASSERT_EQ(before.size(), 2u);
  EXPECT_EQ(before[0], 0.0);
  EXPECT_NEAR(before[1], -0.0125, 0.01 * 0.0125);  // uniform strain: DY(O) = U0 t / 2
  // The converged step of the failed run is saved, equal to the same step of the first run.
  const auto saved = dy_at(out / "contact_step_no_subdivision_converged.rmed", "RESU____DEPL", "O");
  ASSERT_EQ(saved.size(), 2u);
  EXPECT_NEAR(saved[1], before[1], 1e-12);
  EXPECT_TRUE(strays(out, "").size() == 3u) << "expected log.txt, before.rmed and the saved steps only";
}

TEST(ImprResu, NomCmpAndModeleRestrictTheTable) {
  // A model of one cell: FORMAT='RESULTAT' prints its nodes only, and of DEPL only DY (NOM_CMP).
  Harness h("impr_resu_restricted");
  auto resu = make_result(h);
  const engine::Mesh& mesh = *resu->modele->maillage->mesh;
  int cell = 0;
  while (engine::cell_info(mesh.cell_types[cell]).dim != 2) ++cell;
  resu->modele->modelisation.assign(mesh.n_cells(), engine::Modelisation::None);
  resu->modele->modelisation[cell] = engine::Modelisation::PlaneStrain;
  KwNode node = simple({{"FORMAT", std::string("RESULTAT")}, {"FICHIER", std::string("m.resu")},
                        {"MODELE", ConceptPtr(resu->modele)}});
  node.factors["RESU"] = {simple({{"RESULTAT", resu}, {"NOM_CMP", std::string("DY")}, {"NUME_ORDRE", 2LL}})};
  h.run("IMPR_RESU", node);
  const std::string text = slurp(h.session.output_dir / "m.resu");
  EXPECT_NE(text.find("CHAMP DEPL  NUME_ORDRE 2"), std::string::npos) << text;
  EXPECT_EQ(text.find("NUME_ORDRE 1"), std::string::npos) << text;
  EXPECT_NE(text.find("NOEUD                 DY\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("DX"), std::string::npos) << text;
  // One row per node of the cell, with the value make_result gave it (2e-3 n at step 2).
  std::istringstream rows(text.substr(text.find("DY\n") + 3));
  std::vector<std::string> printed;
  for (std::string line; std::getline(rows, line) && !line.empty();) printed.push_back(line);
  ASSERT_EQ(static_cast<int>(printed.size()), mesh.cell_n_nodes(cell)) << text;
  for (int a = 0; a < mesh.cell_n_nodes(cell); ++a) {
    const int n = mesh.cell(cell)[a];
    char expected[64];
    std::snprintf(expected, sizeof expected, "%-8s %15.8e", mesh.node_names[n].c_str(), 2e-3 * n);
    EXPECT_NE(std::find(printed.begin(), printed.end(), std::string(expected)), printed.end()) << expected << "\n" << text;
  }
}

}  // namespace
}  // namespace lunaster::cmd
