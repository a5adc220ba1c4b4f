-- Must-fail deck: a Lua runtime error inside a user function is reported at the
-- line where it happens.
-- EXPECT_ERROR: lua_runtime_error\.lua:8: attempt to perform arithmetic on a nil value \(field 'young'\)
-- EXPECT_STATUS: 2
DEBUT()

local function material(params)
  return DEFI_MATERIAU{ ELAS = _F{ E = params.young * 1.0e6, NU = params.nu } }
end

MAT = material({ nu = 0.3 })
FIN()
