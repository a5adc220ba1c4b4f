-- The runs of the frictional patch tests (testcases/friction_patch_2d.lua and friction_patch_3d.lua),
-- loaded with `require('lib.friction_patch')` (a module beside the decks, not a deck).
local M = {}

--- `run(formulation, zone_keywords, case)` and `check(...)` for one scene. `scene` holds the model
--- and materials (MO, CHMAT), the loads (FIX, PRESS, TOP: the top held for DISCRETE, PUSH, SLIDE,
--- HOLD), the functions R1 (the normal load), R2 (the push), R3 (the sides' shear), the instants
--- L_INST and the last step's number LAST, the zone's SLAVE and MASTER groups and MU, the loaded
--- group TOP_GROUP and the reaction components REACTIONS read there. `case`: 'stick' (HOLD) or
--- 'slip' (PUSH and SLIDE). run returns the result and the table of the reactions at the last step.
function M.runner(scene)
  local function run(formulation, zone_keywords, case)
    local zone = { GROUP_MA_ESCL = scene.SLAVE, GROUP_MA_MAIT = scene.MASTER, COULOMB = scene.MU }
    for k, v in pairs(zone_keywords) do zone[k] = v end
    local cont = DEFI_CONTACT{ MODELE = scene.MO, FORMULATION = formulation, FROTTEMENT = 'COULOMB', ZONE = _F(zone) }
    local excit = { _F{ CHARGE = scene.FIX },
                    _F{ CHARGE = formulation == 'DISCRETE' and scene.TOP or scene.PRESS, FONC_MULT = scene.R1 } }
    if case == 'slip' then
      excit[3] = _F{ CHARGE = scene.PUSH, FONC_MULT = scene.R2 }
      excit[4] = _F{ CHARGE = scene.SLIDE, FONC_MULT = scene.R3 }
    else
      excit[3] = _F{ CHARGE = scene.HOLD, FONC_MULT = scene.R2 }
    end
    local resu = STAT_NON_LINE{ MODELE = scene.MO, CHAM_MATER = scene.CHMAT, CONTACT = cont, EXCIT = excit,
                                INCREMENT = _F{ LIST_INST = scene.L_INST },
                                CONVERGENCE = _F{ RESI_GLOB_RELA = 1e-9, ITER_GLOB_MAXI = 30 } }
    resu = CALC_CHAMP{ reuse = resu, RESULTAT = resu, CONTRAINTE = 'SIGM_NOEU', FORCE = 'REAC_NODA' }
    local tab = POST_RELEVE_T{ ACTION = _F{ INTITULE = scene.TOP_GROUP, RESULTAT = resu, NOM_CHAM = 'REAC_NODA',
                                            GROUP_NO = scene.TOP_GROUP, RESULTANTE = scene.REACTIONS,
                                            OPERATION = 'EXTRACTION', NUME_ORDRE = scene.LAST } }
    return resu, tab
  end
  --- One TEST_RESU occurrence at the last step: VALE_REFE `refe` at PRECISION `tol` (CRITERE `crit`).
  local function check(resu, field, node, cmp, refe, calc, tol, crit)
    return _F{ RESULTAT = resu, NUME_ORDRE = scene.LAST, NOM_CHAM = field, GROUP_NO = node, NOM_CMP = cmp,
               VALE_CALC = calc, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = tol, CRITERE = crit }
  end
  return run, check
end

return M
