#!/usr/bin/env python3
"""Deck budgets through the real CLI (CTest: budget.*).

usage: run_budget_tests.py CASE LUNASTER MESHGEN SOURCE_DIR SCRATCH_DIR
  verify_suite  `lunaster verify` over one good deck and the two budget decks of this folder:
                OK, TIMEOUT, OUT_OF_MEMORY in the table, the JUnit XML and the JSON; exit 1
  run_budgets   `lunaster run`: the header budget, the command-line override (run and verify),
                a bad command-line value
  long_solve    a refined SSNP121 I deck (200 steps, 500 MB) stopped inside STAT_NON_LINE's
                C++ solve by --time-limit 5 and by --memory-limit 150
A stop is checked to be the budget's (the exit status, the message naming the limit and the deck
line or command) and never before its limit; how long after the limit it comes is the scheduler's
(`ctest -j` runs deck solves beside these tests, `make test` may run beside another), so no upper
window is asserted: each command's timeout (120 s) is the hang guard.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

HERE = Path(__file__).resolve().parent
failures = []


def solve_memory_limit():
    """A memory limit that the deck's set-up fits in and its solve does not: 150 MB, or 400 MB
    in a sanitizer build (make test-asan sets LUNASTER_SANITIZED), where AddressSanitizer's
    shadow memory alone puts the process at about 200 MB before its first command."""
    return "400" if os.environ.get("LUNASTER_SANITIZED") else "150"


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


SANITIZED = bool(os.environ.get("LUNASTER_SANITIZED"))
# The time budget of the loops that `verify` runs: longer than any start of the engine (see
# verify_suite): a Release start takes well under a second even beside a loaded `make test`
# (0.07 s idle), a sanitizer build's one to four seconds. The loop spins its core for the whole
# budget, so the budget is no longer than that.
LOOP_LIMIT = 10 if SANITIZED else 4


def run(args, cwd):
    start = time.monotonic()
    proc = subprocess.run(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
    seconds = time.monotonic() - start
    print(f"$ {' '.join(str(a) for a in args)}  -> exit {proc.returncode} in {seconds:.2f} s")
    print("  " + "\n  ".join(proc.stdout.strip().splitlines()[-6:]))
    return proc.returncode, proc.stdout, seconds


def verify_suite(exe, source, scratch):
    suite = scratch / "suite"
    suite.mkdir(parents=True)
    shutil.copy(source / "testcases" / "patch_2d.lua", suite)
    shutil.copytree(source / "testcases" / "meshes", suite / "meshes")
    shutil.copy(HERE / "grow_forever.lua", suite)
    # The loop with a budget of LOOP_LIMIT s, not its own 1 s: it counts from the child's creation
    # and verify kills a child still running 1 s past it, so a start slower than the budget plus
    # that second (a sanitizer build on a loaded machine) would have been killed before its own
    # stop. LOOP_LIMIT covers any start, and the loop is then running: its own stop names line 7.
    loop_text = (HERE / "loop_forever.lua").read_text()
    assert "-- lunaster: time_limit=1\n" in loop_text
    (suite / "loop_forever.lua").write_text(loop_text.replace("-- lunaster: time_limit=1\n",
                                                              f"-- lunaster: time_limit={LOOP_LIMIT}\n"))
    junit, report = scratch / "junit.xml", scratch / "report.json"
    code, out, _ = run([exe, "verify", "suite", "-j", "2", "--out", "out", "--junit", junit, "--json", report], scratch)
    check(code == 1, "verify exits 1 when decks are over budget")
    check(re.search(r"suite/patch_2d\.lua +OK +96/0", out) is not None, "table: the good deck is OK, 96 checks")
    check(re.search(r"suite/loop_forever\.lua +TIMEOUT ", out) is not None, "table: the loop is TIMEOUT")
    check(re.search(r"suite/grow_forever\.lua +OUT_OF_MEMORY ", out) is not None, "table: the growth is OUT_OF_MEMORY")
    check(f"suite/loop_forever.lua:7: time limit of {LOOP_LIMIT} s exceeded" in out,
          "the log tail names the deck line of the loop")
    check("suite/grow_forever.lua: memory limit of 64 MB exceeded" in out, "the log tail names the memory budget")
    check("1 passed, 2 failed" in out, "summary line")
    decks = {Path(d["deck"]).name: d for d in json.loads(report.read_text())["decks"]}
    check(decks["patch_2d.lua"]["status"] == "OK", "JSON: patch_2d OK")
    check(decks["patch_2d.lua"]["time_limit"] == 300, "JSON: the good deck ran under the default 300 s")
    loop, grow = decks["loop_forever.lua"], decks["grow_forever.lua"]
    check(loop["status"] == "TIMEOUT" and loop["exit_code"] == 5 and loop["time_limit"] == LOOP_LIMIT,
          "JSON: loop TIMEOUT, exit 5")
    # Exit 5 is the deck's own stop (a deck verify kills at the limit plus its grace has exit -1).
    check(loop["seconds"] >= LOOP_LIMIT, f"the loop stopped itself, not before its {LOOP_LIMIT} s ({loop['seconds']} s)")
    check(grow["status"] == "OUT_OF_MEMORY" and grow["exit_code"] == 6 and grow["memory_limit_mb"] == 64,
          "JSON: growth OUT_OF_MEMORY, exit 6")
    cases = {c.get("name"): c for c in ET.parse(junit).getroot().iter("testcase")}
    check(len(cases["patch_2d"]) == 0, "JUnit: patch_2d passes")
    loop_error, grow_error = cases["loop_forever"].find("error"), cases["grow_forever"].find("error")
    check(loop_error is not None and loop_error.get("type") == "TIMEOUT", "JUnit: loop is an error of type TIMEOUT")
    check(grow_error is not None and grow_error.get("type") == "OUT_OF_MEMORY",
          "JUnit: growth is an error of type OUT_OF_MEMORY")
    suite_node = ET.parse(junit).getroot().find("testsuite")
    check(suite_node.get("errors") == "2" and suite_node.get("failures") == "0", "JUnit: 2 errors, 0 failures")


def run_budgets(exe, source, scratch):
    scratch.mkdir(parents=True)
    loop, grow, concat = HERE / "loop_forever.lua", HERE / "grow_forever.lua", HERE / "concat_forever.lua"
    code, out, seconds = run([exe, "run", loop, "--out", "o"], scratch)
    check(code == 5 and 1.0 <= seconds, f"header time_limit=1: exit 5, not before 1 s ({seconds:.2f} s)")
    # The loop's line (7). A start slower than the second (a sanitizer build or a loaded machine;
    # seen once, right after mpi.concurrent_runs) may still be in DEBUT (line 5) or before the
    # loop (6) when the second is up, or not yet at the deck's first line (seen in a sanitizer
    # build at load 14: "<deck>: time limit of 1 s exceeded in the deck's Lua code"): which is the
    # scheduler's. verify_suite and mpi.errors check line 7 with a budget longer than any start.
    stop = re.compile(rf"{re.escape(str(loop))}(:[567]: time limit of 1 s exceeded|: time limit of 1 s exceeded in "
                      r"the deck's Lua code)")
    check(stop.search(out) is not None, "the message names the limit, and the deck line when the deck had started")
    code, out, seconds = run([exe, "run", loop, "--out", "o", "--time-limit", "2"], scratch)
    check(code == 5 and 2.0 <= seconds, f"--time-limit 2 overrides the header: exit 5, not before 2 s ({seconds:.2f} s)")
    check("time limit of 2 s exceeded" in out, "the message gives the command-line limit")
    code, out, seconds = run([exe, "run", grow, "--out", "o"], scratch)
    check(code == 6, f"header memory_limit=64: exit 6 ({seconds:.2f} s)")
    check("memory limit of 64 MB exceeded" in out, "the message gives the header's memory limit")
    code, out, seconds = run([exe, "run", grow, "--out", "o", "--memory-limit", "128"], scratch)
    check(code == 6 and "memory limit of 128 MB exceeded" in out, "--memory-limit 128 overrides the header")
    code, out, seconds = run([exe, "run", concat, "--out", "o", "--memory-limit", "96"], scratch)
    check(code == 6 and "memory limit of 96 MB exceeded" in out,
          f"a deck without header gets its memory budget from the command line ({seconds:.2f} s)")
    code, out, _ = run([exe, "run", loop, "--time-limit", "soon"], scratch)
    check(code == 2 and "run: --time-limit expects a positive number of seconds, got 'soon'" in out,
          "a bad command-line value is a usage error")
    report = scratch / "report.json"
    # A limit longer than any start, as in verify_suite: the child stops itself (exit 5).
    code, out, _ = run([exe, "verify", loop, "--out", "vo", "--time-limit", str(LOOP_LIMIT), "--json", report], scratch)
    deck = json.loads(report.read_text())["decks"][0]
    check(code == 1 and deck["status"] == "TIMEOUT" and deck["exit_code"] == 5 and deck["time_limit"] == LOOP_LIMIT
          and LOOP_LIMIT <= deck["seconds"],
          f"verify --time-limit {LOOP_LIMIT} overrides the header ({deck['seconds']} s)")


def long_solve(exe, meshgen, source, scratch):
    scratch.mkdir(parents=True)
    deck = scratch / "refined.lua"
    shutil.copy(source / "tests" / "bench" / "ssnp121i_refined.lua", deck)
    subprocess.run([meshgen, "--v1", "hexa8:5x5x1", "--v2", "hexa20:4x4x1", "--refine", "5", "-o", scratch / "refined.med"],
                   check=True, stdout=subprocess.DEVNULL)
    # A limit that the start and set-up fit in and the solve does not, whatever the load: 5 s, or
    # 30 s in a sanitizer build (where the start and set-up take one to four seconds), and a
    # solve of 200 steps instead of 1 (each step after the first about 0.15 s of CPU: 1.96 s user
    # for the deck with 1 step, 2.26 s with 3, /usr/bin/time), half a minute of CPU, so that the
    # limit falls inside STAT_NON_LINE, not between two commands, however fast or loaded the
    # machine. Refinement 5: at 4 the solve, once its re-pairing pass needed no solve, ended
    # within about a second.
    text = deck.read_text()
    assert "INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 }" in text
    deck.write_text(text.replace("INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 }", "INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 200 }"))
    limit = 30 if SANITIZED else 5
    code, out, seconds = run([exe, "run", deck, "--out", "o", "-q", "--time-limit", str(limit)], scratch)
    check(code == 5 and seconds >= limit, f"--time-limit {limit} stops the run: exit 5, not before the limit ({seconds:.2f} s)")
    check(re.search(rf"refined\.lua: time limit of {limit} s exceeded while running \S*refined\.lua:\d+: STAT_NON_LINE; "
                    r"the run is stopped", out) is not None, "the message names the command that was running")
    limit = solve_memory_limit()
    code, out, seconds = run([exe, "run", deck, "--out", "o", "-q", "--memory-limit", limit], scratch)
    check(code == 6, f"--memory-limit {limit} stops the solve: exit 6 ({seconds:.2f} s)")
    check(re.search(rf"memory limit of {limit} MB exceeded \(resident memory \d+ MB\) while running", out) is not None,
          "the message gives the limit and the resident memory")


def main():
    case = sys.argv[1]
    exe, meshgen, source, scratch = (Path(a).resolve() for a in sys.argv[2:6])
    shutil.rmtree(scratch, ignore_errors=True)
    if case == "verify_suite":
        verify_suite(exe, source, scratch)
    elif case == "run_budgets":
        run_budgets(exe, source, scratch)
    elif case == "long_solve":
        long_solve(exe, meshgen, source, scratch)
    else:
        sys.exit(f"unknown case {case}")
    print(f"{len(failures)} failure(s)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
