-- Budget test, not a verification deck (tests/budget/run_budget_tests.py runs it): a string
-- doubling without bound. No budget in the header: the command line gives one
-- (lunaster run concat_forever.lua --memory-limit 96); do not run it without one.
DEBUT()
local s = 'x'
while true do s = s .. s end
