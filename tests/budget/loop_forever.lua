-- Budget test, not a verification deck (tests/budget/run_budget_tests.py runs it; `lunaster verify
-- testcases` never sees it): a Lua loop with no command in it, stopped by the time budget below.
-- Expected: exit status 5 (TIMEOUT) about 1 s after the start.
-- lunaster: time_limit=1
DEBUT()
local i = 0
while true do i = i + 1 end
