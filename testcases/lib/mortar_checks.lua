-- TEST_RESU occurrences of the mortar decks (testcases/*mortar*.lua), loaded with
-- `require('lib.mortar_checks')` (a module beside the decks, not a deck: `lunaster verify` skips
-- folders named lib). Each check compares against the analytical value (VALE_REFE) and the deck's
-- own recorded value: `calc`, keyed 'field component point' or 'field component KIND(group)'
-- (KIND = MIN or MAX), e.g. calc['DEPL LAGS_C A'] or calc['SIGM_NOEU SIYY MIN(AB)']. A key the
-- deck's table lacks stops the run naming the key.
local M = {}

--- A set of checks on `resu` (NUME_ORDRE 1) at PRECISION `precision` (default 1e-8): `set.check`
--- adds one, `set.list` is what TEST_RESU{ RESU = ... } takes.
function M.new(resu, calc, precision)
  local set = { list = {} }
  function set.check(field, cmp, refe, where, kind)
    local key = field .. ' ' .. cmp .. ' ' .. (kind and kind .. '(' .. where .. ')' or where)
    local test = _F{ RESULTAT = resu, NUME_ORDRE = 1, NOM_CHAM = field, NOM_CMP = cmp, VALE_CALC = assert(calc[key], key),
                     REFERENCE = 'ANALYTIQUE', VALE_REFE = refe, PRECISION = precision or 1.0e-8 }
    if kind then test.GROUP_MA = where; test.TYPE_TEST = kind else test.GROUP_NO = where end
    set.list[#set.list + 1] = test
  end
  --- The SSNP121 patch test's uniform state: the pressure LAGS_C = p at `pressure_points` and
  --- its MIN and MAX over `slave`, the normal displacement `u_cmp` = u at `displacement_points`,
  --- and its MIN and MAX with those of the normal stress `s_cmp` = p over each group of `sides`.
  function set.patch(pressure_points, displacement_points, slave, sides, u_cmp, s_cmp, p, u)
    for _, point in ipairs(pressure_points) do set.check('DEPL', 'LAGS_C', p, point) end
    for _, point in ipairs(displacement_points) do set.check('DEPL', u_cmp, u, point) end
    for _, kind in ipairs({ 'MIN', 'MAX' }) do
      set.check('DEPL', 'LAGS_C', p, slave, kind)
      for _, group in ipairs(sides) do
        set.check('DEPL', u_cmp, u, group, kind)
        set.check('SIGM_NOEU', s_cmp, p, group, kind)
      end
    end
  end
  return set
end

return M
