-- Axisymmetric (AXIS) contact patch test with the discrete (node-to-segment) formulation
-- (DEFI_CONTACT FORMULATION='DISCRETE'): the two coaxial cylinders of axis_contact_patch_mortar.lua
-- (x = r, y = axis), slave AB (upper), master EF (lower), DY = -0.1 on CD, 0 on GH, DX = 0 there and
-- on the axis, NU = 0: exact state SIYY = E eps = -1e5 Pa, DY = -0.05 on the interface.
-- Each slave node carries the tributary measure of its linear shape function in the AXIS measure
-- r dl (per radian), so a nodal contact force is per radian like FORCE_NODALE and the reactions, and
-- E_N is a spring per radian.
-- Variants: CONTRAINTE (active set with Lagrange multipliers), PENALISATION (E_N = 1e12 N/m per
-- radian on each slave node: stiff springs; their penetrations are 1e-7 of the displacement).
-- Known behaviour (the tolerances are the measured largest errors, rounded up): matching meshes pass
-- (CONTRAINTE to round-off, 1e-8; PENALISATION to its penalty error, 2.3e-7). Node-to-segment does
-- not pass the patch test on non-matching meshes (ssnp121b: 6 % in code_aster; 3.4 % on these QUAD4
-- meshes in D_PLAN): 3.4 % on the annulus away from the axis and 12.6 % (SIYY next to the axis) on the
-- cylinder touching it, where the slave node on the axis has a tributary measure O(h^2). Quadratic
-- faces are linearised by this formulation (40 % off already in D_PLAN for the QUAD8 5/4 pair): not
-- tested here.
-- Reference: analytical (uniform state). Units SI. Runtime label: fast, contact.
DEBUT()
local E, E_N = 2.0e6, 1.0e12
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = 0.0 } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }

-- VALE_CALC: lunaster's own values from a real run (non-regression, relative 1e-6), keyed by
-- 'mesh variant field component TYPE_TEST(group)'.
local calc = {
  ['matching CONTRAINTE DEPL DY MIN(AB)'] = -5.000000000000e-02,
  ['matching CONTRAINTE DEPL DY MIN(EF)'] = -5.000000000000e-02,
  ['matching CONTRAINTE SIGM_NOEU SIYY MIN'] = -1.000000000000e+05,
  ['matching CONTRAINTE DEPL DY MAX(AB)'] = -5.000000000000e-02,
  ['matching CONTRAINTE DEPL DY MAX(EF)'] = -5.000000000000e-02,
  ['matching CONTRAINTE SIGM_NOEU SIYY MAX'] = -1.000000000000e+05,
  ['matching PENALISATION DEPL DY MIN(AB)'] = -5.000000542814e-02,
  ['matching PENALISATION DEPL DY MIN(EF)'] = -4.999999986417e-02,
  ['matching PENALISATION SIGM_NOEU SIYY MIN'] = -1.000000109007e+05,
  ['matching PENALISATION DEPL DY MAX(AB)'] = -5.000000012459e-02,
  ['matching PENALISATION DEPL DY MAX(EF)'] = -4.999999449064e-02,
  ['matching PENALISATION SIGM_NOEU SIYY MAX'] = -9.999997721025e+04,
  ['nonmatching CONTRAINTE DEPL DY MIN(AB)'] = -5.094132169078e-02,
  ['nonmatching CONTRAINTE DEPL DY MIN(EF)'] = -5.094132169078e-02,
  ['nonmatching CONTRAINTE SIGM_NOEU SIYY MIN'] = -1.121944424540e+05,
  ['nonmatching CONTRAINTE DEPL DY MAX(AB)'] = -4.992017821831e-02,
  ['nonmatching CONTRAINTE DEPL DY MAX(EF)'] = -4.991871480788e-02,
  ['nonmatching CONTRAINTE SIGM_NOEU SIYY MAX'] = -8.738926139792e+04,
  ['nonmatching PENALISATION DEPL DY MIN(AB)'] = -5.094132166623e-02,
  ['nonmatching PENALISATION DEPL DY MIN(EF)'] = -5.094132156555e-02,
  ['nonmatching PENALISATION SIGM_NOEU SIYY MIN'] = -1.121944503292e+05,
  ['nonmatching PENALISATION DEPL DY MAX(AB)'] = -4.992018107394e-02,
  ['nonmatching PENALISATION DEPL DY MAX(EF)'] = -4.991871182627e-02,
  ['nonmatching PENALISATION SIGM_NOEU SIYY MAX'] = -8.738927041408e+04,
  ['nonmatching_away CONTRAINTE DEPL DY MIN(AB)'] = -5.035072091756e-02,
  ['nonmatching_away CONTRAINTE DEPL DY MIN(EF)'] = -5.035121974201e-02,
  ['nonmatching_away CONTRAINTE SIGM_NOEU SIYY MIN'] = -1.033586587682e+05,
  ['nonmatching_away CONTRAINTE DEPL DY MAX(AB)'] = -4.992624919540e-02,
  ['nonmatching_away CONTRAINTE DEPL DY MAX(EF)'] = -4.992435249976e-02,
  ['nonmatching_away CONTRAINTE SIGM_NOEU SIYY MAX'] = -9.657171457161e+04,
  ['nonmatching_away PENALISATION DEPL DY MIN(AB)'] = -5.035072250875e-02,
  ['nonmatching_away PENALISATION DEPL DY MIN(EF)'] = -5.035121719137e-02,
  ['nonmatching_away PENALISATION SIGM_NOEU SIYY MIN'] = -1.033586745219e+05,
  ['nonmatching_away PENALISATION DEPL DY MAX(AB)'] = -4.992625596154e-02,
  ['nonmatching_away PENALISATION DEPL DY MAX(EF)'] = -4.992434579845e-02,
  ['nonmatching_away PENALISATION SIGM_NOEU SIYY MAX'] = -9.657173762691e+04,
}

-- Reference tolerance of each (mesh, variant): the measured largest relative error, rounded up.
local precision = {
  ['matching CONTRAINTE'] = 1.0e-8, ['matching PENALISATION'] = 3.0e-7,
  ['nonmatching CONTRAINTE'] = 1.3e-1, ['nonmatching PENALISATION'] = 1.3e-1,
  ['nonmatching_away CONTRAINTE'] = 3.5e-2, ['nonmatching_away PENALISATION'] = 3.5e-2,
}

local checks = {}
local function check(resu, label, prec, field, cmp, kind, group, refe, scale)
  local key = label .. ' ' .. field .. ' ' .. cmp .. ' ' .. kind .. (group and '(' .. group .. ')' or '')
  local f = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = field, NOM_CMP = cmp, TYPE_TEST = kind,
                LEGENDE = label, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = prec }
  if group then f.GROUP_MA = group end
  if refe == 0.0 then
    f.CRITERE = 'ABSOLU'; f.PRECISION = prec * scale  -- round-off around zero: no VALE_CALC
  else
    f.VALE_CALC = assert(calc[key], key)
  end
  checks[#checks + 1] = f
end

for _, mesh in ipairs({ 'matching', 'nonmatching', 'nonmatching_away' }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/axis_contact_' .. mesh .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
  local CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = MAT } }
  local ddl = { _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 }, _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } }
  if mesh ~= 'nonmatching_away' then ddl[#ddl + 1] = _F{ GROUP_NO = { 'DA', 'HE' }, DX = 0.0 } end
  local CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = ddl }
  for _, variant in ipairs({ 'CONTRAINTE', 'PENALISATION' }) do
    local zone = _F{ GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF', ALGO_CONT = variant }
    if variant == 'PENALISATION' then zone.E_N = E_N end
    local CONT = DEFI_CONTACT{ MODELE = MO, FORMULATION = 'DISCRETE', ZONE = zone }
    local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT, INCREMENT = _F{ LIST_INST = L_INST },
                             EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, COMPORTEMENT = _F{ RELATION = 'ELAS' } }
    R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' } }
    local label = mesh .. ' ' .. variant
    local p = 0.05 * E
    local prec = assert(precision[label], label)
    for _, kind in ipairs({ 'MIN', 'MAX' }) do
      check(R, label, prec, 'DEPL', 'DY', kind, 'AB', -0.1 + p / E)
      check(R, label, prec, 'DEPL', 'DY', kind, 'EF', -p / E)
      check(R, label, prec, 'SIGM_NOEU', 'SIYY', kind, nil, -p)
      check(R, label, prec, 'SIGM_NOEU', 'SIZZ', kind, nil, 0.0, p)
    end
  end
end
TEST_RESU{ RESU = checks }
FIN()
