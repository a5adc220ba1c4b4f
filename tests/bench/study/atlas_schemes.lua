-- Stability atlas, integration schemes x face types: SSNP121 E (TRIA6 slave on TRIA6 master,
-- PENTA15 / PENTA15), F (TRIA6 on QUAD8, PENTA15 / HEXA20), J (TRIA3 on TRIA6, PENTA6 /
-- PENTA15) and K (TRIA3 on QUAD8, PENTA6 / HEXA20), 4x4x4 cells per block, slave SURESC, with
-- CONTINUE contact and every INTEGRATION at its default ORDRE_INT and higher ones (GAUSS 4 is
-- SSNP121 E's own, the first with as many points as a TRIA6 has LAGS_C unknowns). Every
-- interface is matching (slave vertices on master nodes): a rule that suits the faces gives
-- LAGS_C = -1e5 to round-off, and err_p shows where one does not (degree too low, fewer points
-- than LAGS_C unknowns, vertex points only against a quadratic master). Rows in atlas_schemes.csv.
local study = require('study')

DEBUT()
local geometries = {
  { 'E', 'TRIA6 on TRIA6', 'meshes/ssnp121e.med' }, { 'F', 'TRIA6 on QUAD8', 'meshes/ssnp121f.med' },
  { 'J', 'TRIA3 on TRIA6', 'meshes/ssnp121j.med' }, { 'K', 'TRIA3 on QUAD8', 'meshes/ssnp121k.med' },
}
local schemes = {
  { 'AUTO' }, { 'NOEUD' }, { 'GAUSS', 3 }, { 'GAUSS', 4 }, { 'GAUSS', 6 }, { 'SIMPSON', 1 }, { 'SIMPSON', 2 },
  { 'SIMPSON', 4 }, { 'NCOTES', 3 }, { 'NCOTES', 8 },
}
for _, g in ipairs(geometries) do
  for _, s in ipairs(schemes) do
    local name = s[2] and (s[1] .. '-' .. s[2]) or s[1]
    local m = { name = 'CONTINUE-' .. name, kind = 'CONTINUE', integration = s[1], ordre = s[2], coef = 1000.0,
                init = 'INTERPENETRE' }
    study.run('atlas_schemes.csv', { { 'geometry', g[1] }, { 'faces', g[2] }, { 'scheme', name } }, g[3], m, 3)
  end
end
FIN()
