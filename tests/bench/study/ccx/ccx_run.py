#!/usr/bin/python3
"""Runs CalculiX on one SSNP121 MED mesh and appends a row to a study CSV, in the
columns lunaster's IMPR_MESURE writes (family, method, k, status, nodes, unknowns,
..., t_total, peak_rss_mb, err_p, err_sig, err_A, err_O, err_B, err_u).

    ccx_run.py CSV MESH.med FAMILY K --contact {nts,sts,mortar} --penalty K [--slab] [--work DIR]

t_total is the wall time of `ccx` (conversion excluded), peak memory from
getrusage of the child. Errors are computed as lunaster's IMPR_MESURE computes them,
from nodal values on the nodes med2inp.py lists in its .json sidecar:
  err_p      CalculiX's contact pressure CPRESS (.frd, at the slave nodes) over the slave face
  err_sig    the nodal normal stress (.frd, extrapolated and averaged at the nodes, as
             SIGM_NOEU) over both interface faces
  err_A/O/B  CPRESS at the points A, O, B (3D: A21, A22, A23), as lunaster's CONTINUE rows
  err_u      the normal displacement over both interface faces
The .frd prints 6 significant digits, so errors below ~1e-5 are not resolved.

    ccx_run.py CSV MESH.med FAMILY K --hertz {dplan,axis,3d} --contact ... --penalty K

runs the Hertz scene of chart_hertz.lua instead (same R, E, nu, b or a, load and supports; see
hertz_load) and writes err_p0 = |p - p(r)| / p0 and r_peak = r as chart_hertz.lua does: at the
slave node nearest O (or the axis) whose CPRESS is not zero, r its distance to the axis (D_PLAN:
|x|; AXIS, expanded by CalculiX into a wedge: sqrt(x^2 + z^2); 3D: sqrt(x^2 + y^2)).
Never a pass/fail test.
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import threading
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
P, U = 1.0e5, 0.05


def frd_results(frd):
    """(node coordinates, element nodes, {block name: {node: [values]}}) of an ASCII .frd
    file: the node block ('    2C'), the element block ('    3C') and the last step of each
    nodal result block (DISP, STRESS, CONTACT). Node and result records are ' -1' + I10
    number + E12.5 values; an element is a ' -1' record then ' -2' lines of I10 nodes."""
    coords, elements, out = {}, {}, {}
    section, name, values, elem = None, None, None, None
    for line in open(frd):
        key = line[:3]
        if line.startswith("    2C"):
            section = "nodes"
        elif line.startswith("    3C"):
            section = "elements"
        elif key == " -4":
            section, name, values = "results", line.split()[1], {}
        elif key == " -3":
            if section == "results":
                out[name] = values  # a later step of the same block replaces an earlier one
            section = None
        elif section == "elements":
            if key == " -1":
                elem = int(line[3:13])
                elements[elem] = []
            elif key == " -2":
                elements[elem] += [int(line[k:k + 10]) for k in range(3, len(line.rstrip()) - 9, 10)]
        elif key == " -1" and section in ("nodes", "results"):
            body = line[13:].rstrip("\n")
            row = [float(body[k:k + 12]) for k in range(0, len(body) - 11, 12)]
            (coords if section == "nodes" else values)[int(line[3:13])] = row
    return coords, elements, out


def node_values(coords, candidates, block, targets):
    """For each target point, the mean of `block` over the candidate .frd nodes at its
    coordinates (its first len(point) coordinates: a 2D point matches every node of the
    layer CalculiX expands a 2D mesh into); None where no node of the block is there."""
    ids = np.array([n for n in candidates if n in block and n in coords])
    if len(ids) == 0:
        return [None] * len(targets)
    xyz = np.array([coords[n] for n in ids])
    vals = np.array([block[n] for n in ids])
    span = np.ptp(xyz, axis=0).max()
    out = []
    for t in targets:
        d = np.abs(xyz[:, :len(t)] - np.array(t)).max(axis=1)
        hit = d <= 1e-5 * span
        out.append(vals[hit].mean(axis=0) if hit.any() else None)
    return out


def body_nodes(elements, first_last):
    lo, hi = first_last
    return {n for e, conn in elements.items() if lo <= e <= hi for n in conn}


def max_rel(values, ref):
    return f"{max(abs(v - ref) / abs(ref) for v in values):.6g}" if values else ""


def hertz_load(scene):
    """(Q on BALL_TOP, exact p0) of chart_hertz.lua's scenes: R = 1, E = 1e9, nu = 0.3 on both
    bodies; D_PLAN cylinder with half-width b = 0.02, sphere (AXIS, 3D) with contact radius a = 0.1."""
    r, e_star = 1.0, 1.0 / (2.0 * (1.0 - 0.3 ** 2) / 1.0e9)
    if scene == "dplan":
        b = 0.02
        p = np.pi * e_star * b ** 2 / (4.0 * r)
        return p / (2.0 * r), 2.0 * p / (np.pi * b), b
    a = 0.1
    f = 4.0 * e_star * a ** 3 / (3.0 * r)
    return f / (np.pi * r ** 2), 3.0 * f / (2.0 * np.pi * a ** 2), a


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("mesh")
    ap.add_argument("family")
    ap.add_argument("k")
    ap.add_argument("--contact", default="sts")
    ap.add_argument("--penalty", type=float, default=1e9)
    ap.add_argument("--slab", action="store_true")
    ap.add_argument("--hertz", choices=("dplan", "axis", "3d"))
    ap.add_argument("--work", default=".")
    ap.add_argument("--timeout", type=float, default=300)
    a = ap.parse_args()
    name = f"ccx_{a.family}_{a.contact}_{a.penalty:.0e}_k{a.k}".replace("+", "")
    inp = os.path.join(a.work, name + ".inp")
    cmd = [sys.executable, os.path.join(HERE, "med2inp.py"), a.mesh, inp, "--contact", a.contact,
           "--penalty", str(a.penalty)] + (["--slab"] if a.slab else [])
    if a.hertz:
        q, p0, size = hertz_load(a.hertz)
        cmd += ["--hertz", repr(q)] + (["--axis"] if a.hertz == "axis" else [])
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    method = f"CalculiX-{a.contact.upper()}-{a.penalty:.0e}".replace("e+", "e")
    env = dict(os.environ, OMP_NUM_THREADS="2")
    t0 = time.perf_counter()
    status = "ok"
    logfile = os.path.join(a.work, name + ".log")
    with open(logfile, "w") as out:
        proc = subprocess.Popen(["ccx", name], cwd=a.work, env=env, stdout=out, stderr=subprocess.STDOUT)
        # wait4 gives the peak memory of ccx alone (not of the converter run before it).
        timer = threading.Timer(a.timeout, proc.kill)
        timer.start()
        _, wstatus, usage = os.wait4(proc.pid, 0)
        timer.cancel()
    wall = time.perf_counter() - t0
    peak = usage.ru_maxrss / 1024.0
    code = proc.returncode = os.waitstatus_to_exitcode(wstatus)
    log = open(logfile).read()
    if code != 0 or "*ERROR" in log:
        err = [l.strip() for l in log.splitlines() if "*ERROR" in l]
        status = "failed: " + (err[0] if err else (f"timeout {a.timeout:.0f} s" if code < 0 else f"ccx exit {code}"))
    m = re.search(r"number of equations\s+(\d+)", log)
    eqs = m.group(1) if m else ""
    iters = len(re.findall(r"^ iteration \d+", log, re.M))
    incs = len(re.findall(r"^ increment \d+ attempt", log, re.M))
    row = dict(family=a.family, method=method, k=a.k, status=status, nodes="", unknowns=eqs, free_unknowns=eqs,
               instants=incs, newton_iter=iters, contact_passes="", t_total=f"{wall:.6g}", peak_rss_mb=f"{peak:.6g}")
    frd = os.path.join(a.work, name + ".frd")
    if status == "ok" and os.path.exists(frd) and a.hertz:
        with open(inp[:-4] + ".json") as f:
            side = json.load(f)
        coords, elements, res = frd_results(frd)
        block = body_nodes(elements, side["slave_elements"])
        found = []
        for n, v in res.get("CONTACT", {}).items():
            if n in block and n in coords and v[3] != 0.0:
                x = coords[n]
                rr = abs(x[0]) if a.hertz == "dplan" else np.hypot(x[0], x[2] if a.hertz == "axis" else x[1])
                found.append((rr, v[3]))  # CPRESS, positive in compression
        if found:
            rr, p = min(found)
            exact = p0 * np.sqrt(max(1.0 - (rr / size) ** 2, 0.0))
            row["err_p0"], row["r_peak"] = f"{abs(p - exact) / p0:.6g}", f"{rr:.6g}"
        else:
            row["status"] = "failed: no slave node carries a contact pressure"
    elif status == "ok" and os.path.exists(frd):
        with open(inp[:-4] + ".json") as f:
            nodes = json.load(f)
        coords, elements, res = frd_results(frd)
        c = nodes["normal"] - 1
        # Slave and master faces have coincident nodes: each is looked up among the nodes of
        # the elements of its own body.
        upper, lower = body_nodes(elements, nodes["slave_elements"]), body_nodes(elements, nodes["master_elements"])

        def on_faces(block):
            return [v for v in node_values(coords, upper, block, nodes["slave"]) +
                    node_values(coords, lower, block, nodes["master"]) if v is not None]
        # CPRESS is the 4th CONTACT component (COPEN, CSLIP1, CSLIP2, CPRESS, ...), positive in
        # compression; a slave node with no contact record carries no pressure.
        contact = node_values(coords, upper, res.get("CONTACT", {}), nodes["slave"] + nodes["point_xyz"])
        press = [-v[3] if v is not None else 0.0 for v in contact]
        n_slave = len(nodes["slave"])
        row["err_p"] = max_rel(press[:n_slave], -P)
        row["err_sig"] = max_rel([v[c] for v in on_faces(res.get("STRESS", {}))], -P)
        for col, p in zip(("err_A", "err_O", "err_B"), press[n_slave:]):
            row[col] = max_rel([p], -P)
        row["err_u"] = max_rel([v[c] for v in on_faces(res.get("DISP", {}))], -U)
    with open(a.csv) as f:
        header = next(csv.reader(f))
    with open(a.csv, "a", newline="") as f:
        csv.writer(f).writerow([row.get(h, "") for h in header])
    print(f"{method} k={a.k}: {status}, {wall:.2f} s, err_p={row.get('err_p', row.get('err_p0', ''))}")


if __name__ == "__main__":
    main()
