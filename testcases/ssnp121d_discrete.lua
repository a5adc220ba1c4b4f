-- SSNP121 D with the DISCRETE methods: the 3D contact patch test on the matching 4x4x4 HEXA20 mesh of
-- model D (QUAD8 faces on both sides), ALGO_CONT='CONTRAINTE' (active set, Lagrange multipliers) and
-- 'PENALISATION' (E_N = 1e12 Pa/m), slave SURMAI / master SURESC as in models B and C.
-- Discrete contact uses only the vertex nodes of the slave faces; as in code_aster (message
-- CONTACT_8), every mid-side node of a QUAD8 contact face is tied to the mean of its edge's vertices,
-- so each face moves as the QUAD4 the contact sees and the matching mesh passes the patch test.
-- Without those ties the mid-side nodes penetrate freely: lunaster's study measured 21 % error at
-- A21..A23 and 41 % over the interface on this mesh before they were added.
-- Reference: analytical SIZZ = -1e5 Pa (SIGM_NOEU) and DZ = -0.05 m on the interface, PRECISION 1e-6
-- (code_aster's tolerance on D is 0.1 %). CONTRAINTE is exact to round-off (1e-14); PENALISATION keeps a
-- penetration of F / E_N per slave node (6e-9 m here), a relative error of about 1e-7.
-- A third run (PENE) is the penalty with SOLVEUR ELIM_LAGR = 'OUI': the mid-side ties are then solved
-- for one unknown each, as code_aster does with every kinematic relation, so no multiplier is left and
-- CHOLMOD factorises an SPD system (the other runs factorise a system with the ties' multipliers);
-- same values to the penalty's 1e-7.
-- Runtime label: fast, contact, 3D.
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'ssnp121d.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO,
                       DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                    _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

local function solve(contact, solveur)
  local cha2 = AFFE_CHAR_MECA{ MODELE = MO, CONTACT = _F(contact) }
  local r = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT,
                           EXCIT = { _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, _F{ CHARGE = cha2 } },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L_INST },
                           SOLVEUR = solveur }
  return CALC_CHAMP{ reuse = r, RESULTAT = r, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
end
LAGR = solve{ METHODE = 'CONTRAINTE', GROUP_MA_ESCL = 'SURMAI', GROUP_MA_MAIT = 'SURESC', REAC_GEOM = 'AUTOMATIQUE' }
PENA = solve{ METHODE = 'PENALISATION', GROUP_MA_ESCL = 'SURMAI', GROUP_MA_MAIT = 'SURESC', E_N = 1.0e12,
              REAC_GEOM = 'AUTOMATIQUE' }
-- The same penalty with the mid-side ties solved for one unknown each (ELIM_LAGR = 'OUI', as
-- code_aster treats every kinematic relation): no multiplier is left, so the system is SPD.
PENE = solve({ METHODE = 'PENALISATION', GROUP_MA_ESCL = 'SURMAI', GROUP_MA_MAIT = 'SURESC', E_N = 1.0e12,
               REAC_GEOM = 'AUTOMATIQUE' }, _F{ METHODE = 'CHOLMOD', ELIM_LAGR = 'OUI' })

-- calc: lunaster's own value from a real run (VALE_CALC, non-regression, relative 1e-6).
local checks = {}
local function check(resu, field, cmp, group, calc, refe, kind)
  checks[#checks + 1] = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = field, NOM_CMP = cmp, GROUP_NO = group,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-6,
                            VALE_CALC = calc }
end
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'A21', -1.000000000000e+05, -1.0e5)
check(LAGR, 'DEPL', 'DZ', 'A21', -5.000000000000e-02, -0.05)
check(PENA, 'SIGM_NOEU', 'SIZZ', 'A21', -1.000000050565e+05, -1.0e5)
check(PENA, 'DEPL', 'DZ', 'A21', -4.999999932059e-02, -0.05)
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'A22', -1.000000000000e+05, -1.0e5)
check(LAGR, 'DEPL', 'DZ', 'A22', -5.000000000000e-02, -0.05)
check(PENA, 'SIGM_NOEU', 'SIZZ', 'A22', -1.000000051177e+05, -1.0e5)
check(PENA, 'DEPL', 'DZ', 'A22', -4.999999907443e-02, -0.05)
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'A23', -1.000000000000e+05, -1.0e5)
check(LAGR, 'DEPL', 'DZ', 'A23', -5.000000000000e-02, -0.05)
check(PENA, 'SIGM_NOEU', 'SIZZ', 'A23', -1.000000051175e+05, -1.0e5)
check(PENA, 'DEPL', 'DZ', 'A23', -4.999999876255e-02, -0.05)
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'A24', -1.000000000000e+05, -1.0e5)
check(LAGR, 'DEPL', 'DZ', 'A24', -5.000000000000e-02, -0.05)
check(PENA, 'SIGM_NOEU', 'SIZZ', 'A24', -1.000000050887e+05, -1.0e5)
check(PENA, 'DEPL', 'DZ', 'A24', -4.999999899189e-02, -0.05)
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'SURESC', -1.000000000000e+05, -1.0e5, 'MIN')
check(LAGR, 'DEPL', 'DZ', 'SURESC', -5.000000000000e-02, -0.05, 'MIN')
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'SURESC', -1.000000000000e+05, -1.0e5, 'MAX')
check(LAGR, 'DEPL', 'DZ', 'SURESC', -5.000000000000e-02, -0.05, 'MAX')
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'SURMAI', -1.000000000000e+05, -1.0e5, 'MIN')
check(LAGR, 'DEPL', 'DZ', 'SURMAI', -5.000000000000e-02, -0.05, 'MIN')
check(LAGR, 'SIGM_NOEU', 'SIZZ', 'SURMAI', -1.000000000000e+05, -1.0e5, 'MAX')
check(LAGR, 'DEPL', 'DZ', 'SURMAI', -5.000000000000e-02, -0.05, 'MAX')
check(PENA, 'SIGM_NOEU', 'SIZZ', 'SURESC', -1.000000051177e+05, -1.0e5, 'MIN')
check(PENA, 'DEPL', 'DZ', 'SURESC', -4.999999932059e-02, -0.05, 'MIN')
check(PENA, 'SIGM_NOEU', 'SIZZ', 'SURESC', -9.999998646494e+04, -1.0e5, 'MAX')
check(PENA, 'DEPL', 'DZ', 'SURESC', -4.999999678653e-02, -0.05, 'MAX')
check(PENA, 'SIGM_NOEU', 'SIZZ', 'SURMAI', -1.000000053398e+05, -1.0e5, 'MIN')
check(PENA, 'DEPL', 'DZ', 'SURMAI', -5.000000330656e-02, -0.05, 'MIN')
check(PENA, 'SIGM_NOEU', 'SIZZ', 'SURMAI', -9.999998625902e+04, -1.0e5, 'MAX')
check(PENA, 'DEPL', 'DZ', 'SURMAI', -5.000000032505e-02, -0.05, 'MAX')
check(PENE, 'SIGM_NOEU', 'SIZZ', 'A21', -1.000000050418e+05, -1.0e5)
check(PENE, 'DEPL', 'DZ', 'A21', -4.999999858042e-02, -0.05)
check(PENE, 'SIGM_NOEU', 'SIZZ', 'A23', -1.000000049567e+05, -1.0e5)
check(PENE, 'DEPL', 'DZ', 'A23', -4.999999944184e-02, -0.05)
check(PENE, 'SIGM_NOEU', 'SIZZ', 'SURESC', -1.000000051538e+05, -1.0e5, 'MIN')
check(PENE, 'SIGM_NOEU', 'SIZZ', 'SURESC', -9.999998658524e+04, -1.0e5, 'MAX')
check(PENE, 'DEPL', 'DZ', 'SURMAI', -5.000000335892e-02, -0.05, 'MIN')
check(PENE, 'DEPL', 'DZ', 'SURMAI', -5.000000014292e-02, -0.05, 'MAX')
TEST_RESU{ RESU = checks }
FIN()
