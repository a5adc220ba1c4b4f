#pragma once
/// The two-tier checks shared by TEST_RESU and TEST_TABLE: VALE_CALC (non-regression, or a
/// comparison with code_aster for a .comm) and VALE_REFE, one OK/NOOK line each, counted in
/// the session's report (and by `lunaster verify`).
#include <string>

#include "catalog/args.hpp"
#include "commands/session.hpp"

namespace lunaster::cmd {

/// The error of one check, as code_aster: ABSOLU gives |calc - refe|; RELATIF divides by
/// |refe|, or by ORDRE_GRANDEUR (`magnitude`, 0 when not given) when |refe| is smaller.
/// A quantity that is zero in theory is computed as round-off, which changes with the
/// machine's arithmetic kernels: its VALE_CALC is compared on the scale of the quantity
/// (ORDRE_GRANDEUR), never relative to its own round-off.
double check_difference(double calc, double refe, bool relative, double magnitude);

/// Checks `value` against the reference keywords of `occ` (common::test_reference_keywords),
/// prints and records one line per check; `what` names the value in the line. DeckError at
/// VALE_CALC when neither VALE_CALC nor VALE_REFE is given. With VALE_ABS='OUI' the absolute
/// values are compared. `integer_value`: the value is an integer (a table's integer column),
/// tested by VALE_CALC_I / VALE_REFE_I where the occurrence declares them.
void report_checks(const catalog::Args& occ, Session& session, double value, const std::string& what,
                   bool integer_value = false);

}  // namespace lunaster::cmd
