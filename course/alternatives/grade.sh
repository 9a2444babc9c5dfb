#!/bin/sh
# Test machinery: not part of any assignment.
# The grader against correct code that is not the solution (issue 18): each
# course/alternatives/*.patch is a correct implementation of one part, written from the handout and
# the headers in another algorithm and another rounding than the solution's. Each is applied to a
# copy of parts/ and graded as a submission with bin/grade (part isolation: its own part among the
# solution's others), once per seed; every grading must give that part full marks. A patch that no
# longer applies or a grading below full marks fails the run.
# Usage: course/alternatives/grade.sh [-s "SEEDS"] [patch ...]
#   -s "1 2 3"  grade at these seeds (CI: fixed); default: ALT_SEEDS fresh seeds (3) from the kernel
# (make calibrate-alternatives [ALT_SEEDS=3])
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
scratch="$root/build/alternatives"
seeds=
if [ "${1:-}" = "-s" ]; then seeds=$2; shift 2; fi
if [ -z "$seeds" ]; then
    i=0
    while [ $i -lt "${ALT_SEEDS:-3}" ]; do
        seeds="$seeds $(od -An -N4 -tu4 /dev/urandom | tr -d ' ')"; i=$((i + 1))
    done
fi
[ $# -gt 0 ] || set -- "$root"/course/alternatives/*.patch
full=0; short=0; broken=0
for patch in "$@"; do
    name=$(basename "$patch" .patch)
    part=$(echo "$name" | sed -n 's/^part\([0-9]\)-.*/\1/p')
    sub="$scratch/$name/submission"
    rm -rf "$scratch/$name"
    mkdir -p "$sub"
    cp -a "$root/parts" "$sub/"
    if ! patch -s -p1 -d "$sub" < "$patch"; then
        echo "BROKEN  $name: the patch no longer applies"; broken=$((broken + 1)); continue
    fi
    for seed in $seeds; do
        out="$scratch/$name/seed$seed"
        (cd "$root" && bin/grade --submission "$sub" --parts "$part" --out "$out" --seed "$seed" > "$out.txt" 2>&1)
        line=$(grep "^$part " "$out.txt")
        score=$(echo "$line" | sed -n 's/.* \([0-9.]*\) \/ \([0-9.]*\)$/\1/p')
        max=$(echo "$line" | sed -n 's/.* \([0-9.]*\) \/ \([0-9.]*\)$/\2/p')
        if [ -n "$score" ] && [ "$score" = "$max" ]; then
            echo "FULL    $name: part $part scores $score / $max at seed $seed"; full=$((full + 1))
        else
            echo "SHORT   $name: part $part scores ${score:-?} / ${max:-?} at seed $seed (see $out/results.json)"
            short=$((short + 1))
        fi
    done
done
echo "alternatives: $full gradings with full marks, $short below, $broken patches broken"
[ "$short" = 0 ] && [ "$broken" = 0 ]
