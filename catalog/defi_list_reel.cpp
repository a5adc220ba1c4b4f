#include "catalog/common/keywords.hpp"
#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& defi_list_reel_spec() {
  static const CommandSpec spec = make_command(
      "DEFI_LIST_REEL", "listr8", "Define an increasing list of reals (time steps)",
      {real("DEBUT", "First value of the list"),
       factor("INTERVALLE",
              {real("JUSQU_A", "End of the interval").required(),
               integer("NOMBRE", "Number of equal steps in the interval").range(1, std::nullopt),
               real("PAS", "Step length in the interval").above(0.0)},
              "One interval after the previous end, cut into equal steps")
           .occurs(0, -1)
           .with_rules({exactly_one({"NOMBRE", "PAS"})}),
       real("VALE", "The values, given directly").many(), common::info()},
      {exactly_one({"DEBUT", "VALE"}), at_most_one({"VALE", "INTERVALLE"}), together({"DEBUT", "INTERVALLE"})});
  return spec;
}

}  // namespace lunaster::catalog
