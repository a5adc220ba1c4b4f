# Decks whose output must carry a warning (include(decks/warnings.cmake) from tests/CMakeLists.txt).
# The incompatible SSNP121 pairings (a quadrangle slave facing a TRIA6 master) must warn exactly once,
# name the pairing to use instead, and still finish with every TEST_RESU check OK (lunaster_log_test,
# tests/CMakeLists.txt, fails on a NOOK line of itself; the deck.* test of the same deck checks the
# exit status).
foreach(case ssnp121f_quad8_on_tria6 ssnp121k_quad4_on_tria6)
  lunaster_log_test(warning.${case} ${CMAKE_SOURCE_DIR}/testcases/${case}.lua "deck;warning"
    "<A> [^\n]*does not satisfy the compatibility conditions[^\n]*TRIA6 slave on.*lunaster: [0-9]+ check\\(s\\) OK, 0 NOOK"
    "compatibility conditions.*compatibility conditions")
endforeach()

# SOLVEUR STOP_SINGULIER='NON' (testcases/solver_singularity.lua): the free block must be named in a
# warning, CHOLMOD's weak pivot and MUMPS's null pivot by node and component (with the digits lost, the
# pivots set aside), and every check must still pass.
lunaster_log_test(warning.solver_singularity ${CMAKE_SOURCE_DIR}/testcases/solver_singularity.lua
  "deck;warning"
  "<A> going on as asked with a singular system: [^\n]*the body BLOCK \\(9 cells\\) has a rigid-body mode \\(free to move along DX[^\n]*\n<A> singular matrix at instant 1\\.000000e\\+00 at node N[0-9]+, component DX, going on as asked: CHOLMOD: (pivot lost [0-9.]+ significant digits \\(more than 8\\)|a pivot CHOLMOD cannot take[^\n]*null pivot)[^\n]*\n.*<A> singular matrix at instant 1\\.000000e\\+00 at node N[0-9]+, component DX, going on as asked: MUMPS: [0-9]+ null pivot\\(s\\) below 1e-8 in the scaled matrix, set to 1e20.*lunaster: 14 check\\(s\\) OK, 0 NOOK")

# A linear relation on a mortar slave node's normal component (testcases/ssnp121a_mortar_relation.lua):
# the run must name the node and component once, and every check must still pass.
lunaster_log_test(warning.ssnp121a_mortar_relation ${CMAKE_SOURCE_DIR}/testcases/ssnp121a_mortar_relation.lua
  "deck;warning"
  "<A> mortar contact: a linear relation ties the displacement along the contact normal of slave node\\(s\\) N1 \\(DY\\):.*lunaster: 16 check\\(s\\) OK, 0 NOOK"
  "contact normal of slave node.*contact normal of slave node")

# LIRE_MAILLAGE VERI_MAIL (testcases/veri_mail.lua): VERIF='NON' warns of nothing, no VERI_MAIL of the
# node in no cell only (no warning between the readings: [^<]), VERIF='OUI' of it, of the edge written twice and of the flat triangle.
lunaster_log_test(warning.veri_mail ${CMAKE_SOURCE_DIR}/testcases/veri_mail.lua "deck;warning"
  "VERIF='NON' } }\n  mesh veri_mail\\.mail: [^<]*LIRE_MAILLAGE{[^\n]*UNITE=20 }\n<A> [^\n]*: 1 node\\(s\\) belong to no cell and carry no unknown: N9\n  mesh veri_mail\\.mail: [^<]*VERIF='OUI' } }\n<A> [^\n]*: N9\n<A> [^\n]*: 1 pair\\(s\\) of cells of one type on the same nodes \\(VERI_MAIL\\): S1 = S2\n<A> [^\n]*: 1 flat cell\\(s\\), shortest over longest distance between their nodes below APLAT = 0\\.001 \\(VERI_MAIL\\): T1 \\(0\\.0001\\)\n.*lunaster: 6 check\\(s\\) OK, 0 NOOK")
