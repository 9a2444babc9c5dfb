#!/bin/sh
# Benchmark: not a test. The cost of --trace-pixel (framework/trace.h) on the bunny at -s 64 -l 4 -m 5:
# one traced pixel (load + BVH build + the trace, from -v), and whether the trace's hooks slow a
# normal render: this tree's bin/pathtracer beside one built from BASE (a commit before the hooks),
# by bench/against.sh. Usage: sh bench/trace.sh [RUNS]   (make bench-trace)
set -eu
runs=${1:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
base=${BASE:-2d5ed44}
dir="$root/build/bench/trace"
scene=scenes/cornell_bunny.dae
cd "$root"
echo "render with the trace hooks (this tree) and without them ($base):"
sh bench/against.sh "$base" "$runs" "$scene" -q -t 2 -s 64 -l 4 -m 5 -r 200 150

now() { date +%s.%N; }
median() { sort -n | awk '{ v[NR] = $1 } END { printf "%.3f", v[int((NR + 1) / 2)] }'; }
mkdir -p "$dir"
: > "$dir/trace.txt"; : > "$dir/total.txt"
for i in $(seq "$runs"); do
    t0=$(now)
    bin/pathtracer -v -s 64 -l 4 -m 5 --trace-pixel 400 200 "$scene" 2>&1 >/dev/null |
        sed -n 's/.* in \([0-9.]*\) s (BVH.*/\1/p' >> "$dir/trace.txt"; t1=$(now)
    echo "$t1 - $t0" | bc >> "$dir/total.txt"
done
echo "--trace-pixel 400 200 -s 64 -l 4 -m 5 (800x600 frame), median of $runs:"
echo "  the trace itself: $(median < "$dir/trace.txt") s; the whole command (load, BVH, trace, print): $(median < "$dir/total.txt") s"
