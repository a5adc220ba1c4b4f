#!/usr/bin/env python3
"""Compares two builds of lunaster on every deck of a folder: the values a refactoring must keep.

usage: compare_builds.py OLD_LUNASTER NEW_LUNASTER [--decks testcases] [-j 2] [--rel 1e-10]
                         [--scratch DIR] [--keep]

Runs `verify DECKS --out ... --json ...` with each build (the same decks, one after the other)
and compares:
  - every deck's status and every TEST_RESU check, in order: the same checks with the same status,
    every computed value equal to REL of its field's scale in the deck (the largest |calc| of the
    old build's checks of that field: tests/mpi/compare_checks.py --field-scale);
  - every file the decks write: MED results dataset by dataset (floats to REL of the dataset's
    largest value), text results and tables number by number (to REL of their field's scale),
    other files byte for byte.
Exit 0 when everything matches, 1 otherwise (every difference listed). Needs h5py and numpy
(Debian: python3-h5py) for the MED files.
"""
import argparse
import filecmp
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "mpi"))
import compare_checks  # noqa: E402
from mpi_runs import same_med, same_table  # noqa: E402


def run_verify(exe, decks, out, report, jobs):
    out.mkdir(parents=True)
    cmd = [str(exe), "verify", str(decks), "-j", str(jobs), "--out", str(out), "--json", str(report)]
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    summary = [l for l in done.stdout.splitlines() if "passed" in l and "failed" in l]
    print(f"{exe}: {summary[-1] if summary else 'no summary'} (exit {done.returncode})")


def files(folder):
    return sorted(p.relative_to(folder) for p in folder.rglob("*") if p.is_file())


TIMING = ("t_", "peak_rss")  # IMPR_MESURE columns that measure the run, not the result
ROUND_OFF = 1e-12  # IMPR_MESURE residuals and errors below this are round-off in both builds


def same_measures(a, b, rel):
    """IMPR_MESURE's CSV: the same columns and rows; timings skipped; numbers to `rel`, residuals
    and errors that are round-off (below ROUND_OFF) in both builds accepted."""
    import csv
    ra, rb = list(csv.reader(a.open())), list(csv.reader(b.open()))
    if len(ra) != len(rb) or not ra or ra[0] != rb[0]:
        return [f"{len(ra)} rows against {len(rb)}, or other columns"]
    header = ra[0]
    problems = []
    for k, (x, y) in enumerate(zip(ra[1:], rb[1:])):
        if len(x) != len(y):
            problems.append(f"row {k + 1}: {len(x)} fields against {len(y)}")
            continue
        for i, (p, q) in enumerate(zip(x, y)):
            col = header[i] if i < len(header) else f"column {i + 1}"
            if col.startswith(TIMING) or p == q:
                continue
            try:
                u, v = float(p), float(q)
            except ValueError:
                problems.append(f"row {k + 1} {col}: {p!r} against {q!r}")
                continue
            if max(abs(u), abs(v)) < ROUND_OFF and col.startswith(("resi", "solve_resid", "err_")):
                continue
            if abs(u - v) > rel * max(abs(u), abs(v)):
                problems.append(f"row {k + 1} {col}: {u!r} against {v!r}")
    return problems


def compare_files(old, new, rel):
    problems = []
    fo, fn = files(old), files(new)
    problems += [f"{p}: written by the old build only" for p in sorted(set(fo) - set(fn))]
    problems += [f"{p}: written by the new build only" for p in sorted(set(fn) - set(fo))]
    counted = 0
    for p in sorted(set(fo) & set(fn)):
        a, b = old / p, new / p
        if p.suffix in (".rmed", ".med"):
            found, _, n_values = same_med(a, b, field_scale=True, rel=rel, least_scale=0.0)
            counted += n_values
        elif p.suffix == ".csv":
            found = same_measures(a, b, rel)
        elif p.suffix in (".resu", ".tab", ".txt"):
            found = same_table(a, b, rel=rel)
        elif p.suffix in (".log", ".mess"):
            continue  # logs carry timings
        else:
            found = [] if filecmp.cmp(a, b, shallow=False) else ["differs byte for byte"]
        problems += [f"{p}: {x}" for x in found]
    return problems, len(set(fo) & set(fn)), counted


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--decks", default=str(HERE.parent.parent / "testcases"))
    parser.add_argument("-j", type=int, default=2)
    parser.add_argument("--rel", type=float, default=1e-10)
    parser.add_argument("--scratch")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder")
    args = parser.parse_args()
    scratch = Path(args.scratch or tempfile.mkdtemp(prefix="compare_builds."))
    if scratch.exists() and any(scratch.iterdir()):
        sys.exit(f"compare_builds: {scratch} is not empty")
    try:
        run_verify(Path(args.old).resolve(), args.decks, scratch / "old", scratch / "old.json", args.j)
        run_verify(Path(args.new).resolve(), args.decks, scratch / "new", scratch / "new.json", args.j)
        problems, stats = compare_checks.compare(compare_checks.decks(scratch / "old.json"),
                                                 compare_checks.decks(scratch / "new.json"),
                                                 args.rel, 1e-300, field_scale=True)
        file_problems, n_files, n_values = compare_files(scratch / "old", scratch / "new", args.rel)
        problems += file_problems
        for p in problems:
            print("DIFFERENT  " + p)
        print(f"{stats['decks']} deck(s), {stats['checks']} check value(s); largest relative difference "
              f"{stats['largest_rel']:.3e}" + (f" at {stats['largest_where']}" if stats["largest_where"] else ""))
        print(f"{n_files} output file(s) compared, {n_values} MED value(s), at {args.rel:g} of their scale")
        if stats["checks"] == 0:
            problems.append("no check compared")
            print("DIFFERENT  no check value compared")
        print(f"{len(problems)} difference(s)")
        return 1 if problems else 0
    finally:
        if not args.keep:
            shutil.rmtree(scratch, ignore_errors=True)
        else:
            print(f"kept {scratch}")


if __name__ == "__main__":
    sys.exit(main())
