#!/bin/sh
# Part 6's cost: the mirror-and-glass Cornell box beside the diffuse one it is made from (the same
# box, spheres, light and flags; only the two spheres' materials differ), whole processes, run in
# turn so the machine's drift falls on both. Prints each median and the ratio of the medians.
# A delta vertex costs one extra ray (its light is followed, not sampled: framework/render.c), and
# paths through glass run longer before roulette ends them; the target is a ratio of at most 1.5.
# Environment: BIN (bin), RUNS (5), THREADS (2).
set -eu
BIN=${BIN:-bin}
RUNS=${RUNS:-5}
THREADS=${THREADS:-2}
flags="-q -t $THREADS -r 480 360 -s 64 -l 4 -m 5"
echo "== part 6: scenes/cornell_mirror_glass.dae beside scenes/cornell_spheres.dae ($flags), medians of $RUNS"
times=$(mktemp)
trap 'rm -f "$times"' EXIT
i=0
while [ $i -lt "$RUNS" ]; do
    for scene in cornell_spheres cornell_mirror_glass; do
        start=$(date +%s.%N)
        "$BIN/pathtracer" $flags "scenes/$scene.dae"
        end=$(date +%s.%N)
        echo "$scene $start $end" >> "$times"
    done
    i=$((i + 1))
done
median() { awk -v s="$1" '$1 == s { print $3 - $2 }' "$times" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
diffuse=$(median cornell_spheres) specular=$(median cornell_mirror_glass)
awk -v d="$diffuse" -v s="$specular" 'BEGIN { printf "  diffuse %.2f s, mirror and glass %.2f s: ratio %.3f (target at most 1.5)\n", d, s, s / d }'
