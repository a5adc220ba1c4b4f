#!/usr/bin/env bash
# The speed/accuracy study (`make study`): SSNP121 mesh families, every lunaster contact
# method on each (Lua decks looping inside one lunaster run per family), CalculiX on the
# same meshes, the stability atlas, the Hertz chart (chart_hertz.lua: D_PLAN cylinder, 3D
# sphere uniform and graded, CalculiX on the same meshes), then the charts and the summary
# under docs/study/.
# Usage: tests/bench/study/run_study.sh [BUILD_DIR] [--quick]
# --quick is a smoke run: its charts and summary go to BUILD_DIR/study/quick-docs/, never over
# the published docs/study/ (only the full study writes there).
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
build=${1:-build}; quick=${2:-}
if [ -n "$quick" ] && [ "$quick" != "--quick" ]; then
  echo "run_study.sh: unknown option '$quick' (expected --quick or nothing)" >&2; exit 2
fi
[[ "$build" = /* ]] || build="$root/$build"
here="$root/tests/bench/study"
work="$build/study"
if [ "$quick" = "--quick" ]; then docs="$work/quick-docs"; else docs="$root/docs/study"; fi
gen="$build/lunaster-meshgen"
lun="$build/lunaster"
py=/usr/bin/python3
rm -rf "$work"; mkdir -p "$work/meshes" "$work/out" "$work/ccx" "$work/logs"
cp "$here"/*.lua "$work/"

if [ "$quick" = "--quick" ]; then ks2d="1 2 4"; ks3di="1"; ks3dd="1"; ccx2d="1 2 4"; ratio="12 24 48"
else ks2d="1 2 4 8 16 32"; ks3di="1 2 4"; ks3dd="1 2"; ccx2d="1 2 4 8 16"; ratio="96 60 48 36 28 24 20 17 13 12 9 7 6"
fi
# Hertz chart: "FAMILY:K[:METHOD,...]" runs of chart_hertz.lua (no method list: every method), and
# "FAMILY:K:CONTACT" CalculiX runs (45 s timeout each: the ball, held by the contact alone, makes
# CalculiX cut back, 10-40 s a run). D_PLAN, AXIS-G and 3D-G: --refine K; AXIS-U and 3D-U: K cells
# per radius.
if [ "$quick" = "--quick" ]; then
  hertz_runs="D_PLAN:1 D_PLAN:2 AXIS-U:10 AXIS-U:20 AXIS-G:1 AXIS-G:2 AXIS-G:8 3D-G:1 3D-G:2 3D-U:4:MORTAR"
  hertz_ccx="D_PLAN:1:sts"
else
  hertz_runs="D_PLAN:1 D_PLAN:2 D_PLAN:4 D_PLAN:8 AXIS-U:10 AXIS-U:20 AXIS-U:40 AXIS-U:80 AXIS-G:1 AXIS-G:2 AXIS-G:4
              AXIS-G:8 AXIS-G:16 3D-G:1 3D-G:2 3D-G:4 3D-G:8 3D-U:4 3D-U:6 3D-U:8:MORTAR,CONTINUE"
  hertz_ccx="D_PLAN:1:nts D_PLAN:1:sts D_PLAN:2:sts AXIS-U:20:sts AXIS-G:8:sts 3D-G:2:mortar 3D-G:2:sts 3D-G:4:sts"
fi
hertz_lua() {
  local out="" fam k ms
  for r in $hertz_runs; do
    IFS=: read -r fam k ms <<< "$r"
    if [ -n "$ms" ]; then ms=", { $(echo "$ms" | sed "s/\([^,]*\)/['\1'] = true/g") }"; fi
    out="$out{ '$fam', $k$ms }, "
  done
  echo "{ $out}"
}
hertz_mesh() {  # family k -> mesh of chart_hertz.lua
  case "$1" in
    D_PLAN) echo "--hertz quad8:50 --grading 1.1 --refine $2" ;;
    AXIS-G) echo "--hertz quad8:20 --grading 1.5 --refine $2" ;;
    AXIS-U) echo "--hertz quad8:$2" ;;
    3D-G) echo "--hertz hexa20:20 --grading 1.5 --refine $2" ;;
    3D-U) echo "--hertz hexa20:$2" ;;
  esac
}
hertz_file() { echo "$work/meshes/hertz_$(echo "$1" | tr -cd '[:alnum:]' | tr '[:upper:]' '[:lower:]')_k$2.med"; }
lua_list() { echo "{ $(echo "$@" | sed 's/ /, /g') }"; }
cat > "$work/config.lua" <<LUA
-- written by run_study.sh
return { ks_2d = $(lua_list $ks2d), max_k_2d = { CONTINUE = 16, ['PENALISATION-1e7'] = 16, ['PENALISATION-1e11'] = 16 }, ks_3d_i = $(lua_list $ks3di), ks_3d_d = $(lua_list $ks3dd),
         ratio_ns = $(lua_list $ratio), atlas_ks = { 1, 4 }, hertz_runs = $(hertz_lua) }
LUA

echo "study: meshes"
for k in $ks2d; do "$gen" --upper quad4:12 --lower quad4:11 --refine "$k" -o "$work/meshes/ssnp121_2d_k$k.med" >/dev/null; done
for k in $ks3di; do "$gen" --v1 hexa8:5x5x1 --v2 hexa20:4x4x1 --refine "$k" -o "$work/meshes/ssnp121_3di_k$k.med" >/dev/null; done
for k in $ks3dd; do "$gen" --v1 hexa20:4x4x4 --v2 hexa20:4x4x4 --refine "$k" -o "$work/meshes/ssnp121_3dd_k$k.med" >/dev/null; done
for n in $ratio; do "$gen" --upper "quad4:$n" --lower quad4:24 -o "$work/meshes/ratio_$n.med" >/dev/null; done
for k in 1 2 4; do
  [ -f "$work/meshes/ssnp121_2d_k$k.med" ] || "$gen" --upper quad4:12 --lower quad4:11 --refine "$k" -o "$work/meshes/ssnp121_2d_k$k.med" >/dev/null
  "$gen" --v1 "hexa8:$((12 * k))x1x$((12 * k))" --v2 "hexa8:$((11 * k))x1x$((11 * k))" -o "$work/meshes/slab_k$k.med" >/dev/null
done
"$gen" --v1 penta15:4x4x4 --v2 hexa20:4x4x4 -o "$work/meshes/incompat_q8_t6.med" >/dev/null
"$gen" --v1 penta15:4x4x4 --v2 hexa8:4x4x4 -o "$work/meshes/incompat_q4_t6.med" >/dev/null
# SSNP121 E, F, J, K (testcases/ and tools/make_meshes.sh): the integration-scheme atlas
for g in "e penta15 penta15" "f penta15 hexa20" "j penta6 penta15" "k penta6 hexa20"; do
  read -r id v1 v2 <<< "$g"
  "$gen" --v1 "$v1:4x4x4" --v2 "$v2:4x4x4" -o "$work/meshes/ssnp121$id.med" >/dev/null
done
for r in $hertz_runs; do
  IFS=: read -r fam k _ <<< "$r"
  f=$(hertz_file "$fam" "$k")
  # shellcheck disable=SC2046
  [ -f "$f" ] || "$gen" $(hertz_mesh "$fam" "$k") -o "$f" >/dev/null
done

run_deck() {  # deck name; a deck that stops is reported, the study goes on
  local t0=$SECONDS
  if (cd "$work" && "$lun" run "$1.lua" --out out -q > "logs/$1.log" 2>&1); then status=ok; else status="exit $?"; fi
  echo "study: $1 ($status, $((SECONDS - t0)) s)"
}
for deck in chart_2d atlas_penalty atlas_coef atlas_ratio atlas_init chart_3d atlas_incompat atlas_2d3d atlas_schemes chart_hertz; do run_deck "$deck"; done
# Warnings and errors the user sees, for the atlas text.
(cd "$work" && "$lun" run atlas_incompat.lua --out out_v > logs/atlas_incompat_full.log 2>&1 || true)

echo "study: CalculiX"
csv="$work/out/chart_2d_ccx.csv"
head -1 "$work/out/chart_2d.csv" > "$csv"
for k in $ccx2d; do
  for c in nts sts; do
    for pen in 1e9 1e11; do
      $py "$here/ccx/ccx_run.py" "$csv" "$work/meshes/ssnp121_2d_k$k.med" 2D-Q4 "$k" --contact "$c" --penalty "$pen" --work "$work/ccx" || true
    done
  done
  $py "$here/ccx/ccx_run.py" "$csv" "$work/meshes/ssnp121_2d_k$k.med" 2D-Q4 "$k" --contact mortar --penalty 1e11 --slab --work "$work/ccx" || true
done

# 3D: the I and D families; node-to-surface only on the two coarsest meshes, with a short
# timeout (on quadratic faces it cuts back until it gives up: the failure is the result).
csv3="$work/out/chart_3d_ccx.csv"
head -1 "$work/out/chart_2d.csv" > "$csv3"
for fam in i d; do
  ks=$ks3di; [ "$fam" = d ] && ks=$ks3dd
  for k in $ks; do
    mesh="$work/meshes/ssnp121_3d${fam}_k$k.med"; F="3D-${fam^^}"
    for c in sts mortar; do
      $py "$here/ccx/ccx_run.py" "$csv3" "$mesh" "$F" "$k" --contact "$c" --penalty 1e11 --work "$work/ccx" || true
    done
    if [ "$k" -le 2 ]; then
      $py "$here/ccx/ccx_run.py" "$csv3" "$mesh" "$F" "$k" --contact nts --penalty 1e11 --timeout 60 --work "$work/ccx" || true
    fi
  done
done

# Hertz: the same meshes and scene (ccx_run.py --hertz), penalty slope 1e12 Pa/m.
csvh="$work/out/chart_hertz_ccx.csv"
head -1 "$work/out/chart_hertz.csv" > "$csvh"
t0=$SECONDS
for r in $hertz_ccx; do
  IFS=: read -r fam k c <<< "$r"
  case "$fam" in D_PLAN) scene=dplan ;; AXIS-*) scene=axis ;; *) scene=3d ;; esac
  $py "$here/ccx/ccx_run.py" "$csvh" "$(hertz_file "$fam" "$k")" "$fam" "$k" --hertz "$scene" --contact "$c" \
    --penalty 1e12 --timeout 45 --work "$work/ccx" || true
done
echo "study: CalculiX Hertz ($((SECONDS - t0)) s)"

echo "study: charts"
$py "$here/plot_study.py" "$work" "$docs"
if [ "$quick" = "--quick" ]; then
  sed -i '1a\\n> Smoke run (`make study STUDY_FLAGS=--quick`, coarse meshes only): not the published study, which is docs/study/.' "$docs/summary.md"
fi
echo "study: charts, CSV and summary written to $docs"
