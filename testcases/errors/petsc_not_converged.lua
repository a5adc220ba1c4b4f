-- Must-fail deck: SOLVEUR METHODE='PETSC' with too few iterations allowed (GMRES + JACOBI,
-- NMAX_ITER = 3) for RESI_RELA = 1e-10 on the 3D SSNP121 I mortar system. The solve that does
-- not reach RESI_RELA is a solve failure giving the residual reached, never a silent result.
-- EXPECT_STATUS: 3
-- EXPECT_ERROR: petsc_not_converged\.lua:20: STAT_NON_LINE: the iterative solver PETSc GMRES \+ JACOBI did not converge: relative residual [0-9.e+-]+ after 3 iterations, 1\.0e-10 asked \(DIVERGED_ITS\)
-- EXPECT_ERROR: raise NMAX_ITER or RESI_RELA, choose another PRE_COND, or use a direct solver: METHODE='MUMPS'
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121i.med' }
MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D' } }
MAT = DEFI_MATERIAU{ ELAS = _F{ E = 2.0e6, NU = 0.0 } }
CHMAT = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = _F{ GROUP_MA = { 'V1', 'V2' }, MATER = MAT } }
CHA1 = AFFE_CHAR_MECA{ MODELE = MO, DDL_IMPO = { _F{ GROUP_NO = 'ENCAST', DX = 0.0, DY = 0.0, DZ = 0.0 },
                                                 _F{ GROUP_NO = 'SURCHA', DX = 0.0, DY = 0.0, DZ = -0.1 } } }
CONT = DEFI_CONT{ MODELE = MO, ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'SURESC', GROUP_MA_MAIT = 'SURMAI',
                                          CONTACT_INIT = 'INTERPENETRE' } }
L_INST = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
RAMPE = DEFI_FONCTION{ NOM_PARA = 'INST', VALE = { 0.0, 0.0, 1.0, 1.0 } }


RESU = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CHMAT, CONTACT = CONT,
                      EXCIT = _F{ CHARGE = CHA1, FONC_MULT = RAMPE }, COMPORTEMENT = _F{ RELATION = 'ELAS' },
                      INCREMENT = _F{ LIST_INST = L_INST },
                      SOLVEUR = _F{ METHODE = 'PETSC', ALGORITHME = 'GMRES', PRE_COND = 'JACOBI', RESI_RELA = 1.0e-10,
                                    NMAX_ITER = 3 } }
FIN()
