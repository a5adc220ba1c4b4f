#!/usr/bin/env python3
"""Compares the TEST_RESU checks of two `lunaster verify --json` reports, deck by deck and
check by check: the same decks, the same deck statuses, the same checks in the same order
with the same status (OK/NOOK, SAME/DIFF), and every computed value (calc=) equal to
REL relative, with an absolute floor ABS near zero: |a - b| <= max(REL * max(|a|, |b|), ABS).
With --field-scale the floor is also REL times the field's scale in the deck: the largest |calc|
of the reference's checks of that field (NOM_CHAM), so that a component which is zero analytically
(its round-off) is compared at the size of the field it belongs to.

usage: compare_checks.py REFERENCE.json OTHER.json [--rel 1e-8] [--abs 1e-8] [--field-scale]
Exit 0 if everything matches, 1 otherwise (every difference is listed). Standard library only.
"""
import argparse
import json
import re
import sys

# " OK  ANALYTIQUE     DEPL  O  DY  refe=-5.0e-02  calc=-4.99e-02  err=...  tol=...  RELATIF"
# "NOOK NON_REGRESSION ...", "SAME CODE_ASTER     ...", "DIFF CODE_ASTER     ..."
CHECK = re.compile(r"^ ?(OK|NOOK|SAME|DIFF) +(\S+) +(.*?) +refe=(\S+) +calc=(\S+)")


def checks(output):
    """The check lines of a deck's output: (status, kind, what, calc) in printed order."""
    found = []
    for line in output.splitlines():
        m = CHECK.match(line)
        if m:
            found.append((m.group(1), m.group(2), m.group(3), float(m.group(5))))
    return found


def decks(report_path):
    with open(report_path, encoding="utf-8") as f:
        report = json.load(f)
    return {d["deck"]: d for d in report["decks"]}


def close(a, b, rel, floor):
    return abs(a - b) <= max(rel * max(abs(a), abs(b)), floor)


def field_of(what):
    """The field a check reads: the first word of its description (DEPL, SIGM_NOEU ...)."""
    words = what.split()
    return words[0] if words else ""


def field_scales(found):
    """Per field (field_of), the largest |calc| among the checks `found`."""
    scales = {}
    for _, _, what, calc in found:
        scales[field_of(what)] = max(scales.get(field_of(what), 0.0), abs(calc))
    return scales


def compare(reference, other, rel, floor, field_scale=False, status_only=(), wider=None):
    """The list of differences between two reports (empty when they match) and statistics.
    field_scale: the floor of each value is also rel times its field's scale in the reference
    deck (field_scales). status_only: (deck, check number from 1) pairs whose value is not
    compared (their status, kind and description are). wider(deck, description): None, or an entry
    with a `tolerance` for a value whose conditioning allows more than `rel` (compared at that, of
    itself or of its field's scale). stats["differing"]: the (deck, check number) pairs whose values
    differ; stats["largest_share"]: the largest difference as a share of the one allowed;
    stats["wider"]: per entry of `wider`, the largest difference as a share of what `rel` allows."""
    problems = []
    stats = {"decks": 0, "checks": 0, "largest_rel": 0.0, "largest_where": "", "differing": [],
             "largest_share": 0.0, "share_where": "", "wider": {}}
    for name in sorted(set(reference) - set(other)):
        problems.append(f"{name}: missing from the second report")
    for name in sorted(set(other) - set(reference)):
        problems.append(f"{name}: not in the first report")
    for name in sorted(set(reference) & set(other)):
        a, b = reference[name], other[name]
        stats["decks"] += 1
        if a["status"] != b["status"] or a["exit_code"] != b["exit_code"]:
            problems.append(f"{name}: status {a['status']} (exit {a['exit_code']}) against "
                            f"{b['status']} (exit {b['exit_code']})")
        ca, cb = checks(a["output"]), checks(b["output"])
        scales = field_scales(ca) if field_scale else {}
        if len(ca) != len(cb):
            problems.append(f"{name}: {len(ca)} check(s) against {len(cb)}")
        for i, (x, y) in enumerate(zip(ca, cb)):
            where = f"{name}: check {i + 1} ({x[1]} {x[2]})"
            if x[:3] != y[:3]:
                problems.append(f"{where}: '{' '.join(x[:3])}' against '{' '.join(y[:3])}'")
                continue
            if (name, i + 1) in status_only:
                continue
            stats["checks"] += 1
            named = wider(name, x[2]) if wider else None
            value_rel = rel
            if named is not None:  # what the default alone allows, then the value's own tolerance
                base_floor = max(floor, rel * scales.get(field_of(x[2]), 0.0))
                base = abs(x[3] - y[3]) / max(rel * max(abs(x[3]), abs(y[3])), base_floor)
                stats["wider"][named] = max(stats["wider"].get(named, 0.0), base)
                value_rel = named.tolerance
            value_floor = max(floor, value_rel * scales.get(field_of(x[2]), 0.0))
            scale = max(abs(x[3]), abs(y[3]))
            if scale > value_floor:
                relative = abs(x[3] - y[3]) / scale
                if relative > stats["largest_rel"]:
                    stats["largest_rel"], stats["largest_where"] = relative, where
            share = abs(x[3] - y[3]) / max(value_rel * scale, value_floor)  # of what is allowed
            if share > stats["largest_share"]:
                stats["largest_share"], stats["share_where"] = share, where
            if not close(x[3], y[3], value_rel, value_floor):
                stats["differing"].append((name, i + 1))
                problems.append(f"{where}: calc={x[3]:.9e} against calc={y[3]:.9e}")
    return problems, stats


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reference")
    parser.add_argument("other")
    parser.add_argument("--rel", type=float, default=1e-8)
    parser.add_argument("--abs", type=float, default=1e-8, dest="floor")
    parser.add_argument("--field-scale", action="store_true")
    args = parser.parse_args()
    problems, stats = compare(decks(args.reference), decks(args.other), args.rel, args.floor, args.field_scale)
    for p in problems:
        print("DIFFERENT  " + p)
    print(f"{stats['decks']} deck(s), {stats['checks']} check value(s) compared; largest relative difference "
          f"{stats['largest_rel']:.3e}" + (f" at {stats['largest_where']}" if stats["largest_where"] else ""))
    if stats["checks"] == 0:
        print("DIFFERENT  no check value compared")
        problems.append("no check")
    print(f"{len(problems)} difference(s)")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
