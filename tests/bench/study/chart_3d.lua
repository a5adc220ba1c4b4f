-- The SSNP121 3D chart: the I-type non-matching pair (HEXA8 5k x 5k x k under HEXA20 4k x 4k x k)
-- and the D-type matching pair (HEXA20 4k x 4k x 4k on both) for the k of config.lua, with
-- every contact method (slave SURESC for CONTINUE, SURMAI for the discrete ones). Rows in chart_3d.csv.
local study = require('study')
local config = require('config')

DEBUT()
for _, fam in ipairs({ { 'I', config.ks_3d_i or { 1, 2 } }, { 'D', config.ks_3d_d or { 1 } } }) do
  for _, k in ipairs(fam[2]) do
    for _, m in ipairs(study.methods()) do
      study.run('chart_3d.csv', { { 'family', '3D-' .. fam[1] }, { 'method', m.name }, { 'k', k } },
                'meshes/ssnp121_3d' .. fam[1]:lower() .. '_k' .. k .. '.med', m, 3)
    end
  end
end
FIN()
