#!/bin/sh
# Benchmark: not a test. The cost of --trace-pixel (framework/trace.h) on the bunny at -s 64 -l 4 -m 5:
# one traced pixel (load + BVH build + the trace, from -v), and whether the trace's hooks slow a
# normal render: this tree's bin/pathtracer and one built from BASE (a commit before the hooks),
# timed side by side, alternating, in one run. Usage: sh bench/trace.sh [RUNS]   (make bench-trace)
set -eu
runs=${1:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
base=${BASE:-2d5ed44}
dir="$root/build/bench/trace-base"
scene=scenes/cornell_bunny.dae
flags="-q -t 2 -s 64 -l 4 -m 5 -r 200 150"
cd "$root"
if [ ! -x "$dir/bin/pathtracer" ]; then
    rm -rf "$dir" && mkdir -p "$dir"
    git archive "$base" | tar -x -C "$dir"
    make -C "$dir" -j2 bin/pathtracer > /dev/null
fi
now() { date +%s.%N; }
median() { sort -n | awk '{ v[NR] = $1 } END { printf "%.3f", v[int((NR + 1) / 2)] }'; }
: > "$dir/new.txt"; : > "$dir/old.txt"; : > "$dir/trace.txt"; : > "$dir/total.txt"
for i in $(seq "$runs"); do
    t0=$(now); bin/pathtracer $flags "$scene"; t1=$(now)
    "$dir/bin/pathtracer" $flags "$scene"; t2=$(now)
    bin/pathtracer -v -s 64 -l 4 -m 5 --trace-pixel 400 200 "$scene" 2>&1 >/dev/null |
        sed -n 's/.* in \([0-9.]*\) s (BVH.*/\1/p' >> "$dir/trace.txt"; t3=$(now)
    echo "$t1 - $t0" | bc >> "$dir/new.txt"; echo "$t2 - $t1" | bc >> "$dir/old.txt"; echo "$t3 - $t2" | bc >> "$dir/total.txt"
done
echo "render $flags $scene, median of $runs:"
echo "  with the trace hooks (this tree): $(median < "$dir/new.txt") s"
echo "  without them ($base):            $(median < "$dir/old.txt") s"
echo "--trace-pixel 400 200 -s 64 -l 4 -m 5 (800x600 frame), median of $runs:"
echo "  the trace itself: $(median < "$dir/trace.txt") s; the whole command (load, BVH, trace, print): $(median < "$dir/total.txt") s"
