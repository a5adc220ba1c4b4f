// lunaster-meshgen: generates the SSNP121 meshes and unit blocks as MED or Gmsh
// files, and prints a summary of a mesh file (--info). Usage: lunaster-meshgen --help.
#include <algorithm>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/io/gmsh_reader.hpp"
#include "engine/io/med_reader.hpp"
#include "engine/io/med_writer.hpp"
#include "tools/aster_mail_writer.hpp"
#include "tools/gmsh_writer.hpp"
#include "tools/hertz_mesh.hpp"
#include "tools/ssnp121_mesh.hpp"

namespace {

using namespace lunaster;

const char* kUsage =
    "usage:\n"
    "  lunaster-meshgen --upper TYPE:N --lower TYPE:N [--top TYPE:N] [--x-range X0,X1] [--refine K] [--glued]\n"
    "                   [--name MESH] -o FILE.med\n"
    "      SSNP121 2D: PLAQUE1 = [-1,1]x[0,1] (upper), PLAQUE2 = [-1,1]x[-1,0]; TYPE quad4|quad8|tria3|tria6;\n"
    "      --top: a third block PLAQUE3 = [-1,1]x[1,2] (edges IJ JK KL LI, nodes I J K L P), meshed apart\n"
    "      --x-range: [X0,X1] instead of [-1,1] (axisymmetric sections: x = r)\n"
    "      --gibi-node-names: nodes named in the order code_aster's GIBI script of SSNP121 creates its\n"
    "      points (corners, then the edges' inner points), as in code_aster's mesh of the case\n"
    "  lunaster-meshgen --v1 TYPE:NXxNYxNZ --v2 TYPE:NXxNYxNZ [--v3 TYPE:NXxNYxNZ] [--refine K] [--glued]\n"
    "                   [--name MESH] -o FILE.med\n"
    "      SSNP121 3D: V1 = [0,1]^3, V2 = [0,1]^2x[1,2]; TYPE hexa8|hexa20|penta6|penta15|tetra4|tetra10;\n"
    "      --v3: a third block V3 = [0,1]^2x[2,3] (faces SURBA3 z=2, SURCH3 z=3, nodes A31..A34), meshed apart\n"
    "      --x-faces: the sides x = 0 and x = 1 of V1 and V2 as face groups X0_V1 X1_V1 X0_V2 X1_V2\n"
    "  lunaster-meshgen --ring TYPE:NTxNR --sleeve TYPE:NTxNR [--radii A,B,C] [--refine K] [--name MESH] -o FILE.med\n"
    "      quarter ring RING (A <= r <= B) fitted in a sleeve SLEEVE (B <= r <= C), meshed independently\n"
    "      (non-matching on r = B when the NT differ); NT cells along the arc, NR through the thickness;\n"
    "      TYPE quad4|quad8 (quad8 arc edges curved, mid-side nodes on the circle); default radii 0.5,0.75,1\n"
    "      groups RING SLEEVE INNER RING_OUT SLEEVE_IN OUTER X0_RING Y0_RING X0_SLEEVE Y0_SLEEVE,\n"
    "      nodes A_X A_Y P_X P_Y (ring, r = A, B) Q_X Q_Y C_X C_Y (sleeve, r = B, C)\n"
    "  lunaster-meshgen --block TYPE:N [--distort A] [--rect X0,X1,Y0,Y1] [--name MESH] -o FILE.med\n"
    "      unit square/cube; --distort moves interior vertices by up to A cell sizes (default 0.2 if given without A)\n"
    "      --rect X0,X1,Y0,Y1 (2D types): the rectangle [X0,X1]x[Y0,Y1] instead (axisymmetric sections: x = r)\n"
    "  lunaster-meshgen --hertz TYPE:N [--radius R] [--box W,H] [--grading G] [--refine K] [--full] [--name MESH] -o FILE.med\n"
    "      Hertz contact: ball of radius R (default 1) resting on a block, touching at O = origin, meshed\n"
    "      independently (non-matching). 2D (TYPE quad4|quad8|tria3|tria6; axisymmetric x = r, y = axis, or a\n"
    "      plane-strain cylinder): BALL = quarter disc x >= 0, y <= R centred at (0,R), BLOCK = [0,W]x[-H,0].\n"
    "      3D (TYPE hexa8|hexa20): BALL = quarter (x,y >= 0) of the sphere's lower half, BLOCK = [0,W]^2x[-H,0].\n"
    "      Cell size at O h0 = R/(N K); with --grading G > 1 (default 1) a uniform core of m = round(1/(G-1))\n"
    "      cells per direction around O, then layers one cell thick growing by about G; G = 1: (quasi-)uniform.\n"
    "      Quadratic edges on the sphere have their mid-side nodes on it. Default W = H = R.\n"
    "      groups BALL BLOCK BALL_SURF (curved side) BALL_TOP (flat top, load) BLOCK_TOP (contact)\n"
    "      BLOCK_BOTTOM BLOCK_SIDE, 2D AXIS_BALL AXIS_BLOCK (x = 0), 3D SYMX_BALL SYMX_BLOCK (x = 0)\n"
    "      SYMY_BALL SYMY_BLOCK (y = 0); nodes O_BALL O_BLOCK (contact point), C_BALL (top of the axis),\n"
    "      D_BLOCK (bottom of the axis). Nodes of BLOCK_TOP near O sit at multiples of h0 (the core); list\n"
    "      them with --info FILE --nodes BLOCK_TOP to pick the node nearest a radius\n"
    "      --full (2D): the whole cylinder on the whole block, the half model mirrored about x = 0 (the\n"
    "      axis groups dropped, the mirrored nodes named on from the last): a load along x\n"
    "  lunaster-meshgen --info FILE [--nodes GROUP[,GROUP]]    (.med, or .msh for Gmsh)\n"
    "      --nodes also lists the nodes of these groups (node or cell groups): 'node NAME X Y Z'\n"
    "  --test-result adds an analytic result RESU (2 steps, DEPL and SIGM_ELNO) for interop tests\n"
    "  --mirror GROUP[,GROUP] lists the volume cells of these groups in mirror order (clockwise in 2D) and\n"
    "      reverses the boundary cells on them, as Gmsh does for a clockwise curve loop\n"
    "  -o FILE.mail writes code_aster's text format instead of MED\n"
    "  -o FILE.msh writes Gmsh ASCII instead of MED (--msh-version 2.2 or 4.1, default 4.1; node groups\n"
    "      become physical point groups)\n";

struct Options {
  std::map<std::string, std::string> values;
  bool glued = false;
  bool gibi_names = false;
  bool test_result = false;
  bool x_faces = false;
  bool full = false;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--glued") {
      o.glued = true;
    } else if (a == "--gibi-node-names") {
      o.gibi_names = true;
    } else if (a == "--test-result") {
      o.test_result = true;
    } else if (a == "--x-faces") {
      o.x_faces = true;
    } else if (a == "--full") {
      o.full = true;
    } else if (a == "--distort" && (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0)) {
      o.values["--distort"] = "0.2";
    } else if (a == "-o" || a == "--upper" || a == "--lower" || a == "--v1" || a == "--v2" || a == "--block" ||
               a == "--ring" || a == "--sleeve" || a == "--radii" || a == "--nodes" ||
               a == "--refine" || a == "--distort" || a == "--name" || a == "--info" || a == "--mirror" ||
               a == "--msh-version" || a == "--hertz" || a == "--radius" || a == "--box" || a == "--grading" ||
               a == "--rect" || a == "--x-range" || a == "--top" || a == "--v3") {
      if (i + 1 >= argc) throw DeckError("meshgen: option " + a + " needs a value");
      o.values[a] = argv[++i];
    } else {
      throw DeckError("meshgen: unknown option '" + a + "'", {kUsage});
    }
  }
  return o;
}

/// Comma-separated numbers of an option; DeckError naming the option on anything else.
std::vector<double> number_list(const std::string& text, const std::string& option) {
  std::vector<double> out;
  std::stringstream list(text);
  for (std::string v; std::getline(list, v, ',');) {
    size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(v, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != v.size())
      throw DeckError("meshgen: " + option + " expects comma-separated numbers, got '" + text + "'");
    out.push_back(x);
  }
  return out;
}

tools::BlockCells refined(const std::string& spec, int dim, int refine) {
  tools::BlockCells cells = tools::parse_block_cells(spec, dim);
  for (int a = 0; a < dim; ++a) cells.n[a] *= refine;
  return cells;
}

/// Analytic result for interoperability tests (tests/quick/meshio_interop.py
/// recomputes it): steps t = 0.5, 1.0; DEPL: DX = t x, DY = t (x + 2 y),
/// [DZ = t z], LAGS_C = -1e5 t where x >= 0 (undefined, written 0, elsewhere);
/// SIGM_ELNO on every cell: SIXX = t x(node), SIYY = t (y(node) + 10 k), k = local node.
std::vector<engine::ResultStep> test_result(const engine::Mesh& mesh) {
  std::vector<engine::ResultStep> steps(2);
  for (int s = 0; s < 2; ++s) {
    const double t = 0.5 * (s + 1);
    steps[s].nume_ordre = s + 1;
    steps[s].inst = t;
    std::vector<std::string> cmps{"DX", "DY"};
    if (mesh.dim == 3) cmps.push_back("DZ");
    cmps.push_back("LAGS_C");
    engine::NodalField depl(cmps, mesh.n_nodes());
    const int lags = static_cast<int>(cmps.size()) - 1;
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      const double* x = mesh.node(n);
      depl.set(n, 0, t * x[0]);
      depl.set(n, 1, t * (x[0] + 2 * x[1]));
      if (mesh.dim == 3) depl.set(n, 2, t * x[2]);
      if (x[0] >= 0) depl.set(n, lags, -1e5 * t);
    }
    engine::ElnoField sig;
    sig.components = {"SIXX", "SIYY"};
    sig.cell_offsets = {0};
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int rows = mesh.cell_n_nodes(c);
      for (int k = 0; k < rows; ++k) {
        const double* x = mesh.node(mesh.cell(c)[k]);
        sig.values.push_back(t * x[0]);
        sig.values.push_back(t * (x[1] + 10 * k));
      }
      sig.cell_offsets.push_back(sig.cell_offsets.back() + rows);
    }
    steps[s].nodal["DEPL"] = depl;
    steps[s].elno["SIGM_ELNO"] = sig;
  }
  return steps;
}

int print_info(const std::string& path, const std::string& node_groups) {
  const bool gmsh = path.size() > 4 && path.substr(path.size() - 4) == ".msh";
  const engine::Mesh mesh = gmsh ? engine::read_gmsh(path) : engine::read_med(path);
  std::cout << "mesh " << mesh.name << "\n";
  std::cout << "dim " << mesh.dim << "\n";
  std::cout << "nodes " << mesh.n_nodes() << "\n";
  std::map<std::string, int> counts;
  for (auto t : mesh.cell_types) ++counts[std::string(engine::cell_info(t).name)];
  for (const auto& [name, n] : counts) std::cout << "cells " << name << " " << n << "\n";
  for (const auto& [name, list] : mesh.cell_groups) std::cout << "cell_group " << name << " " << list.size() << "\n";
  for (const auto& [name, list] : mesh.node_groups) std::cout << "node_group " << name << " " << list.size() << "\n";
  std::stringstream groups(node_groups);
  std::cout.precision(17);
  for (std::string g; std::getline(groups, g, ',');) {
    std::vector<int> nodes;
    if (const auto it = mesh.node_groups.find(g); it != mesh.node_groups.end()) nodes = it->second;
    else if (const auto ct = mesh.cell_groups.find(g); ct != mesh.cell_groups.end()) nodes = mesh.nodes_of_cells(ct->second);
    else throw DeckError("meshgen: --nodes: no node or cell group '" + g + "' in " + path);
    for (int n : nodes)
      std::cout << "node " << mesh.node_names[n] << " " << mesh.node(n)[0] << " " << mesh.node(n)[1] << " "
                << mesh.node(n)[2] << "\n";
  }
  return 0;
}

/// The Hertz scene of --hertz TYPE:N with --radius, --box, --grading and --full; prints its layout.
engine::Mesh hertz_mesh(const Options& o, int refine) {
  const auto get = [&](const std::string& key) {
    const auto it = o.values.find(key);
    return it == o.values.end() ? std::string() : it->second;
  };
  engine::Mesh mesh;
  tools::HertzOptions opt;
  const std::string spec = get("--hertz");
  const auto colon = spec.find(':');
  std::string name = spec.substr(0, colon);
  std::transform(name.begin(), name.end(), name.begin(), ::toupper);
  if (colon == std::string::npos || !engine::cell_type_from_name(name, opt.type))
    throw DeckError("meshgen: --hertz expects TYPE:N (quad4, quad8, tria3, tria6, hexa8, hexa20), got '" + spec + "'");
  const std::string count = spec.substr(colon + 1);
  if (count.empty() || count.size() > 6 || count.find_first_not_of("0123456789") != std::string::npos)
    throw DeckError("meshgen: --hertz: bad cell count in '" + spec + "'");
  opt.n = std::stoi(count);
  opt.refine = refine;
  const auto number = [&](const std::string& key, const std::string& text) {
    size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size()) throw DeckError("meshgen: " + key + " expects a number, got '" + text + "'");
    return x;
  };
  if (!get("--radius").empty()) opt.radius = number("--radius", get("--radius"));
  opt.width = opt.height = opt.radius;
  if (!get("--box").empty()) {
    const std::string box = get("--box");
    const auto comma = box.find(',');
    if (comma == std::string::npos) throw DeckError("meshgen: --box expects W,H, got '" + box + "'");
    opt.width = number("--box", box.substr(0, comma));
    opt.height = number("--box", box.substr(comma + 1));
  }
  if (!get("--grading").empty()) opt.grading = number("--grading", get("--grading"));
  tools::HertzLayout lay;
  mesh = tools::make_hertz(opt, &lay);
  if (o.full) {
    if (mesh.dim != 2) throw DeckError("meshgen: --full mirrors a 2D --hertz mesh about x = 0", {kUsage});
    mesh = tools::mirrored_about_x0(mesh, 1e-9 * opt.radius);
  }
  std::cout << "hertz: h0 " << lay.h0 << ", ball core " << lay.m_ball << " layers " << lay.layers_ball
            << " growth " << lay.g_ball << ", block core " << lay.m_block[0] << " layers " << lay.layers_block
            << " growth " << lay.g_block[0] << "\n";
  return mesh;
}

int run(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  const Options o = parse(argc, argv);
  const auto get = [&](const std::string& key) {
    const auto it = o.values.find(key);
    return it == o.values.end() ? std::string() : it->second;
  };
  if (!get("--info").empty()) return print_info(get("--info"), get("--nodes"));
  if (!get("--nodes").empty()) throw DeckError("meshgen: --nodes needs --info FILE", {kUsage});
  const std::string out = get("-o");
  if (out.empty()) throw DeckError("meshgen: missing -o FILE.med", {kUsage});
  const int refine = get("--refine").empty() ? 1 : std::stoi(get("--refine"));
  if (refine < 1) throw DeckError("meshgen: --refine must be >= 1");
  const bool ring = !get("--ring").empty() || !get("--sleeve").empty();
  if (!get("--radii").empty() && !ring) throw DeckError("meshgen: --radii needs --ring/--sleeve", {kUsage});
  const bool hertz = !get("--hertz").empty();
  for (const char* key : {"--radius", "--box", "--grading"})
    if (!get(key).empty() && !hertz) throw DeckError(std::string("meshgen: ") + key + " needs --hertz", {kUsage});
  engine::Mesh mesh;
  if (hertz) {
    mesh = hertz_mesh(o, refine);
  } else if (!get("--upper").empty() || !get("--lower").empty()) {
    tools::Ssnp121Options2d opt;
    opt.upper = refined(get("--upper").empty() ? "quad4:12" : get("--upper"), 2, refine);
    opt.lower = refined(get("--lower").empty() ? "quad4:11" : get("--lower"), 2, refine);
    opt.glued = o.glued;
    if (!get("--top").empty()) opt.top = refined(get("--top"), 2, refine);
    if (!get("--x-range").empty()) {
      const std::vector<double> r = number_list(get("--x-range"), "--x-range");
      if (r.size() != 2) throw DeckError("meshgen: --x-range expects X0,X1, got '" + get("--x-range") + "'");
      opt.x0 = r[0], opt.x1 = r[1];
    }
    mesh = tools::make_ssnp121_2d(opt);
    if (o.gibi_names) tools::name_nodes_as_gibi_script(mesh);
  } else if (!get("--v1").empty() || !get("--v2").empty()) {
    tools::Ssnp121Options3d opt;
    opt.v1 = refined(get("--v1").empty() ? "hexa20:4" : get("--v1"), 3, refine);
    opt.v2 = refined(get("--v2").empty() ? "hexa20:4" : get("--v2"), 3, refine);
    if (!get("--v3").empty()) opt.v3 = refined(get("--v3"), 3, refine);
    opt.glued = o.glued;
    opt.x_faces = o.x_faces;
    mesh = tools::make_ssnp121_3d(opt);
  } else if (ring) {
    tools::RingOptions opt;
    opt.ring = refined(get("--ring").empty() ? "quad4:12x4" : get("--ring"), 2, refine);
    opt.sleeve = refined(get("--sleeve").empty() ? "quad4:9x4" : get("--sleeve"), 2, refine);
    if (!get("--radii").empty()) {
      const std::vector<double> r = number_list(get("--radii"), "--radii");
      if (r.size() != 3) throw DeckError("meshgen: --radii expects three radii A,B,C, got '" + get("--radii") + "'");
      opt.a = r[0], opt.b = r[1], opt.c = r[2];
    }
    mesh = tools::make_ring_sleeve(opt);
  } else if (!get("--block").empty()) {
    tools::BlockOptions opt;
    const std::string spec = get("--block");
    engine::CellType type;
    std::string name = spec.substr(0, spec.find(':'));
    std::transform(name.begin(), name.end(), name.begin(), ::toupper);
    const int dim = engine::cell_type_from_name(name, type) ? engine::cell_info(type).dim : 3;
    opt.cells = refined(spec, dim, refine);
    opt.distort = get("--distort").empty() ? 0.0 : std::stod(get("--distort"));
    if (!get("--rect").empty()) {
      const std::vector<double> r = number_list(get("--rect"), "--rect");
      if (r.size() != 4) throw DeckError("meshgen: --rect expects X0,X1,Y0,Y1, got '" + get("--rect") + "'");
      opt.lo = {r[0], r[2]}, opt.hi = {r[1], r[3]};
    }
    mesh = tools::make_block(opt);
  } else {
    throw DeckError("meshgen: nothing to generate", {kUsage});
  }
  if (!get("--name").empty()) mesh.name = get("--name");
  if (!get("--mirror").empty()) {
    std::vector<std::string> groups;
    std::stringstream list(get("--mirror"));
    for (std::string g; std::getline(list, g, ',');) groups.push_back(g);
    tools::mirror_cell_groups(mesh, groups);
  }
  const bool gmsh = out.size() > 4 && out.substr(out.size() - 4) == ".msh";
  const bool mail = out.size() > 5 && out.substr(out.size() - 5) == ".mail";
  if (mail) {
    if (o.test_result || !get("--msh-version").empty())
      throw DeckError("meshgen: --test-result and --msh-version need a .med or .msh output");
    tools::write_aster_mail(out, mesh);
  } else if (gmsh) {
    if (o.test_result) throw DeckError("meshgen: --test-result needs a .med output");
    tools::write_gmsh(out, mesh, get("--msh-version").empty() ? "4.1" : get("--msh-version"));
  } else {
    if (!get("--msh-version").empty()) throw DeckError("meshgen: --msh-version needs a .msh output");
    const std::vector<engine::ResultStep> steps = o.test_result ? test_result(mesh) : std::vector<engine::ResultStep>{};
    engine::write_med(out, mesh, {{"RESU", &steps}});
  }
  std::cout << out << ": " << mesh.n_nodes() << " nodes, " << mesh.n_cells() << " cells\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const lunaster::Error& e) {
    std::cerr << e.format() << "\n";
    return static_cast<int>(e.kind());
  } catch (const std::exception& e) {
    std::cerr << "meshgen: " << e.what() << "\n";
    return 2;
  }
}
