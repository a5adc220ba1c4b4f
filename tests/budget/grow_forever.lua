-- Budget test, not a verification deck (tests/budget/run_budget_tests.py runs it): a Lua table
-- growing without bound, stopped by the memory budget below.
-- Expected: exit status 6 (OUT_OF_MEMORY) well within a second.
-- lunaster: memory_limit=64
DEBUT()
local t, i = {}, 0
while true do i = i + 1; t[i] = i end
