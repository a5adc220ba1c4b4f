#include "commands/test_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lunaster::cmd {

namespace {

std::string check_line(bool ok, const std::string& kind, const std::string& what, double refe, double calc, double err,
                       double tol, const std::string& critere) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "%s %-14s %s  refe=%.9e  calc=%.9e  err=%.3e  tol=%.3e  %s", ok ? " OK " : "NOOK",
                kind.c_str(), what.c_str(), refe, calc, err, tol, critere.c_str());
  return buf;
}

}  // namespace

double check_difference(double calc, double refe, bool relative, double magnitude) {
  const double d = std::abs(calc - refe);
  if (!relative) return d;
  const double scale = std::max(std::abs(refe), magnitude);
  return scale > 0.0 ? d / scale : d;
}

void report_checks(const catalog::Args& occ, Session& session, double value, const std::string& what_in,
                   bool integer_value) {
  const bool relative = occ.text("CRITERE") == "RELATIF";
  const double magnitude = occ.has("ORDRE_GRANDEUR") ? occ.real("ORDRE_GRANDEUR") : 0.0;
  // VALE_ABS='OUI' (code_aster): the absolute values of the computed value and of the
  // references are compared, and printed.
  const bool absolute = occ.text("VALE_ABS") == "OUI";
  const auto shown = [&](double x) { return absolute ? std::abs(x) : x; };
  const std::string what = absolute ? what_in + "  (absolute values)" : what_in;
  // VALE_CALC_I / VALE_REFE_I (where declared) give the references of an integer value.
  const bool with_ints = occ.declares("VALE_CALC_I");
  const bool calc_i = with_ints && occ.has("VALE_CALC_I"), refe_i = with_ints && occ.has("VALE_REFE_I");
  const char* calc_kw = calc_i ? "VALE_CALC_I" : "VALE_CALC";
  const char* refe_kw = refe_i ? "VALE_REFE_I" : "VALE_REFE";
  if ((calc_i || refe_i) && !integer_value)
    throw occ.error(calc_i ? calc_kw : refe_kw, std::string(calc_i ? "VALE_CALC" : "VALE_REFE") + " (the value tested is a real)",
                    "an integer reference");
  if (occ.has("REFERENCE") && !occ.has(refe_kw))
    throw occ.error("REFERENCE", "VALE_REFE or VALE_REFE_I with REFERENCE", "neither");
  const auto reference = [&](const char* kw, bool is_int) {
    return is_int ? static_cast<double>(occ.integer(kw)) : occ.real(kw);
  };
  value = shown(value);
  bool any = false;
  if (occ.has(calc_kw)) {
    any = true;
    const double refe = shown(reference(calc_kw, calc_i));
    const double tol = occ.real("TOLE_MACHINE");
    const double err = check_difference(value, refe, relative, magnitude);
    const bool ok = err <= tol;
    if (!session.code_aster_vale_calc) {
      session.tests.push_back({ok, check_line(ok, "NON_REGRESSION", what, refe, value, err, tol, occ.text("CRITERE"))});
      session.log().always(session.tests.back().text);
    } else {
      // A .comm's VALE_CALC is code_aster's result: the check compares lunaster with code_aster.
      session.comparisons.push_back({what, value, refe, err, tol});
      std::string line = check_line(ok, "CODE_ASTER", what, refe, value, err, tol, occ.text("CRITERE"));
      if (session.vale_calc_report) {
        line.replace(0, 4, ok ? "SAME" : "DIFF");  // a report line, not a check
        session.log().always(line);
      } else {
        session.tests.push_back({ok, line});
        session.log().always(line);
      }
    }
  }
  if (occ.has(refe_kw)) {
    any = true;
    const double refe = shown(reference(refe_kw, refe_i));
    const double tol = occ.real("PRECISION");
    const double err = check_difference(value, refe, relative, magnitude);
    const bool ok = err <= tol;
    session.tests.push_back({ok, check_line(ok, occ.text("REFERENCE"), what, refe, value, err, tol, occ.text("CRITERE"))});
    session.log().always(session.tests.back().text);
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.12e", value);
  if (!any) throw occ.error("VALE_CALC", "VALE_CALC and/or VALE_REFE", "neither", {"computed value: " + std::string(text)});
  if (!occ.has(calc_kw)) session.log().always("      computed value (paste as VALE_CALC): " + std::string(text));
}

}  // namespace lunaster::cmd
