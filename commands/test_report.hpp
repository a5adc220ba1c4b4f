#pragma once
/// The two-tier checks shared by TEST_RESU and TEST_TABLE: VALE_CALC (non-regression, or a
/// comparison with code_aster for a .comm) and VALE_REFE, one OK/NOOK line each, counted in
/// the session's report (and by `lunaster verify`).
#include <string>

#include "catalog/args.hpp"
#include "commands/session.hpp"

namespace lunaster::cmd {

/// Checks `value` against the reference keywords of `occ` (common::test_reference_keywords),
/// prints and records one line per check; `what` names the value in the line. DeckError at
/// VALE_CALC when neither VALE_CALC nor VALE_REFE is given.
void report_checks(const catalog::Args& occ, Session& session, double value, const std::string& what);

}  // namespace lunaster::cmd
