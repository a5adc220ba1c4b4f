// MODI_MAILLAGE: rotates the mesh (ROTATION), orients boundary cells outward (ORIE_PEAU_2D / ORIE_PEAU_3D).
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/selection.hpp"
#include "engine/mesh/orientation.hpp"
#include "engine/mesh/transform.hpp"

#include <array>
#include <cmath>
#include <sstream>

namespace lunaster::cmd {

namespace {

std::string format_vector(const std::vector<double>& v) {
  std::ostringstream out;
  out << "{";
  for (size_t i = 0; i < v.size(); ++i) out << (i ? ", " : " ") << v[i];
  out << " }";
  return out.str();
}

/// One ROTATION occurrence: the axis is DIR, or POIN_2 - POIN_1, or z; in a 2D mesh it must be along z.
void rotate(const Args& occ, engine::Mesh& mesh, Session& session, bool say) {
  const std::vector<double> p1 = occ.reals("POIN_1");
  const std::array<double, 3> point = {p1[0], p1[1], p1.size() > 2 ? p1[2] : 0.0};
  std::array<double, 3> axis = {0.0, 0.0, 1.0};
  std::string axis_kw;
  if (occ.has("DIR")) {
    const std::vector<double> d = occ.reals("DIR");
    axis = {d[0], d[1], d[2]};
    axis_kw = "DIR";
  } else if (occ.has("POIN_2")) {
    const std::vector<double> p2 = occ.reals("POIN_2");
    if (p2.size() != p1.size())
      throw occ.error("POIN_2", std::to_string(p1.size()) + " coordinates, as POIN_1", format_vector(p2));
    axis = {p2[0] - point[0], p2[1] - point[1], (p2.size() > 2 ? p2[2] : 0.0) - point[2]};
    axis_kw = "POIN_2";
  }
  const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(length > 0.0)) {
    throw occ.error(axis_kw, axis_kw == "DIR" ? "a non-zero direction" : "a point other than POIN_1",
                    format_vector(occ.reals(axis_kw)));
  }
  if (mesh.dim == 2 && std::hypot(axis[0], axis[1]) > 1e-12 * length) {
    throw occ.error(axis_kw, "an axis along z in a 2D mesh (the mesh must stay in its plane)",
                    "the axis " + format_vector({axis[0], axis[1], axis[2]}),
                    {"omit DIR and POIN_2 to rotate about z"});
  }
  if (mesh.dim == 2) axis = {0.0, 0.0, axis[2] > 0.0 ? 1.0 : -1.0};
  const double degrees = occ.real("ANGLE");
  constexpr double kPi = 3.14159265358979323846;
  engine::rotate_mesh(mesh, point, axis, degrees * kPi / 180.0);
  if (!say) return;
  std::ostringstream msg;
  msg << "  ROTATION: " << mesh.n_nodes() << " nodes rotated by " << degrees << " degrees about "
      << format_vector({axis[0], axis[1], axis[2]}) << " through " << format_vector({point[0], point[1], point[2]});
  session.log().info(msg.str());
}

/// The occurrences of MODI_MAILLAGE on one mesh; `say` logs what they did.
void modify(const Args& args, engine::Mesh& mesh, Session& session, bool say);

}  // namespace

ConceptPtr modi_maillage(const Args& args, Session& session) {
  auto ma = args.concept_as<Maillage>("MAILLAGE");
  // A mesh in parts: each rank changes its part (a boundary cell's volume cell is in every part
  // holding it), and rank 0 the whole mesh as well, which it writes and logs.
  const std::vector<engine::Mesh*> meshes = ma->changed_meshes();
  for (engine::Mesh* mesh : meshes) modify(args, *mesh, session, mesh == meshes.back());
  return ma;
}

namespace {

void modify(const Args& args, engine::Mesh& mesh, Session& session, bool say) {
  for (const auto& occ : args.factors("ROTATION")) rotate(occ, mesh, session, say);
  for (const char* kw : {"ORIE_PEAU_2D", "ORIE_PEAU_3D"}) {
    for (const auto& occ : args.factors(kw)) {
      const int needed = std::string(kw) == "ORIE_PEAU_2D" ? 2 : 3;
      if (mesh.dim != needed)
        throw occ.error("GROUP_MA", "a " + std::to_string(needed) + "D mesh for " + kw,
                        "a " + std::to_string(mesh.dim) + "D mesh", {"use ORIE_PEAU_" + std::to_string(mesh.dim) + "D"});
      for (const auto& g : occ.texts("GROUP_MA")) {
        const auto cells = cell_group(occ, "GROUP_MA", mesh, g);
        const int flipped = engine::orient_boundary_outward(mesh, cells);
        if (say)
          session.log().info("  " + std::string(kw) + " " + g + ": " + std::to_string(flipped) + " of " +
                           std::to_string(cells.size()) + " cells reoriented");
      }
    }
  }
}

}  // namespace

}  // namespace lunaster::cmd
