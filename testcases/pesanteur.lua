-- PESANTEUR: a column under its own weight, NU = 0, support on its base (DY/DZ = 0 there, one
-- node or two holding the rigid motions), gravity along -y (2D, AXIS) or -z (3D):
--   sigma = -RHO G (L - y), u(y) = -RHO G / E (L y - y^2 / 2), u(top) = -RHO G L^2 / (2 E),
--   base reaction (REAC_NODA, the body pushing on its support) = +RHO G V (V per radian in AXIS).
-- With NU = 0 and a grid of rectangles the transverse equations decouple (no shear, no lateral
-- stress) and each column of nodes is a 1D bar with consistent loads, whose nodal values are exact:
-- u(top) and the reaction are exact up to round-off, tolerance 1e-10 (Newton's RESI_GLOB_RELA 1e-6
-- on a linear problem converges in one step to the direct solver's accuracy).
--   D_PLAN: unit square of 4 x 4 QUAD4 (first_deck.med), V = 1 m2 per unit thickness.
--   AXIS: ring 1 <= r <= 2, one QUAD4 cell high h = 0.0078125 (axis_cylinder_quad4.med),
--     V = h (2^2 - 1^2) / 2 per radian.
--   3D: unit cube of 12^3 HEXA8 (block_hexa8_12.med), V = 1 m3.
-- The load follows FONC_MULT (a ramp: half the weight at INST 0.5). DIRECTION is normalised.
-- No VALE_CALC: every check is analytical at the tolerance an exact method allows.
-- Reference: analytical. Units SI. Runtime label: fast.
DEBUT()
local E, RHO, G = 2.0e11, 7800.0, 9.81
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = 0.0, RHO = RHO } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 2 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }
local H_AXIS = 0.0078125
local cases = {
  { name = 'D_PLAN', file = 'first_deck.med', model = 'D_PLAN', top = 'C11', up = 'DY', len = 1.0, vol = 1.0,
    dir = { 0.0, -2.0, 0.0 } },
  { name = 'AXIS', file = 'meshes/axis_cylinder_quad4.med', model = 'AXIS', top = 'C11', up = 'DY', len = H_AXIS,
    vol = H_AXIS * 3.0 / 2.0, dir = { 0.0, -1.0, 0.0 } },
  { name = '3D', file = 'meshes/block_hexa8_12.med', model = '3D', top = 'C111', up = 'DZ', len = 1.0, vol = 1.0,
    dir = { 0.0, 0.0, -0.5 } },
}
for _, c in ipairs(cases) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = c.file }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = c.model } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
  local ddl
  if c.model == '3D' then
    ddl = { _F{ GROUP_MA = 'BOTTOM', DZ = 0.0 }, _F{ GROUP_NO = 'C000', DX = 0.0, DY = 0.0 },
            _F{ GROUP_NO = 'C100', DY = 0.0 } }
  elseif c.model == 'AXIS' then
    ddl = _F{ GROUP_MA = 'BOTTOM', DY = 0.0 }  -- the hoop stiffness holds r
  else
    ddl = { _F{ GROUP_MA = 'BOTTOM', DY = 0.0 }, _F{ GROUP_NO = 'C00', DX = 0.0 } }
  end
  local CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = ddl, PESANTEUR = _F{ GRAVITE = G, DIRECTION = c.dir } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH, FONC_MULT = RAMPE },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
  R = CALC_CHAMP{ reuse = R, RESULTAT = R, FORCE = 'REAC_NODA' }
  local u_top = -RHO * G * c.len * c.len / (2.0 * E)
  TEST_RESU{ RESU = {
    _F{ RESULTAT = R, NUME_ORDRE = 2, NOM_CHAM = 'DEPL', NOM_CMP = c.up, GROUP_NO = c.top, LEGENDE = c.name,
        REFERENCE = 'ANALYTIQUE', VALE_REFE = u_top, PRECISION = 1.0e-10 },
    _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = c.up, GROUP_NO = c.top, LEGENDE = c.name,
        REFERENCE = 'ANALYTIQUE', VALE_REFE = u_top / 2, PRECISION = 1.0e-10 },
  } }
  local T = POST_RELEVE_T{ ACTION = _F{ OPERATION = 'EXTRACTION', INTITULE = 'BASE', RESULTAT = R,
                                        NOM_CHAM = 'REAC_NODA', GROUP_NO = 'BOTTOM', RESULTANTE = c.up,
                                        NUME_ORDRE = 2 } }
  TEST_TABLE{ TABLE = T, NOM_PARA = c.up, LEGENDE = c.name, REFERENCE = 'ANALYTIQUE', VALE_REFE = RHO * G * c.vol,
              PRECISION = 1.0e-10 }
end
FIN()
