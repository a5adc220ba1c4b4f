-- Stability atlas, CONTACT_INIT: SSNP121 G (upper block loaded by a pressure of 1e5 Pa on CD,
-- only DX = 0 at D, so the upper block floats until contact holds it) with CONTACT_INIT
-- 'NON', 'OUI' and 'INTERPENETRE'. The status column holds what the user is told when it fails.
local study = require('study')

DEBUT()
local ma = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'meshes/ssnp121_2d_k1.med' }
ma = MODI_MAILLAGE{ reuse = ma, MAILLAGE = ma, ORIE_PEAU_2D = _F{ GROUP_MA = 'CD' } }
local mo = AFFE_MODELE{ MAILLAGE = ma, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
local mat = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
local cm = AFFE_MATERIAU{ MAILLAGE = ma, AFFE = _F{ GROUP_MA = { 'PLAQUE1', 'PLAQUE2' }, MATER = mat } }
local bc = AFFE_CHAR_MECA{ MODELE = mo, DDL_IMPO = { _F{ GROUP_NO = 'D', DX = 0.0 }, _F{ GROUP_NO = 'GH', DX = 0.0, DY = 0.0 } },
                           PRES_REP = _F{ GROUP_MA = 'CD', PRES = 1.0e5 } }
for _, init in ipairs({ 'NON', 'OUI', 'INTERPENETRE' }) do
  local cont = AFFE_CHAR_MECA{ MODELE = mo, CONTACT = _F{ METHODE = 'CONTINUE', GROUP_MA_ESCL = 'AB', GROUP_MA_MAIT = 'EF',
                               INTEGRATION = 'SIMPSON', ORDRE_INT = 4, COEF_REGU_CONT = 1000.0, CONTACT_INIT = init } }
  local ok, r = pcall(STAT_NON_LINE, { MODELE = mo, CHAM_MATER = cm,
                        EXCIT = { _F{ CHARGE = bc, FONC_MULT = study.ramp() }, _F{ CHARGE = cont } },
                        COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = study.times() } })
  local status = ok and 'ok' or ('failed: ' .. tostring(r):gsub('\n.*', ''))
  local errs = { _F{ NOM = 'err_p', NOM_CHAM = 'DEPL', NOM_CMP = 'LAGS_C', GROUP_MA = 'AB', VALE_REFE = -1.0e5 },
                 _F{ NOM = 'err_u', NOM_CHAM = 'DEPL', NOM_CMP = 'DY', GROUP_MA = 'AB', VALE_REFE = -0.05 } }
  IMPR_MESURE{ FICHIER = 'atlas_init.csv', RESULTAT = ok and r or nil, PARA = { 'CONTACT_INIT', 'status' },
               VALE_K = { init, status }, ERREUR = errs }
end
FIN()
