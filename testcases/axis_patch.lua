-- Axisymmetric (AXIS) patch tests: distorted blocks of each element type (QUAD4, QUAD8, TRIA3, TRIA6)
-- touching the axis (meshes/patch_*.med, 0 <= r <= 1) and away from it (meshes/axis_patch_*.med,
-- 1 <= r <= 2), x being the radius r and y the axis z. Two uniform states, each loaded by imposed
-- displacements and by pressures (PRES_REP, integrated with the AXIS measure r dl):
--   AXIAL:  sigma_zz = S, other stresses 0; u_z = S z / E, u_r = -NU S r / E.
--   RADIAL: u_r = C r, u_z = 0 (ends held: DY = 0 on BOTTOM and TOP); eps_rr = eps_tt = C,
--           sigma_rr = sigma_tt = 2 (lambda + mu) C, sigma_zz = 2 lambda C.
-- Nodes on the axis (touching patches) get DX = 0, which both exact states satisfy. Every element must
-- reproduce the states to round-off (1e-10), nodal stresses included: SIXX radial, SIYY axial, SIZZ hoop,
-- and the von Mises stress with the hoop component (AXIAL: |S|; RADIAL: |sigma_rr - sigma_zz| = 2 mu C).
-- Reference: analytical (Hooke's law). Units SI. Runtime label: fast.
DEBUT()
local E, NU, S, C = 2.0e6, 0.3, -1.0e4, 1.0e-3
local LAMBDA, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
local SRR, SZZ = 2 * (LAMBDA + MU) * C, 2 * LAMBDA * C
MAT = DEFI_MATERIAU{ ELAS = _F{ E = E, NU = NU } }
L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }

for _, cell in ipairs({ 'quad4', 'quad8', 'tria3', 'tria6' }) do
  for _, where in ipairs({ 'touching', 'away' }) do
    local file = where == 'touching' and 'meshes/patch_' .. cell .. '.med' or 'meshes/axis_patch_' .. cell .. '.med'
    local RIN, ROUT = where == 'touching' and 0.0 or 1.0, where == 'touching' and 1.0 or 2.0
    local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = file }
    MA = MODI_MAILLAGE{ reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = _F{ GROUP_MA = { 'TOP', 'LEFT', 'RIGHT' } } }
    local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
    local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS' } }
    for _, state in ipairs({ 'AXIAL', 'RADIAL' }) do
      for _, loading in ipairs({ 'DEPL', 'PRES' }) do
        local ddl = { _F{ GROUP_NO = 'BOTTOM', DY = 0.0 } }
        if where == 'touching' then ddl[#ddl + 1] = _F{ GROUP_NO = 'LEFT', DX = 0.0 } end
        local pres = {}
        if state == 'AXIAL' then
          if loading == 'DEPL' then ddl[#ddl + 1] = _F{ GROUP_NO = 'TOP', DY = S / E }
          else pres[#pres + 1] = _F{ GROUP_MA = 'TOP', PRES = -S } end
        else
          ddl[#ddl + 1] = _F{ GROUP_NO = 'TOP', DY = 0.0 }
          if loading == 'DEPL' then
            ddl[#ddl + 1] = _F{ GROUP_NO = 'RIGHT', DX = C * ROUT }
            if where == 'away' then ddl[#ddl + 1] = _F{ GROUP_NO = 'LEFT', DX = C * RIN } end
          else
            pres[#pres + 1] = _F{ GROUP_MA = 'RIGHT', PRES = -SRR }
            if where == 'away' then pres[#pres + 1] = _F{ GROUP_MA = 'LEFT', PRES = -SRR } end
          end
        end
        local CH = #pres > 0 and AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = ddl, PRES_REP = pres }
                             or AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = ddl }
        local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, EXCIT = _F{ CHARGE = CH },
                                 COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
        R = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = { 'SIGM_ELNO', 'SIGM_NOEU' }, CRITERES = { 'SIEQ_NOEU' } }
        local label = cell .. ' ' .. where .. ' ' .. state .. ' ' .. loading
        local checks = {}
        local function t(cham, cmp, refe, group, scale)
          for _, kind in ipairs({ 'MIN', 'MAX' }) do
            local f = _F{ RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = cham, NOM_CMP = cmp, TYPE_TEST = kind,
                          GROUP_NO = group, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = 1.0e-10,
                          LEGENDE = label }
            if refe == 0.0 then f.CRITERE = 'ABSOLU'; f.PRECISION = 1.0e-10 * scale end
            checks[#checks + 1] = f
          end
        end
        if state == 'AXIAL' then
          t('SIGM_NOEU', 'SIYY', S)
          t('SIGM_NOEU', 'SIXX', 0.0, nil, math.abs(S))
          t('SIGM_NOEU', 'SIZZ', 0.0, nil, math.abs(S))
          t('SIGM_NOEU', 'SIXY', 0.0, nil, math.abs(S))
          t('SIEQ_NOEU', 'VMIS', math.abs(S))
          t('DEPL', 'DY', S / E, 'TOP')
          t('DEPL', 'DX', -NU * S * ROUT / E, 'RIGHT')
          if where == 'away' then t('DEPL', 'DX', -NU * S * RIN / E, 'LEFT') end
        else
          t('SIGM_NOEU', 'SIXX', SRR)
          t('SIGM_NOEU', 'SIZZ', SRR)
          t('SIGM_NOEU', 'SIYY', SZZ)
          t('SIGM_NOEU', 'SIXY', 0.0, nil, SRR)
          t('SIEQ_NOEU', 'VMIS', 2 * MU * C)
          t('DEPL', 'DX', C * ROUT, 'RIGHT')
          if where == 'away' then t('DEPL', 'DX', C * RIN, 'LEFT') end
          t('DEPL', 'DY', 0.0, nil, C)
        end
        TEST_RESU{ RESU = checks }
      end
    end
  end
end
FIN()
