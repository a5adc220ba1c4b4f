-- Stability atlas, penalty sweep: discrete PENALISATION (node-to-segment, slave EF) with
-- E_N = 1e3 .. 1e16 Pa/m on the SSNP121 2D meshes k = 1 and 4. Columns: err_p (pressure),
-- penetration (largest |JEU| on the slave nodes, m), Newton iterations, status; the linear
-- solver's loss of accuracy shows as an error floor rising again or as a failed run.
local study = require('study')
local config = require('config')

DEBUT()
for _, k in ipairs(config.atlas_ks or { 1, 4 }) do
  for e = 3, 16 do
    local m = { name = 'PENALISATION', kind = 'PENALISATION', e_n = 10.0 ^ e }
    local r = study.run('atlas_penalty.csv', { { 'k', k }, { 'E_N', m.e_n } },
                        'meshes/ssnp121_2d_k' .. k .. '.med', m, 2)
    if r then
      IMPR_MESURE{ FICHIER = 'atlas_penalty_gap.csv', RESULTAT = r, PARA = { 'k', 'E_N' },
                   VALE_K = { tostring(k), string.format('%.0e', m.e_n) },
                   ERREUR = _F{ NOM = 'penetration', NOM_CHAM = 'CONT_NOEU', NOM_CMP = 'JEU', GROUP_MA = 'EF', VALE_REFE = 0.0 } }
    end
  end
end
FIN()
