-- FORMULE and DEFI_CONSTANTE as load multipliers (FONC_MULT). The block of first_deck.lua (1 m x 1 m,
-- plane strain, sliding on BOTTOM and LEFT) is pressed on TOP by two pressures: P1 times a FORMULE of
-- INST and P2 times a DEFI_CONSTANTE. The FORMULE uses reals given by name, a function of the deck,
-- another FORMULE, a DEFI_CONSTANTE, math's functions, '**', '%', '//', a comparison and 'a if c else b'.
-- Exact solution at every instant t: SIYY = -(P1 f(t) + P2 C) everywhere, and the floor pushes back with
-- that pressure times the width. The references are computed below from f written in Lua.
-- Mesh: first_deck.med (build/lunaster-meshgen --block quad4:4 -o first_deck.med).
DEBUT()
P1, P2 = 1.0e5, 2.5e4
a, b, d = 0.8, 0.3, 0.25
function half_root(t) return math.sqrt(t) / 2 end                 -- a function of the deck
MA  = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = 'first_deck.med' }
MO  = AFFE_MODELE{ MAILLAGE = MA,
                   AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e11, NU = 0.3 } }
CM  = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', MATER = MAT } }
BC  = AFFE_CHAR_MECA{ MODELE = MO,
                      DDL_IMPO = { _F{ GROUP_MA = 'BOTTOM', DY = 0.0 }, _F{ GROUP_MA = 'LEFT', DX = 0.0 } } }
CH1 = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'TOP', PRES = P1 } }
CH2 = AFFE_CHAR_MECA{ MODELE = MO, PRES_REP = _F{ GROUP_MA = 'TOP', PRES = P2 } }
K   = DEFI_CONSTANTE{ VALE = 0.125 }
C   = DEFI_CONSTANTE{ VALE = 2.0 }
SQ  = FORMULE{ VALE = 'X**2', NOM_PARA = 'X' }
F   = FORMULE{ NOM_PARA = 'INST', a = a, b = b, d = d, g = half_root, K = K, SQ = SQ,
               VALE = [[a*sin(pi*INST/2)**2 + b*INST + g(INST) + K(INST)
                        + (d if INST > 0.5 else 0.0) - math.fabs(-SQ(INST)) / 4
                        + (INST*4) % 3 / 10 - (INST*4) // 3 / 8 + 2**-2 * min(INST, 0.5)]] }
-- the same function in Lua: the references
local function f(t)
  return a * math.sin(math.pi * t / 2) ^ 2 + b * t + math.sqrt(t) / 2 + 0.125 + (t > 0.5 and d or 0.0)
         - math.abs(-(t ^ 2)) / 4 + ((t * 4) % 3) / 10 - ((t * 4) // 3) / 8 + 0.25 * math.min(t, 0.5)
end
L   = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 4 } }
R   = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM,
                     EXCIT = { _F{ CHARGE = BC }, _F{ CHARGE = CH1, FONC_MULT = F }, _F{ CHARGE = CH2, FONC_MULT = C } },
                     COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L } }
R   = CALC_CHAMP{ reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_NOEU', FORCE = 'REAC_NODA' }
local checks = {}
for i = 1, 4 do
  local t = 0.25 * i
  local p = P1 * f(t) + P2 * 2.0
  for _, kind in ipairs({ 'MIN', 'MAX' }) do
    checks[#checks + 1] = _F{ RESULTAT = R, INST = t, NOM_CHAM = 'SIGM_NOEU', NOM_CMP = 'SIYY', TYPE_TEST = kind,
                              REFERENCE = 'ANALYTIQUE', VALE_REFE = -p, PRECISION = 1.0e-10 }
  end
  checks[#checks + 1] = _F{ RESULTAT = R, INST = t, NOM_CHAM = 'REAC_NODA', NOM_CMP = 'DY', TYPE_TEST = 'SOMM',
                            GROUP_NO = 'BOTTOM', REFERENCE = 'ANALYTIQUE', VALE_REFE = p, PRECISION = 1.0e-10 }
end
TEST_RESU{ RESU = checks }
FIN()
