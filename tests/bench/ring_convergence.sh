#!/usr/bin/env bash
# Mesh convergence of mortar contact on a curved interface: the pressurised ring fitted in a
# sleeve of testcases/ring_sleeve_mortar.lua (plane strain, Lame solution), QUAD4 and QUAD8
# families refined uniformly (lunaster-meshgen --ring/--sleeve --refine K). One lunaster run per
# family; the slave nodes' DEPL (DX, DY, LAGS_C) are written as IMPR_RESU text tables and
# compared with the exact solution, which this script derives again on its own (python3).
#
# Usage: tests/bench/ring_convergence.sh [-k "1 2 4 8 16"] [-f quad4,quad8] [-g SANS|AUTOMATIQUE] [BUILD_DIR]
# -g: DEFI_CONT's REAC_GEOM (default SANS: paired once, in the reference configuration, as the
#   small-strain Lame solution assumes; AUTOMATIQUE pairs again in the deformed configuration,
#   and LAGS_C is then a force per deformed length, q b / (b + u(b)) in the limit).
# Prints per mesh: h (slave cell arc length), slave nodes, nodes with LAGS_C = 0 (open),
#   e_p max   largest |lambda_j - q| / q over the slave nodes (lambda = -LAGS_C)
#   e_p mean  |mean pressure - q| / q, mean over the slave arc (trapezoid / Simpson weights)
#   e_p P_X   the relative pressure error at the interface end point on y = 0
#   e_u max   largest |u_r - u(b)| / u(b) over the slave nodes (u_r radial displacement)
# and the observed rates log(e_k / e_k+1) / log(h_k / h_k+1) between successive meshes, then
# the least-squares slope of log e against log h over all meshes.
set -euo pipefail
ks="1 2 4 8 16"; families="quad4,quad8"; reac=SANS
while getopts "k:f:g:" opt; do case $opt in k) ks=$OPTARG ;; f) families=$OPTARG ;; g) reac=$OPTARG ;; *) exit 2 ;; esac; done
case $reac in SANS|AUTOMATIQUE) ;; *) echo "$0: -g must be SANS or AUTOMATIQUE, got '$reac'" >&2; exit 2 ;; esac
shift $((OPTIND - 1))
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
[[ "$build" = /* ]] || build="$PWD/$build"
lun="$build/lunaster"; gen="$build/lunaster-meshgen"
for b in "$lun" "$gen"; do [ -x "$b" ] || { echo "$0: not an executable: $b" >&2; exit 2; }; done
work=$(mktemp -d); [ -n "${KEEP:-}" ] && echo "work: $work" >&2 || trap 'rm -rf "$work"' EXIT

# Base meshes (k = 1): NT x NR cells, ring (slave) finer along the arc than the sleeve.
NT_RING=12; NT_SLEEVE=10; NR=2
# The case (same numbers as testcases/ring_sleeve_mortar.lua)
A=0.5; B=0.75; C=1.0; P=1.0e8; E1=2.0e11; NU1=0.3; E2=1.0e11; NU2=0.25

IFS=, read -r -a fams <<< "$families"
for fam in "${fams[@]}"; do
  case $fam in quad4|quad8) ;; *) echo "$0: family must be quad4 or quad8, got '$fam'" >&2; exit 2 ;; esac
  list=""
  for k in $ks; do
    m="${fam}_k$k"
    "$gen" --ring "$fam:${NT_RING}x$NR" --sleeve "$fam:${NT_SLEEVE}x$NR" --radii "$A,$B,$C" --refine "$k" \
      -o "$work/$m.med" > /dev/null
    "$gen" --info "$work/$m.med" --nodes RING_OUT | awk '$1 == "node" { print $2, $3, $4 }' > "$work/$m.xyz"
    list="$list'$m', "
  done
  cat > "$work/$fam.lua" <<LUA
DEBUT()
local M1 = DEFI_MATERIAU{ ELAS = _F{ E = $E1, NU = $NU1 } }
local M2 = DEFI_MATERIAU{ ELAS = _F{ E = $E2, NU = $NU2 } }
local L = DEFI_LIST_REEL{ DEBUT = 0.0, INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 } }
for _, m in ipairs({ $list }) do
  local MA = LIRE_MAILLAGE{ FORMAT = 'MED', FICHIER = m .. '.med' }
  local MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN' } }
  local CM = AFFE_MATERIAU{ MAILLAGE = MA, AFFE = { _F{ GROUP_MA = 'RING', MATER = M1 }, _F{ GROUP_MA = 'SLEEVE', MATER = M2 } } }
  local CH = AFFE_CHAR_MECA{ MODELE = MO,
    DDL_IMPO = { _F{ GROUP_NO = { 'X0_RING', 'X0_SLEEVE' }, DX = 0.0 }, _F{ GROUP_NO = { 'Y0_RING', 'Y0_SLEEVE' }, DY = 0.0 } },
    PRES_REP = _F{ GROUP_MA = 'INNER', PRES = $P } }
  local CONT = DEFI_CONT{ MODELE = MO, REAC_GEOM = '$reac', ZONE = _F{ APPARIEMENT = 'MORTAR', GROUP_MA_ESCL = 'RING_OUT',
                          GROUP_MA_MAIT = 'SLEEVE_IN', ALGO_CONT = 'LAGRANGIEN', CONTACT_INIT = 'OUI' } }
  local R = STAT_NON_LINE{ MODELE = MO, CHAM_MATER = CM, CONTACT = CONT, EXCIT = _F{ CHARGE = CH },
                           COMPORTEMENT = _F{ RELATION = 'ELAS' }, INCREMENT = _F{ LIST_INST = L },
                           CONVERGENCE = _F{ RESI_GLOB_RELA = 1e-8 } }
  IMPR_RESU{ FORMAT = 'RESULTAT', FICHIER = m .. '.resu',
             RESU = _F{ RESULTAT = R, NOM_CHAM = 'DEPL', NUME_ORDRE = 1, GROUP_NO = 'RING_OUT' } }
end
FIN()
LUA
  (cd "$work" && "$lun" run "$fam.lua" --out out -q > "$fam.log" 2>&1) || {
    echo "$0: the $fam run failed:" >&2; tail -20 "$work/$fam.log" >&2; exit 1; }
done

/usr/bin/python3 - "$work" "$families" "$ks" "$NT_RING" "$A" "$B" "$C" "$P" "$E1" "$NU1" "$E2" "$NU2" "$reac" <<'PY'
import math, sys
work, families, ks, nt_ring = sys.argv[1], sys.argv[2].split(','), [int(k) for k in sys.argv[3].split()], int(sys.argv[4])
a, b, c, p, e1, nu1, e2, nu2 = map(float, sys.argv[5:13])
reac = sys.argv[13]

# Lame, plane strain: sigma_rr = C1 - C2/r^2, u = (1+nu)/E r ((1-2nu) C1 + C2/r^2) in a cylinder
# ri <= r <= ro under pressures pi (inside) and po (outside), C1 = (pi ri^2 - po ro^2)/(ro^2 - ri^2),
# C2 = (pi - po) ri^2 ro^2/(ro^2 - ri^2). Ring: pi = p, po = q; sleeve: pi = q, po = 0; u equal at b.
def u_at(r, ri, ro, pi, po, e, nu):
    c1 = (pi * ri**2 - po * ro**2) / (ro**2 - ri**2)
    c2 = (pi - po) * ri**2 * ro**2 / (ro**2 - ri**2)
    return (1 + nu) / e * r * ((1 - 2 * nu) * c1 + c2 / r**2)
def mismatch(q):
    return u_at(b, a, b, p, q, e1, nu1) - u_at(b, b, c, q, 0.0, e2, nu2)
q = -mismatch(0.0) * p / (mismatch(p) - mismatch(0.0))  # mismatch is affine in q
ub = u_at(b, b, c, q, 0.0, e2, nu2)
print(f"exact: q = {q:.10e} Pa (LAGS_C = -q), u(b) = {ub:.10e} m; REAC_GEOM = {reac}")

def read(m):
    xyz = {}
    for line in open(f"{work}/{m}.xyz"):
        n, x, y = line.split()
        xyz[n] = (float(x), float(y))
    text = open(f"{work}/out/{m}.resu").read().split("NUME_ORDRE 1")[1].splitlines()
    head = text[1].split()
    rows = {}
    for line in text[2:]:
        f = line.split()
        if len(f) == len(head) and f[0] in xyz:
            rows[f[0]] = dict(zip(head[1:], map(float, f[1:])))
    return xyz, rows

def slope(hs, es):
    xs, ys = [math.log(h) for h in hs], [math.log(e) for e in es]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)

for fam in families:
    print(f"\n{fam.upper()} (ring {fam}:{nt_ring}x2 on sleeve {fam}:{nt_ring * 10 // 12}x2, refined by k)")
    print("    k   h (m)      slave  open   e_p max     e_p mean    e_p P_X     e_u max")
    hs, cols = [], {"e_p max": [], "e_p mean": [], "e_p P_X": [], "e_u max": []}
    for k in ks:
        xyz, rows = read(f"{fam}_k{k}")
        nodes = sorted(rows, key=lambda n: math.atan2(xyz[n][1], xyz[n][0]))
        th = [math.atan2(xyz[n][1], xyz[n][0]) for n in nodes]
        lam = [-rows[n]["LAGS_C"] for n in nodes]
        ur = [(xyz[n][0] * rows[n]["DX"] + xyz[n][1] * rows[n]["DY"]) / math.hypot(*xyz[n]) for n in nodes]
        # arc weights: trapezoid on SEG2 (QUAD4) cells, Simpson on SEG3 (QUAD8) cells
        w = [0.0] * len(nodes)
        if fam == "quad4":
            for i in range(len(nodes) - 1):
                d = b * (th[i + 1] - th[i]); w[i] += d / 2; w[i + 1] += d / 2
        else:
            for i in range(0, len(nodes) - 2, 2):
                d = b * (th[i + 2] - th[i]); w[i] += d / 6; w[i + 1] += 2 * d / 3; w[i + 2] += d / 6
        h = b * math.pi / 2 / (nt_ring * k)
        e = {"e_p max": max(abs(l - q) for l in lam) / q,
             "e_p mean": abs(sum(wi * l for wi, l in zip(w, lam)) / sum(w) - q) / q,
             "e_p P_X": abs(lam[0] - q) / q,
             "e_u max": max(abs(u - ub) for u in ur) / ub}
        n_open = sum(1 for n in nodes if rows[n]["LAGS_C"] == 0.0)
        hs.append(h)
        for key in cols: cols[key].append(e[key])
        print(f"  {k:3d}   {h:.4e}  {len(nodes):5d}  {n_open:4d}   " + "  ".join(f"{e[key]:.3e}" for key in cols))
    print("  observed rates between successive meshes:")
    for key, es in cols.items():
        rates = [math.log(es[i] / es[i + 1]) / math.log(hs[i] / hs[i + 1]) if es[i] > 0 and es[i + 1] > 0 else float("nan")
                 for i in range(len(es) - 1)]
        fit = slope(hs, es) if all(x > 0 for x in es) else float("nan")
        print(f"    {key:9s} " + " ".join(f"{r:6.2f}" for r in rates) + f"   least-squares slope {fit:.2f}")
PY
