#!/usr/bin/env python3
"""CPU seconds (user + sys) of each compile of a build directory, one at a time, heaviest first.

    cmake -S . -B build-times -DCMAKE_BUILD_TYPE=Release -DLUNASTER_TESTS=OFF
    python3 tests/bench/compile_times.py build-times [--top 25] [--match engine/]

Runs every command of BUILD/compile_commands.json with ccache disabled (a cache hit is not a
compile), in the order of that file, and prints CPU and wall seconds per source file and their
sum. CPU time is what to compare when other work shares the machine; wall time is not.
A precompiled header must exist first: configure with -DLUNASTER_PCH=OFF, or build the target
once. The objects are written where the build would write them.
"""
import argparse
import json
import os
import resource
import shlex
import subprocess
import sys
import time


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--top", type=int, default=25, help="rows to print (0: all)")
    ap.add_argument("--match", default="", help="only the sources whose path contains this")
    a = ap.parse_args()
    commands = json.load(open(os.path.join(a.build, "compile_commands.json")))
    source_dir = os.path.dirname(os.path.abspath(os.path.join(os.path.dirname(__file__), "..")))
    env = dict(os.environ, CCACHE_DISABLE="1")
    rows = []
    for c in commands:
        name = os.path.relpath(c["file"], source_dir)
        if a.match not in name:
            continue
        args = c["arguments"] if "arguments" in c else shlex.split(c["command"])
        before, t0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.monotonic()
        run = subprocess.run(args, cwd=c["directory"], env=env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
        after, t1 = resource.getrusage(resource.RUSAGE_CHILDREN), time.monotonic()
        if run.returncode != 0:
            sys.exit(f"compile failed: {name}")
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        rows.append((cpu, t1 - t0, name))
    rows.sort(reverse=True)
    print(f"{'CPU s':>7} {'wall s':>7}  file")
    for cpu, wall, name in rows[: a.top or None]:
        print(f"{cpu:7.2f} {wall:7.2f}  {name}")
    print(f"{sum(r[0] for r in rows):7.1f} {sum(r[1] for r in rows):7.1f}  total of {len(rows)} compiles")


if __name__ == "__main__":
    main()
