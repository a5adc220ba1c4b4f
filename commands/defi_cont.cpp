// DEFI_CONT: mortar contact definition (code_aster 17 syntax).
#include "commands/commands.hpp"
#include "commands/concepts.hpp"
#include "commands/contact_keywords.hpp"
#include "commands/selection.hpp"
#include "engine/contact/contact_factory.hpp"
#include "engine/core/error.hpp"

namespace lunaster::cmd {

ConceptPtr defi_cont(const Args& args, Session& session) {
  auto result = std::make_shared<CharContact>();
  result->modele = args.concept_as<Modele>("MODELE");
  const Modele& mo = *result->modele;
  auto& def = result->contact;
  def.reac_geom = args.text("REAC_GEOM") == "SANS" ? engine::GeometryUpdate::None : engine::GeometryUpdate::Automatic;
  def.iter_geom_maxi = static_cast<int>(args.integer("ITER_GEOM_MAXI"));
  def.resi_geom = args.real("RESI_GEOM");
  for (const auto& zone : args.factors("ZONE")) {
    // 'MORTAR' is the one pairing DEFI_CONT offers (the catalogue refuses any other).
    LUNASTER_ASSERT(zone.text("APPARIEMENT") == "MORTAR", "DEFI_CONT: unexpected APPARIEMENT");
    const std::string algo = zone.text("ALGO_CONT");
    const engine::ContactMethod method =
        algo == "PENALISATION" ? engine::ContactMethod::MortarPenalty : engine::ContactMethod::MortarLagrange;
    if (!def.zones.empty() && method != def.method)
      throw zone.error("ALGO_CONT", "the same contact algorithm in every zone", "'" + algo + "'");
    def.method = method;
    engine::ContactZone z = read_contact_zone(zone, *mo.maillage->mesh, mo.dim, method);
    // COEF_CONT is the penalty of ALGO_CONT='PENALISATION' (Pa/m), the complementarity
    // constant of 'LAGRANGIEN' (relative) otherwise.
    (method == engine::ContactMethod::MortarPenalty ? z.coef_pena : z.coef_cont) = zone.real("COEF_CONT");
    z.dist_mait = zone.real("DIST_MAIT");
    z.dist_escl = zone.real("DIST_ESCL");
    def.zones.push_back(std::move(z));
  }
  // The surfaces are checked here, where the deck names them (boundary of the model, cell
  // types); on a mesh in parts whole.
  const ContactSurfaces surfaces = contact_surfaces(def, mo);
  warn_contact_surfaces(args.factors("ZONE"), surfaces, *mo.maillage, session, false);
  engine::make_contact_hook(surfaces.definition, *surfaces.mesh, mo.dim);
  return result;
}

}  // namespace lunaster::cmd
