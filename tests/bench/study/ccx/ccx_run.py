#!/usr/bin/python3
"""Runs CalculiX on one SSNP121 MED mesh and appends a row to a study CSV, in the
columns lunaster's IMPR_MESURE writes (family, method, k, status, nodes, unknowns,
..., t_total, peak_rss_mb, err_p, err_sig, err_A, err_O, err_B, err_u).

    ccx_run.py CSV MESH.med FAMILY K --contact {nts,sts,mortar} --penalty K [--slab] [--work DIR]

t_total is the wall time of `ccx` (conversion excluded), peak memory from
getrusage of the child. err_p: contact pressure CSTR over the contact elements
(node-to-surface: slave nodes; surface-to-surface: slave integration points), or,
for mortar which prints no CSTR, the normal stress at the interface elements'
integration points; err_sig: normal stress at those integration points (lunaster
uses nodal SIGM_NOEU: close, not identical); err_u: normal displacement of the
interface nodes. err_A/O/B are left empty. Never a pass/fail test.
"""
import argparse
import csv
import os
import re
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
P, U = 1.0e5, 0.05


def blocks(dat):
    """Yields (title, rows of floats) of each table of a CalculiX .dat file."""
    title, rows = None, []
    for line in open(dat):
        s = line.strip()
        if not s:
            continue
        if re.match(r"^[a-z]", s):
            if title:
                yield title, rows
            title, rows = s, []
        else:
            rows.append([float(v) for v in s.split()])
    if title:
        yield title, rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("mesh")
    ap.add_argument("family")
    ap.add_argument("k")
    ap.add_argument("--contact", default="sts")
    ap.add_argument("--penalty", type=float, default=1e9)
    ap.add_argument("--slab", action="store_true")
    ap.add_argument("--work", default=".")
    ap.add_argument("--timeout", type=float, default=300)
    a = ap.parse_args()
    name = f"ccx_{a.family}_{a.contact}_{a.penalty:.0e}_k{a.k}".replace("+", "")
    inp = os.path.join(a.work, name + ".inp")
    cmd = [sys.executable, os.path.join(HERE, "med2inp.py"), a.mesh, inp, "--contact", a.contact,
           "--penalty", str(a.penalty)] + (["--slab"] if a.slab else [])
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    method = f"CalculiX-{a.contact.upper()}-{a.penalty:.0e}".replace("e+", "e")
    env = dict(os.environ, OMP_NUM_THREADS="2")
    t0 = time.perf_counter()
    status = "ok"
    try:
        proc = subprocess.run(["ccx", name], cwd=a.work, env=env, capture_output=True, text=True, timeout=a.timeout)
        log = proc.stdout + proc.stderr
        if proc.returncode != 0 or "*ERROR" in log:
            err = [l.strip() for l in log.splitlines() if "*ERROR" in l]
            status = "failed: " + (err[0] if err else f"ccx exit {proc.returncode}")
    except subprocess.TimeoutExpired:
        log, status = "", f"failed: timeout {a.timeout:.0f} s"
    wall = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
    with open(os.path.join(a.work, name + ".log"), "w") as f:
        f.write(log)
    m = re.search(r"number of equations\s+(\d+)", log)
    eqs = m.group(1) if m else ""
    iters = len(re.findall(r"^ iteration \d+", log, re.M))
    incs = len(re.findall(r"^ increment \d+ attempt", log, re.M))
    row = dict(family=a.family, method=method, k=a.k, status=status, nodes="", unknowns=eqs, free_unknowns=eqs,
               instants=incs, newton_iter=iters, contact_passes="", t_total=f"{wall:.6g}", peak_rss_mb=f"{peak:.6g}")
    dat = os.path.join(a.work, name + ".dat")
    if status == "ok" and os.path.exists(dat):
        press, sig, disp = [], [], []
        normal = 2 if ("2D" in a.family) else 3
        tables = list(blocks(dat))
        final = max(float(t.split()[-1]) for t, _ in tables) if tables else 0.0
        for title, rows in tables:
            if abs(float(title.split()[-1]) - final) > 1e-9:
                continue  # an intermediate increment
            if title.startswith("contact stress"):
                press += [r[-3] for r in rows]
            elif title.startswith("stresses"):
                sig += [r[2 + normal - 1] for r in rows]  # elem, ip, sxx, syy, szz, ...
            elif title.startswith("displacements"):
                disp += [r[normal] for r in rows]
        if not press:
            press = [-s for s in sig]
        row["err_p"] = f"{max(abs(p - P) / P for p in press):.6g}" if press else ""
        row["err_sig"] = f"{max(abs(s + P) / P for s in sig):.6g}" if sig else ""
        row["err_u"] = f"{max(abs(u + U) / U for u in disp):.6g}" if disp else ""
    with open(a.csv) as f:
        header = next(csv.reader(f))
    with open(a.csv, "a", newline="") as f:
        csv.writer(f).writerow([row.get(h, "") for h in header])
    print(f"{method} k={a.k}: {status}, {wall:.2f} s, err_p={row.get('err_p', '')}")


if __name__ == "__main__":
    main()
