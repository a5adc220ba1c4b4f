-- Stability atlas, the seed's incompatible pairings: a QUAD8 slave on a TRIA6 master (model F
-- reversed: slave SURMAI of a HEXA20 block, master SURESC of a PENTA15 block) and a QUAD4 slave
-- on a TRIA6 master (HEXA8 on PENTA15). What each method gives; warnings are in the log.
local study = require('study')

DEBUT()
for _, pair in ipairs({ { 'QUAD8-on-TRIA6', 'meshes/incompat_q8_t6.med' }, { 'QUAD4-on-TRIA6', 'meshes/incompat_q4_t6.med' } }) do
  for _, m in ipairs(study.methods()) do
    if m.name ~= 'PENALISATION-1e7' and m.name ~= 'PENALISATION-1e11' then
      m.slave, m.master = 'SURMAI', 'SURESC'
      study.run('atlas_incompat.csv', { { 'pairing', pair[1] }, { 'method', m.name } }, pair[2], m, 3)
    end
  end
end
FIN()
