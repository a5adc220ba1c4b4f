#include "catalog/specs.hpp"

namespace lunaster::catalog {

const CommandSpec& fin_spec() {
  static const CommandSpec spec = make_command("FIN", "", "End of a study (optional)", {});
  return spec;
}

}  // namespace lunaster::catalog
