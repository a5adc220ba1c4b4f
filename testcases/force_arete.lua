-- FORCE_ARETE, a force per unit length on edges of a 3D model: the block [0,2]x[0,1]x[0,1] of two
-- HEXA8 (meshes/force_arete_hexa8_v22.msh), clamped on BOTTOM (z = 0), loaded along its top front
-- edge EDGE (y = 0, z = 1, two SEG2, length 2) by F = (FX, FY, FZ) N/m. Equilibrium: the base
-- reaction (REAC_NODA, the body pushing on its support) sums to -F x 2 in each component, whatever
-- the deformation; the consistent forces of a uniform line load are exact and the sum of the
-- nodal reactions holds to the solver's round-off: tolerance 1e-10. The load follows FONC_MULT
-- (a ramp: half at INST 0.5).
-- No VALE_CALC: every check is analytical at the tolerance an exact method allows.
-- Reference: analytical (equilibrium). Units SI. Runtime label: fast.
DEBUT()
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
MA = LIRE_MAILLAGE{ FORMAT = 'GMSH', FICHIER = 'meshes/force_arete_hexa8_v22.msh' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = 'BLOCK', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
local F = { DX = 1.0e5, DY = -2.0e5, DZ = -3.0e5 }
CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_MA = 'BOTTOM', DX = 0.0, DY = 0.0, DZ = 0.0 },
                     FORCE_ARETE = _F{ GROUP_MA = 'EDGE', FX = F.DX, FY = F.DY, FZ = F.DZ } }
R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                   COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
R = CALC_CHAMP{ reuse = R, RESULTAT = R, FORCE = 'REAC_NODA' }
T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'BASE', RESULTAT = R, NOM_CHAM = 'REAC_NODA',
                                GROUP_NO = 'BOTTOM', RESULTANTE = { 'DX', 'DY', 'DZ' } } }
for _, cmp in ipairs({ 'DX', 'DY', 'DZ' }) do
  for order, scale in ipairs({ 0.5, 1.0 }) do
    local refe = -F[cmp] * 2.0 * scale
    TEST_TABLE{ TABLE = T, NOM_PARA = cmp, FILTRE = _F{ NOM_PARA = 'NUME_ORDRE', VALE_I = order },
                REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10 }
  end
end
FIN()
