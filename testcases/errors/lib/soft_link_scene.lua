-- The scene of the must-fail decks on a soft part holding a stiff one (singular_soft_link_nprec.lua,
-- mumps_resi_rela_default.lua): the SSNP121 glued blocks (glued2d_quad4.med, D_PLAN, NU = 0.3),
-- the upper block PLAQUE1 of Young's modulus `e_soft`, the lower block PLAQUE2 (E = 2e6) hanging
-- from it and held by nothing else, CD moved by DY = -0.1. Defines MO, CM, CH and L.
return function(e_soft)
  DEBUT()
  MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../meshes/glued2d_quad4.med' }
  MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  STIFF = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.3 } }
  SOFT = DEFI_MATERIAU{ ELAS = _F{ E = e_soft, NU = 0.3 } }
  CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'PLAQUE1', MATER = SOFT },
                                              _F{ GROUP_MA = 'PLAQUE2', MATER = STIFF } } }
  CH = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = _F{ GROUP_NO = 'CD', DX = 0.0, DY = -0.1 } }
  L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
end
