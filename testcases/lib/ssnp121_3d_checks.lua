-- TEST_RESU occurrences of the 3D SSNP121 decks (testcases/ssnp121{d,e,e_simpson,f,i,j,k}.lua), loaded
-- with `require('lib.ssnp121_3d_checks')` (a module beside the decks, not a deck). Every value is
-- checked twice against its analytical value, both times with the deck's recorded VALE_CALC:
--   - at PRECISION 1e-3, the case's tolerance in code_aster (0.1 %; code_aster's J allows 0.3-0.6 %),
--     kept on purpose: these checks mirror those of code_aster's case, which its .comm twin
--     (testcases/comm/) carries and tests/comm/compare_with_lua.sh matches one for one;
--   - at PRECISION 1e-10, LEGENDE '... lunaster: exact': the contact of these patch tests is exact
--     (matching faces, or integration points on every master edge), and the runs are exact to
--     round-off: at most 2.9e-13 relative on these checks in a serial run, 1.4e-12 with MUMPS
--     (--solveur=MUMPS), 1.1e-11 on 3 MPI ranks (ssnp121f); 1e-10 leaves round-off a margin of 9.
-- Returns check(cmp, refe, calc, group, kind), which adds both to `list`; `legende` names the run.
return function(list, resu, legende)
  return function(cmp, refe, calc, group, kind)
    for _, precision in ipairs({ 1.0e-3, 1.0e-10 }) do
      list[#list + 1] = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', NOM_CMP = cmp, GROUP_NO = group,
                            TYPE_TEST = kind, REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision,
                            VALE_CALC = calc,
                            LEGENDE = precision < 1.0e-3 and (legende and legende .. ', ' or '') .. 'lunaster: exact'
                                      or legende }
    end
  end
end
