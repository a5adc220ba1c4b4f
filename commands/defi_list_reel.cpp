// DEFI_LIST_REEL: a list of reals (instants), by intervals or by values.
#include <cmath>

#include "commands/commands.hpp"
#include "commands/concepts.hpp"

namespace lunaster::cmd {

ConceptPtr defi_list_reel(const Args& args, Session&) {
  auto list = std::make_shared<ListR8>();
  if (args.has("VALE")) {
    list->values = args.reals("VALE");
  } else {
    double x = args.real("DEBUT");
    list->values.push_back(x);
    for (const auto& occ : args.factors("INTERVALLE")) {
      const double end = occ.real("JUSQU_A");
      if (end <= x)
        throw occ.error("JUSQU_A", "real > " + number_text(x) + " (the previous point of the list)",
                        number_text(end));
      long long n = 0;
      if (occ.has("NOMBRE")) {
        n = occ.integer("NOMBRE");
      } else {
        const double step = occ.real("PAS");
        n = std::llround((end - x) / step);
        if (n < 1 || std::abs(n * step - (end - x)) > 1e-9 * std::abs(end - x))
          throw occ.error("PAS", "a step dividing the interval [" + number_text(x) + ", " + number_text(end) + "]",
                          number_text(step));
      }
      if (n < 1) throw occ.error("NOMBRE", "at least 1", std::to_string(n));
      for (long long i = 1; i <= n; ++i) list->values.push_back(i == n ? end : x + (end - x) * double(i) / double(n));
      x = end;
    }
  }
  // VALE is taken as given; intervals could only fail here through round-off of huge NOMBRE.
  for (size_t i = 1; i < list->values.size(); ++i)
    if (list->values[i] <= list->values[i - 1])
      throw args.error(args.has("VALE") ? "VALE" : "INTERVALLE", "strictly increasing values",
                       number_text(list->values[i]) + " after " + number_text(list->values[i - 1]) + " (value " +
                           std::to_string(i + 1) + ")");
  return list;
}

}  // namespace lunaster::cmd
