-- Must-fail deck: every violation of one command is reported at once (first line
-- plus one hint line per further violation).
-- EXPECT_ERROR: several_errors\.lua:9: STAT_NON_LINE: MODELE: expected modele concept \(mandatory keyword\), got nothing
-- EXPECT_ERROR: also CHAM_MATER: expected cham_mater concept \(mandatory keyword\), got nothing
-- EXPECT_ERROR: also INCREMENT: expected _F\{\.\.\.\} \(mandatory factor keyword\), got nothing
-- EXPECT_ERROR: also CONVERGENCE\.RESI_GLOB_RELA: expected real > 0, got -1e-06
-- EXPECT_STATUS: 2
DEBUT()
RESU = STAT_NON_LINE{ CONVERGENCE = _F{ RESI_GLOB_RELA = -1.0e-6 } }
FIN()
