#pragma once
/// Keywords shared by several commands: entity selections (TOUT, GROUP_MA,
/// GROUP_NO, MAILLE, NOEUD), contact integration schemes and the TEST_RESU
/// reference block.
#include "catalog/spec.hpp"

namespace lunaster::catalog::common {

/// TOUT = 'OUI': the whole mesh.
Keyword tout(std::string doc = "Apply to the whole mesh");
/// GROUP_MA: one or several cell groups.
Keyword group_ma(std::string doc = "Cell groups of the mesh");
/// GROUP_NO: one or several node groups.
Keyword group_no(std::string doc = "Node groups of the mesh");
/// MAILLE: one or several cell names.
Keyword maille(std::string doc = "Cell names of the mesh");
/// NOEUD: one or several node names.
Keyword noeud(std::string doc = "Node names of the mesh");
/// INFO = 1|2: code_aster's amount of printed information, accepted without effect.
Keyword info();

/// INTEGRATION keyword of a contact zone with the given allowed schemes (default 'AUTO').
Keyword contact_integration(std::vector<Scalar> schemes);
/// Blocks declaring ORDRE_INT for INTEGRATION = GAUSS (1..6, default 3),
/// SIMPSON (1..4, default 1) and NCOTES (3..8, default 3).
std::vector<Block> ordre_int_blocks();
/// Shared seed/current contact algorithm keywords (REAC_GEOM, ITER_GEOM_MAXI, ...).
std::vector<Keyword> contact_loop_keywords();
/// ALGO_RESO_CONT: 'POINT_FIXE' or 'NEWTON' for the continuous formulation; the discrete
/// one has no status update inside Newton, so it refuses 'NEWTON'.
Keyword algo_reso_cont(bool discrete);
/// ITER_CONT_MULT of the discrete formulation: status iterations allowed per contact point.
Keyword iter_cont_mult();

/// The two-tier check keywords of TEST_RESU (VALE_CALC, REFERENCE, VALE_REFE, VALE_ABS ...);
/// `integers` adds VALE_CALC_I and VALE_REFE_I (an integer value tested: TEST_TABLE).
std::vector<Keyword> test_reference_keywords(bool integers = false);
/// Rules tying the reference keywords together (with `integers`, of both kinds).
std::vector<Rule> test_reference_rules(bool integers = false);

}  // namespace lunaster::catalog::common
