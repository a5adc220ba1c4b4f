// DEFI_FONCTION: piecewise linear function given as (x, y) pairs.

#include "commands/commands.hpp"
#include "commands/concepts.hpp"

namespace lunaster::cmd {

namespace {
char prolongation(const std::string& name) { return name == "CONSTANT" ? 'C' : name == "LINEAIRE" ? 'L' : 'E'; }
}  // namespace

ConceptPtr defi_fonction(const Args& args, Session&) {
  auto f = std::make_shared<Fonction>();
  f->nom_para = args.text("NOM_PARA");
  const std::vector<double> vale = args.reals("VALE");
  if (vale.size() % 2 != 0 || vale.size() < 2)
    throw args.error("VALE", "an even number of values (x1, y1, x2, y2, ...)", std::to_string(vale.size()) + " values");
  for (size_t i = 0; i < vale.size(); i += 2) {
    // Finite values are the catalogue's check; the order of the pairs is the command's.
    if (!f->abscissas.empty() && vale[i] <= f->abscissas.back())
      throw args.error("VALE", "strictly increasing abscissas x1 < x2 < ...",
                       "x" + std::to_string(i / 2 + 1) + " = " + number_text(vale[i]) + " after x" +
                           std::to_string(i / 2) + " = " + number_text(f->abscissas.back()) + " (value " +
                           std::to_string(i + 1) + " of VALE)");
    f->abscissas.push_back(vale[i]);
    f->ordinates.push_back(vale[i + 1]);
  }
  if (args.has("PROL_GAUCHE")) f->prol_gauche = prolongation(args.text("PROL_GAUCHE"));
  if (args.has("PROL_DROITE")) f->prol_droite = prolongation(args.text("PROL_DROITE"));
  return f;
}

}  // namespace lunaster::cmd
