# Sourced by the bench scripts that set a deck on a mesh in parts against the shared model
# (parts_deck.sh, contact_parts.sh): runs $work/MODE.lua for each MODE of $modes (default: parts
# shared) in turn, $runs times, under mpirun -np $np, printing the whole run's time, the lines
# matching $keep and each rank's peak from its own /usr/bin/time. $label names the size in the
# headings.
in_turn() {
  for i in $(seq "$runs"); do for mode in ${modes:-parts shared}; do
    echo "=== $mode, run $i, $np ranks, $label"
    (cd "$work" && /usr/bin/time -f "whole %e s" mpirun -np "$np" sh -c \
       '/usr/bin/time -o "peak.$OMPI_COMM_WORLD_RANK" -f "rank $OMPI_COMM_WORLD_RANK peak %M KB" "$@"' x \
       "$root/$build/lunaster" run "$mode.lua" --out "$work/out" 2>&1 | grep -E "$keep|whole" || true)
    grep -h peak "$work"/peak.*; rm -f "$work"/peak.*
  done; done
}
