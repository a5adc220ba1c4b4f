-- Must-fail deck: a command called straight through pcall (as study decks do to keep going
-- after a failed run) still names the deck line of the call, not pcall's "[C]". The deck
-- catches the error, prints it, then raises it again so that the run stops with it.
-- EXPECT_ERROR: caught: [^ ]*error_under_pcall\.lua:9: AFFE_MODELE: AFFE\[1\]\.MODELISATION: expected one of .*got 'D_PLANE'
-- EXPECT_ERROR: did you mean 'D_PLAN'\?
-- EXPECT_STATUS: 2
DEBUT()
MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = '../ssnp121a.med' }
local ok, err = pcall(AFFE_MODELE, { MAILLAGE = MA,
                                     AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLANE' } })
print('caught: ' .. tostring(err))
assert(not ok)
error(err, 0)
FIN()
