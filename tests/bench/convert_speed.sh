#!/usr/bin/env bash
# `lunaster convert` on a 1,000-line .comm (the issue: "a 1,000-line .comm converts in under
# 10 ms"). The study is the SSNP121 A command file written as code_aster writes it (comments,
# keywords over several lines, tuples of _F, E-notation reals) repeated to 1,000 lines.
# Each of R runs is timed by /usr/bin/time -v (whole process: start-up, read, convert, atomic
# write); the median wall, user and system time and the peak RSS are printed. /usr/bin/time
# shows wall time in hundredths of a second, so a batch of N back-to-back runs is also timed
# and the mean per run printed.
#
# Usage: tests/bench/convert_speed.sh [-r R] [-n N] BINARY
set -euo pipefail
runs=5; batch=100
while getopts "r:n:" opt; do case $opt in r) runs=$OPTARG ;; n) batch=$OPTARG ;; *) exit 2 ;; esac; done
shift $((OPTIND - 1))
[ $# -eq 1 ] || { echo "usage: $0 [-r R] [-n N] BINARY" >&2; exit 2; }
bin=$(readlink -f "$1")
[ -x "$bin" ] || { echo "$0: not an executable: $bin" >&2; exit 2; }
work=$(mktemp -d); [ -n "${KEEP:-}" ] && echo "work: $work" >&2 || trap 'rm -rf "$work"' EXIT

block() {  # one study, suffix $1 on every concept name
  local s=$1
  cat <<COMM
# SSNP121 A, copy $s: two elastic blocks pressed together
MA$s=LIRE_MAILLAGE(FORMAT='MED',);

MO$s=AFFE_MODELE(MAILLAGE=MA$s,
               AFFE=_F(TOUT='OUI',
                       PHENOMENE='MECANIQUE',
                       MODELISATION='D_PLAN',),);

MAT$s=DEFI_MATERIAU(ELAS=_F(E=20.0E+05,
                          NU=0.0,),);

CHMAT$s=AFFE_MATERIAU(MAILLAGE=MA$s,
                    AFFE=_F(GROUP_MA=('PLAQUE1','PLAQUE2',),
                            MATER=MAT$s,),);

CHA$s=AFFE_CHAR_MECA(MODELE=MO$s,
                    DDL_IMPO=(_F(GROUP_NO='CD',
                                 DX=0.0,
                                 DY=-0.1,),
                              _F(GROUP_NO='GH',
                                 DX=0.0,
                                 DY=0.0,),),);

CONT$s=DEFI_CONTACT(MODELE=MO$s, FORMULATION='CONTINUE',
                  ALGO_RESO_CONT='POINT_FIXE', ALGO_RESO_GEOM='POINT_FIXE',
                  REAC_GEOM='CONTROLE', NB_ITER_GEOM=2,
                  ZONE=_F(GROUP_MA_ESCL='AB', GROUP_MA_MAIT='EF', INTEGRATION='SIMPSON',
                          ORDRE_INT=4, COEF_CONT=1000., CONTACT_INIT='NON'))

L_INST$s=DEFI_LIST_REEL(DEBUT=0.0,
                      INTERVALLE=_F(JUSQU_A=1.0,
                                    NOMBRE=1,),);

RAMPE$s=DEFI_FONCTION(NOM_PARA='INST',
                    VALE=(0.0,0.0,
                          1.0,1.0,),);

RESU$s=STAT_NON_LINE(MODELE=MO$s, CHAM_MATER=CHMAT$s, CONTACT=CONT$s,
                   EXCIT=_F(CHARGE=CHA$s, FONC_MULT=RAMPE$s,),
                   COMPORTEMENT=_F(RELATION='ELAS',),
                   INCREMENT=_F(LIST_INST=L_INST$s,),
                   CONVERGENCE=_F(RESI_GLOB_MAXI=2e-8, ITER_GLOB_MAXI=30,),);

TEST_RESU(RESU=(_F(NUME_ORDRE=1, RESULTAT=RESU$s, NOM_CHAM='DEPL', GROUP_NO='A', NOM_CMP='DY',
                   VALE_CALC=-4.999669690478e-02, REFERENCE='ANALYTIQUE', VALE_REFE=-0.05, PRECISION=1.E-2,),
                _F(NUME_ORDRE=1, RESULTAT=RESU$s, NOM_CHAM='DEPL', GROUP_NO='O', NOM_CMP='LAGS_C',
                   VALE_CALC=-1.003593668221e+05, REFERENCE='ANALYTIQUE', VALE_REFE=-1.0E5, PRECISION=1.E-2,),),);

COMM
}

comm="$work/study.comm"
# whole copies of the study while they fit, one-line commands up to line 999, then FIN()
block_lines=$(block 1 | wc -l)
{
  echo "DEBUT();"
  n=1; used=1
  while [ $((used + block_lines)) -le 999 ]; do block "$n"; used=$((used + block_lines)); n=$((n + 1)); done
  while [ "$used" -lt 999 ]; do
    echo "L$used=DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=$used,),);"; used=$((used + 1))
  done
  echo "FIN();"
} >"$comm"
lines=$(wc -l <"$comm")
"$bin" convert "$comm" --check >/dev/null 2>&1 || true  # warm the page cache
"$bin" convert "$comm" -o "$work/study.lua" || { echo "$0: the generated study does not convert cleanly" >&2; exit 1; }

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
walls=(); users=(); syss=(); rss=()
for r in $(seq "$runs"); do
  /usr/bin/time -v -o "$work/time.txt" "$bin" convert "$comm" -o "$work/study.lua"
  walls+=("$(awk -F': ' '/Elapsed/ { n = split($2, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s }' "$work/time.txt")")
  users+=("$(awk -F': ' '/User time/ { print $2 }' "$work/time.txt")")
  syss+=("$(awk -F': ' '/System time/ { print $2 }' "$work/time.txt")")
  rss+=("$(awk -F': ' '/Maximum resident/ { print $2 }' "$work/time.txt")")
done
mean_ms() {  # COMMAND...: mean wall time of $batch back-to-back runs, in ms
  local t0 t1; t0=$(date +%s%N)
  for _ in $(seq "$batch"); do "$@"; done
  t1=$(date +%s%N); awk -v d=$((t1 - t0)) -v n="$batch" 'BEGIN { printf "%.2f", d / n / 1e6 }'
}
: >"$work/empty.comm"
study_ms=$(mean_ms "$bin" convert "$comm" -o "$work/study.lua")
empty_ms=$(mean_ms "$bin" convert "$work/empty.comm" -o "$work/empty.lua")
echo "study: $lines lines, $(wc -c <"$comm") bytes; $runs runs under /usr/bin/time -v, then $batch back to back"
echo "median wall $(printf '%s\n' "${walls[@]}" | median) s, user $(printf '%s\n' "${users[@]}" | median) s, sys $(printf '%s\n' "${syss[@]}" | median) s, peak RSS $(printf '%s\n' "${rss[@]}" | median) kB"
echo "mean of $batch back-to-back runs: study $study_ms ms, empty .comm (start-up) $empty_ms ms," \
     "difference (reading, converting and writing the study) $(awk -v a="$study_ms" -v b="$empty_ms" 'BEGIN { printf "%.2f", a - b }') ms"
