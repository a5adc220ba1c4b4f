#!/usr/bin/env python3
"""The engine's folders include only folders below them (docs/architecture.md, "Layers").

check_layers.py ENGINE_DIR ORDER
    Reads every source of ENGINE_DIR (engine/) and its #include "engine/<folder>/..." lines; fails,
    naming file:line, on an include of a folder above the file's own in ORDER (the folders lowest
    first, ',' or ';' between them: CMake's LUNASTER_ENGINE_LAYERS), on a folder of engine/ that ORDER does
    not place, and on a relative include that leaves its folder ("../x/y.hpp" would slip past).
check_layers.py --self-test ENGINE_DIR ORDER
    Shows that the check can fail: on a scratch copy of ENGINE_DIR it passes as the tree does,
    then fails on each upward include added to the copy (naming the file and line added), and
    still passes with a downward one.
"""
import pathlib
import re
import shutil
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCES = {".hpp", ".cpp", ".h", ".c", ".inc"}


def violations(engine_dir, order):
    """Every offending include of the tree, as 'path:line: what' (paths relative to engine/'s parent)."""
    engine_dir = pathlib.Path(engine_dir)
    rank = {folder: i for i, folder in enumerate(order)}
    found = []
    for folder in sorted(p.name for p in engine_dir.iterdir() if p.is_dir()):
        if folder not in rank:
            found.append(f"engine/{folder}: a folder the order does not place ({' < '.join(order)}); "
                         "add it to LUNASTER_ENGINE_LAYERS (CMakeLists.txt) and docs/architecture.md")
    for path in sorted(engine_dir.rglob("*")):
        if path.suffix not in SOURCES or not path.is_file():
            continue
        rel = path.relative_to(engine_dir)
        own = rel.parts[0]
        if own not in rank:
            continue
        name = f"engine/{rel.as_posix()}"
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), start=1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            if target.startswith("engine/"):
                parts = target.split("/")
                included = parts[1] if len(parts) > 2 else ""
                if included not in rank:
                    found.append(f"{name}:{number}: includes {target}, in no folder of the order")
                elif rank[included] > rank[own]:
                    found.append(f"{name}:{number}: engine/{own} includes {target}, a folder above it "
                                 f"({' < '.join(order)})")
            elif ".." in pathlib.PurePosixPath(target).parts:
                found.append(f'{name}:{number}: relative include "{target}": spell it "engine/<folder>/..."')
    return found


def check(engine_dir, order):
    found = violations(engine_dir, order)
    for v in found:
        print(v)
    if found:
        print(f"layers: {len(found)} include(s) against the order {' < '.join(order)}")
        return 1
    print(f"layers: every include of {engine_dir} follows the order {' < '.join(order)}")
    return 0


def self_test(engine_dir, order):
    """Upward includes added to a scratch copy must each be reported at their file and line."""
    failures = []
    with tempfile.TemporaryDirectory(prefix="lunaster-layers-") as scratch:
        copy = pathlib.Path(scratch) / "engine"
        shutil.copytree(engine_dir, copy)
        if violations(copy, order):
            failures.append("the scratch copy does not pass as the tree does")
        # (file in a folder, included header): one upward include per case, each from a fresh copy
        # of the file; the last is downward and must pass.
        lowest, highest = order[0], order[-1]
        cases = [
            (f"{lowest}", f"engine/{highest}/anything.hpp", True),
            (f"{order[-2]}", f"engine/{highest}/anything.hpp", True),  # the folder just below: a cycle's first edge
            (f"{order[len(order) // 2]}", f"engine/{order[len(order) // 2 + 1]}/anything.hpp", True),
            (f"{order[1]}", f"../{highest}/anything.hpp", True),
            (f"{highest}", f"engine/{lowest}/anything.hpp", False),
        ]
        for folder, header, must_fail in cases:
            sources = sorted(p for p in (copy / folder).glob("*.hpp"))
            if not sources:
                failures.append(f"engine/{folder} has no header to add an include to")
                continue
            victim = sources[0]
            original = victim.read_text()
            victim.write_text(original + f'#include "{header}"\n')
            line = original.count("\n") + 1
            where = f"engine/{victim.relative_to(copy).as_posix()}:{line}:"
            found = violations(copy, order)
            named = [v for v in found if v.startswith(where)]
            if must_fail and not named:
                failures.append(f'an include of "{header}" added at {where} was not reported (got {found})')
            if not must_fail and found:
                failures.append(f'a downward include of "{header}" at {where} was reported: {found}')
            if must_fail and named:
                print(f"reported as it must be: {named[0]}")
            victim.write_text(original)
        # A folder of engine/ that the order does not place.
        (copy / "newfolder").mkdir()
        if not any(v.startswith("engine/newfolder:") for v in violations(copy, order)):
            failures.append("a folder outside the order was not reported")
    for f in failures:
        print(f"self-test: {f}")
    print("layers self-test: " + ("FAILED" if failures else "the check fails on every upward include added"))
    return 1 if failures else 0


def main(argv):
    test = argv[1:2] == ["--self-test"]
    args = argv[2:] if test else argv[1:]
    if len(args) != 2:
        print(__doc__)
        return 2
    engine_dir, order = args[0], [f for f in re.split("[;,]", args[1]) if f]
    return self_test(engine_dir, order) if test else check(engine_dir, order)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
