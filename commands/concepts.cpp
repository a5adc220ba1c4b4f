#include "commands/concepts.hpp"

#include "commands/commands.hpp"
#include "commands/formula.hpp"

#include <algorithm>
#include <cstdio>

namespace lunaster::cmd {

double Fonction::operator()(double x) const {
  const size_t n = abscissas.size();
  if (n == 0) throw InternalError("empty function");
  if (n == 1) return ordinates[0];
  auto extrapolate = [&](char prol, size_t i0, size_t i1) {
    if (prol == 'C') return ordinates[x < abscissas[0] ? 0 : n - 1];
    if (prol == 'L') {
      const double s = (x - abscissas[i0]) / (abscissas[i1] - abscissas[i0]);
      return ordinates[i0] + s * (ordinates[i1] - ordinates[i0]);
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "function %s evaluated at %s = %g, outside [%g, %g] with prolongation EXCLU",
                  user_name.empty() ? "DEFI_FONCTION" : user_name.c_str(), nom_para.c_str(), x, abscissas.front(),
                  abscissas.back());
    throw DeckError(buf, {"extend VALE or set PROL_GAUCHE / PROL_DROITE to 'CONSTANT' or 'LINEAIRE'"});
  };
  const double tol = 1e-12 * std::max(1.0, std::abs(abscissas.back() - abscissas.front()));
  if (x < abscissas.front() - tol) return extrapolate(prol_gauche, 0, 1);
  if (x > abscissas.back() + tol) return extrapolate(prol_droite, n - 2, n - 1);
  auto it = std::upper_bound(abscissas.begin(), abscissas.end(), x);
  size_t i1 = static_cast<size_t>(it - abscissas.begin());
  if (i1 >= n) i1 = n - 1;
  if (i1 == 0) i1 = 1;
  const size_t i0 = i1 - 1;
  const double s = (x - abscissas[i0]) / (abscissas[i1] - abscissas[i0]);
  return ordinates[i0] + s * (ordinates[i1] - ordinates[i0]);
}

double Fonction::evaluate(const std::vector<double>& values) const {
  if (values.size() != 1)
    throw DeckError("function " + (user_name.empty() ? std::string("DEFI_FONCTION") : user_name) + " of " + nom_para +
                    " called with " + std::to_string(values.size()) + " values");
  return (*this)(values[0]);
}

double Formule::evaluate(const std::vector<double>& values) const {
  if (values.size() != nom_para.size())
    throw DeckError("FORMULE " + user_name + " of " + std::to_string(nom_para.size()) + " parameter(s) called with " +
                    std::to_string(values.size()) + " value(s)");
  try {
    return compiled(values);
  } catch (const FormulaDomainError& e) {
    std::string at;
    for (std::size_t i = 0; i < values.size(); ++i)
      at += (i ? ", " : "") + nom_para[i] + " = " + number_text(values[i]);
    throw DeckError("FORMULE " + (user_name.empty() ? std::string() : user_name + " ") + "'" + vale + "': " + e.what +
                    " at " + at);
  }
}

}  // namespace lunaster::cmd
