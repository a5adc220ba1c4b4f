-- Stability atlas, element size ratio: slave AB (upper block, N_s cells along the interface)
-- against master EF (lower block, 24 cells), h_slave / h_master = 24 / N_s from 1/4 to 4,
-- non-integer ratios included. Every method uses slave AB here, so the ratio means the same
-- thing for all. err_p is the largest pressure deviation on the slave side: the oscillation.
local study = require('study')
local config = require('config')

DEBUT()
for _, ns in ipairs(config.ratio_ns) do
  for _, m in ipairs(study.methods()) do
    if m.kind ~= 'CONTINUE' then m.slave, m.master = 'AB', 'EF' end
    study.run('atlas_ratio.csv', { { 'method', m.name }, { 'n_slave', ns }, { 'ratio', 24 / ns } },
              'meshes/ratio_' .. ns .. '.med', m, 2, { points = false })
  end
end
FIN()
