#!/usr/bin/env python3
"""Every log test (lunaster_log_test, tests/CMakeLists.txt) fails on a wrong log.

A log test passes when its output matches PASS_REGULAR_EXPRESSION and none of its
FAIL_REGULAR_EXPRESSION; CTest reads both as ';'-separated lists and passes a test on any one
piece of PASS, so a ';' written in a pattern once let two log tests pass on a run that ended
"5 NOOK". This script takes each log test's patterns as CTest holds them (`ctest --show-only=
json-v1` of the build), and the log its last run kept (deck-out/NAME.log, tests/decks/run_logged.sh),
and has CTest itself judge that log and wrong versions of it, in a small CTest project of its own
whose tests print them (`cmake -E cat`). A log test whose log is missing is run first (its command as
CTest holds it). Each wrong log must fail, where the log as it was passes (a log test failing on
its own run fails by itself, and its wrong logs prove nothing: they are left out, with a note):
  nook_count   the final count says "5 NOOK"
  nook_line    a NOOK check line before the final count
  no_check     the run checked nothing (NO_CHECK)
  sanitizer    a sanitizer's report after the run
  truncated    the run stopped before its final count
  empty        the run printed nothing
  lost_K       the lines holding the K-th piece of PASS (the text before its K-th '.*') are gone
usage: log_tests_fail.py CTEST CMAKE BUILD_DIR SCRATCH
"""
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

SUMMARY = re.compile(r"^lunaster: (\d+) check\(s\) OK, 0 NOOK$", re.M)
META = set(".[]()*+?|^$")


def literal_prefix(piece):
    """The text a regex piece requires first, up to its first operator (escapes resolved), on one line."""
    out = []
    i = 0
    while i < len(piece):
        c = piece[i]
        if c == "\\" and i + 1 < len(piece):
            c, i = piece[i + 1], i + 2
        elif c in META or c == "\n":
            break
        else:
            i += 1
        if i < len(piece) and piece[i] in "?*":  # an optional last character is not required
            break
        out.append(c)
    return "".join(out)


def top_level_pieces(pattern):
    """The pieces of `pattern` between its '.*' that lie outside brackets and parentheses."""
    pieces, depth, start, i, in_bracket = [], 0, 0, 0, False
    while i < len(pattern):
        c = pattern[i]
        if c == "\\":
            i += 2
            continue
        if in_bracket:
            in_bracket = c != "]"
        elif c == "[":
            in_bracket = True
            if pattern[i + 1:i + 2] == "]" or pattern[i + 1:i + 3] == "^]":
                i += 2 if pattern[i + 1] == "]" else 3
                continue
        elif c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
        elif depth == 0 and pattern.startswith(".*", i):
            pieces.append(pattern[start:i])
            start = i + 2
            i += 2
            continue
        i += 1
    pieces.append(pattern[start:])
    return pieces


def wrong_logs(log, pass_pattern):
    """(name, text) of the wrong versions of `log`."""
    counts = list(SUMMARY.finditer(log))
    if not counts:
        return None
    last = counts[-1]
    before, after = log[:last.start()], log[last.end():]
    nook = ("NOOK ANALYTIQUE     DEPL  A  DY  refe=-5.000000000e-02  calc=-4.000000000e-02  err=2.000e-01  "
            "tol=1.000e-03  RELATIF\n")
    yield "nook_count", before + f"lunaster: {last.group(1)} check(s) OK, 5 NOOK" + after
    yield "nook_line", before + nook + log[last.start():]
    yield "no_check", (before + "lunaster: 0 check(s) OK, 0 NOOK\nlunaster: NO_CHECK: the deck checked nothing "
                       "(it ran no TEST_RESU or TEST_TABLE): exit status 1" + after)
    yield "sanitizer", log + "==4242==ERROR: AddressSanitizer: heap-use-after-free on address 0x602000000010\n"
    yield "truncated", before
    yield "empty", ""
    for k, piece in enumerate(top_level_pieces(pass_pattern), 1):
        text = literal_prefix(piece)
        if len(text) < 4:
            continue  # too short to name its lines
        kept = [line for line in log.splitlines(keepends=True) if text not in line]
        yield f"lost_{k}", "".join(kept)


def main():
    ctest, cmake, build, scratch = sys.argv[1], sys.argv[2], Path(sys.argv[3]), Path(sys.argv[4])
    shown = subprocess.run([ctest, "--test-dir", str(build), "--show-only=json-v1"], check=True,
                           capture_output=True, text=True).stdout
    tests = []
    for test in json.loads(shown)["tests"]:
        props = {p["name"]: p["value"] for p in test.get("properties", [])}
        command = test.get("command", [])
        if len(command) > 2 and command[1].endswith("run_logged.sh"):  # bash run_logged.sh LOG lunaster run ...
            tests.append((test["name"], command, props))
    problems = []
    if not tests:
        problems.append("no log test found (a command through tests/decks/run_logged.sh) in " + str(build))
    shutil.rmtree(scratch, ignore_errors=True)
    (scratch / "logs").mkdir(parents=True)
    lines = ["cmake_minimum_required(VERSION 3.20)", "project(log_tests_fail NONE)", "enable_testing()"]
    expected = {}
    for name, command, props in tests:
        passes, fails = props.get("PASS_REGULAR_EXPRESSION", []), props.get("FAIL_REGULAR_EXPRESSION", [])
        if len(passes) != 1:
            problems.append(f"{name}: PASS_REGULAR_EXPRESSION is {len(passes)} patterns, each enough to pass: "
                            f"{[p[:60] for p in passes]}")
        log_path = Path(command[2])
        if not log_path.is_file():
            subprocess.run(command, cwd=props.get("WORKING_DIRECTORY"), stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        if not log_path.is_file():
            problems.append(f"{name}: no log of its run ({log_path})")
            continue
        log = log_path.read_text()
        variants = wrong_logs(log, passes[0] if passes else "")
        if variants is None:
            problems.append(f"{name}: its log has no final 'lunaster: N check(s) OK, 0 NOOK' line")
            continue
        # The patterns as CTest holds them: a list joined again with ';' splits where the original did.
        for kind, value in (("pass", passes), ("fail", fails)):
            (scratch / "logs" / f"{name}.{kind}").write_text(";".join(value))
        for variant, text in [("as_run", log), *variants]:
            test = f"{name}.{variant}"
            (scratch / "logs" / f"{test}.log").write_text(text)
            expected[test] = variant == "as_run"
            lines += [f'file(READ "{scratch}/logs/{name}.pass" pass)', f'file(READ "{scratch}/logs/{name}.fail" fail)',
                      f'add_test(NAME {test} COMMAND "{cmake}" -E cat "{scratch}/logs/{test}.log")',
                      f'set_tests_properties({test} PROPERTIES PASS_REGULAR_EXPRESSION "${{pass}}"',
                      '                     FAIL_REGULAR_EXPRESSION "${fail}")' if fails else ")"]
    (scratch / "CMakeLists.txt").write_text("\n".join(lines) + "\n")
    subprocess.run([cmake, "-S", str(scratch), "-B", str(scratch / "build")], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([ctest, "--test-dir", str(scratch / "build"), "-j2"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    failed_file = scratch / "build" / "Testing" / "Temporary" / "LastTestsFailed.log"
    failed = {line.split(":", 1)[1].strip() for line in failed_file.read_text().splitlines()} if failed_file.exists() else set()
    failing = {t[:-len(".as_run")] for t, must_pass in expected.items() if must_pass and t in failed}
    for name in sorted(failing):
        print(f"NOTE: {name} fails on the log of its own run ({scratch}/logs/{name}.as_run.log): "
              "its wrong logs are left out")
    for test, must_pass in sorted(expected.items()):
        if not must_pass and test.rsplit(".", 1)[0] not in failing and test not in failed:
            problems.append(f"{test}: this wrong log passes the test ({scratch}/logs/{test}.log)")
    for problem in problems:
        print("FAIL:", problem)
    wrong = [t for t, must_pass in expected.items() if not must_pass and t.rsplit(".", 1)[0] not in failing]
    print(f"{len(tests)} log test(s), {len(expected)} log(s) judged by CTest: {len(wrong)} wrong logs of "
          f"{len(tests) - len(failing)} test(s) passing on their own log, each of which must fail")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
