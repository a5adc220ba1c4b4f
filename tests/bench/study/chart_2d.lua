-- The SSNP121 2D chart: every contact method on the mesh family 12k x 12k QUAD4 (upper
-- block, slave side of CONTINUE) over 11k x 11k QUAD4 (lower block), non-matching,
-- for the refinements k of config.lua. One row per run in chart_2d.csv (IMPR_MESURE).
-- Meshes: meshes/ssnp121_2d_k<k>.med, made by `lunaster-meshgen --upper quad4:12
-- --lower quad4:11 --refine k` (run_study.sh). Run: lunaster run chart_2d.lua --out DIR
local study = require('study')
local config = require('config')

DEBUT()
for _, k in ipairs(config.ks_2d) do
  for _, m in ipairs(study.methods()) do
    local cap = config.max_k_2d[m.name] or config.max_k_2d[m.kind]
    if not (cap and k > cap) then
      study.run('chart_2d.csv', { { 'family', '2D-Q4' }, { 'method', m.name }, { 'k', k } },
                'meshes/ssnp121_2d_k' .. k .. '.med', m, 2)
    end
  end
end
FIN()
