-- SOLVEUR METHODE='MUMPS' with each fill-reducing ordering of code_aster's RENUM (AUTO, METIS,
-- AMD, AMF, QAMD, PORD), through STAT_NON_LINE and MECA_NON_LINE: the ordering changes MUMPS's
-- elimination order (the log names it), not the answer. SSNP121 I's geometry glued
-- (meshes/glued3d_hexa20.med: two unit cubes stacked), ENCAST clamped, SURCHA moved by
-- DZ = -0.1, E = 2e6, NU = 0: DZ = -0.05 m on the interface and SIZZ = -1e5 Pa everywhere, to
-- 1e-8. Under `verify --np 2` the model is shared among the ranks and METIS orders the pattern
-- they send to rank 0 (tests/mpi/renum_metis.lua checks the log); the orders MUMPS reports are
-- checked by the unit test Solvers.MumpsTakesTheOrderingAskedForAndAgreesWithUmfpackIn3d.
-- Reference: analytical.
-- Runtime label: fast, 3D, solver.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/glued3d_hexa20.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                               _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
for _, command in ipairs({ 'STAT_NON_LINE', 'MECA_NON_LINE' }) do
  for _, renum in ipairs({ 'AUTO', 'METIS', 'AMD', 'AMF', 'QAMD', 'PORD' }) do
    local solve = command == 'STAT_NON_LINE' and STAT_NON_LINE or MECA_NON_LINE
    local R = solve{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                     SOLVEUR = _F{ METHODE = 'MUMPS', RENUM = renum }, INCREMENT = _F{ LIST_INST = L_INST } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_NOEU' } }
    local label = command .. ' RENUM=' .. renum
    local function t(cham, cmp, kind, refe, group)
      return _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind, GROUP_NO = group,
                 REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-8, LEGENDE = label }
    end
    TEST_RESU{ RESU = {
      t('SIGM_NOEU', 'SIZZ', 'MIN', -1.0e5), t('SIGM_NOEU', 'SIZZ', 'MAX', -1.0e5),
      t('DEPL', 'DZ', 'MIN', -0.05, 'SURESC'), t('DEPL', 'DZ', 'MAX', -0.05, 'SURESC'),
    } }
  end
end
FIN()
