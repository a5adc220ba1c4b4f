-- Stability atlas, COEF_CONT sweep: CONTINUE (Simpson, ORDRE_INT 4) with COEF_CONT = 1e-5 .. 1e16
-- on the SSNP121 2D meshes k = 1 and 4: iterations (Newton, contact passes) and accuracy.
local study = require('study')
local config = require('config')

DEBUT()
for _, k in ipairs(config.atlas_ks or { 1, 4 }) do
  for e = -5, 16 do
    local m = { name = 'CONTINUE-SIMPSON', kind = 'CONTINUE', integration = 'SIMPSON', ordre = 4, coef = 10.0 ^ e }
    study.run('atlas_coef.csv', { { 'k', k }, { 'COEF_CONT', m.coef } }, 'meshes/ssnp121_2d_k' .. k .. '.med', m, 2)
  end
end
FIN()
