-- A material with the hardening data of the von Mises laws (ECRO_LINE, and TRACTION as a function
-- of EPSI whose first point is the yield point SY / E), stretched below yield with RELATION = 'ELAS'.
-- Purpose: DEFI_MATERIAU reads and checks ECRO_LINE and TRACTION (D_SIGM_EPSI below E, a curve
--          that does not soften; errors/ holds the refusals); RELATION = 'ELAS' uses ELAS alone, as
--          code_aster's ELAS does, so the solution is Hooke's. The von Mises relations that use the
--          hardening (VMIS_ISOT_LINE, VMIS_ISOT_TRAC) are checked in vmis_isot_line_bar.lua.
-- Problem: the unit square (one QUAD4, plane stress), u_x = 0 on the left, u_y = 0 at the bottom,
--          u_y = 0.8 SY / E on the top: uniaxial stress SIYY = 0.8 SY, lateral strain -NU 0.8 SY / E.
-- Reference: analytical (Hooke's law in plane stress; one bilinear cell holds the uniform field).
--            Units: MPa, mm. Runtime label: fast.
DEBUT()
local E, NU, SY, ET = 2.0e5, 0.3, 1000.0, 2000.0
local D = 0.8 * SY / E
CURVE = DEFI_FONCTION{ NOM_PARA = 'EPSI', PROL_DROITE = 'CONSTANT',
                       VALE = { SY / E, SY,
                                0.015, 1100.0,
                                0.035, 1150.0 } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU }, ECRO_LINE = _F{ D_SIGM_EPSI = ET, SY = SY },
                     TRACTION = _F{ SIGM = CURVE } }
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/unit_quad4.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'LEFT', DX = 0.0 }, _F{ GROUP_NO = 'BOTTOM', DY = 0.0 },
                                               _F{ GROUP_NO = 'TOP', DY = D } } }
L = DEFI_LIST_REEL{ VALE = { 0.0, 1.0 } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                   COMPORTEMENT = _F{ RELATION = 'ELAS', TOUT = 'OUI' }, INCREMENT = _F{ LIST_INST = L } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_NOEU' }
local checks = {}
local function check(cham, cmp, kind, group, refe)
  checks[#checks + 1] = _F{ RESULTAT = R, INST = 1.0, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind,
                            GROUP_NO = group, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10 }
end
check('SIGM_NOEU', 'SIYY', 'MIN', nil, E * D)
check('SIGM_NOEU', 'SIYY', 'MAX', nil, E * D)
check('DEPL', 'DX', 'MIN', 'RIGHT', -NU * D)
check('DEPL', 'DX', 'MAX', 'RIGHT', -NU * D)
TEST_RESU{ RESU = checks }
FIN()
