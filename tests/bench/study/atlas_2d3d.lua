-- Stability atlas, 2D against 3D: the same scene, plane strain (12k x 12k over 11k x 11k QUAD4)
-- and 3D (a one-cell-thick slab: HEXA8 12k x 1 x 12k (V1, slave of CONTINUE) with HEXA8 11k x 1 x 11k (V2), same interface
-- pattern; with nu = 0 the plane-strain answer is the 3D answer). Equal answers, at what cost.
local study = require('study')
local config = require('config')

DEBUT()
for _, k in ipairs(config.ks_2d3d or { 1, 2, 4 }) do
  for _, m in ipairs(study.methods()) do
    study.run('atlas_2d3d.csv', { { 'family', '2D' }, { 'method', m.name }, { 'k', k } },
              'meshes/ssnp121_2d_k' .. k .. '.med', m, 2)
    study.run('atlas_2d3d.csv', { { 'family', '3D-slab' }, { 'method', m.name }, { 'k', k } },
              'meshes/slab_k' .. k .. '.med', m, 3)
  end
end
FIN()
