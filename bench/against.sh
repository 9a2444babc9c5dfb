#!/bin/sh
# Benchmark: not a test. One render timed with this tree's bin/pathtracer and with one built from
# an earlier commit, side by side, alternating, in one run: both see the same load, so the ratio
# holds on a shared machine where absolute times do not. With valgrind installed, also both
# binaries' instruction counts for the same render (deterministic: no load moves them).
#   sh bench/against.sh BASE RUNS SCENE FLAGS...
# prints one line: flags, the two medians of RUNS wall times, their ratio, and the instructions.
# The earlier binary is built once, from `git archive BASE`, in build/bench/base-BASE/.
set -eu
[ $# -ge 3 ] || { echo "usage: sh bench/against.sh BASE RUNS SCENE FLAGS..." >&2; exit 2; }
base=$1 runs=$2 scene=$3
shift 3
root=$(cd "$(dirname "$0")/.." && pwd)
dir="$root/build/bench/base-$base"
cd "$root"
if [ ! -x "$dir/bin/pathtracer" ]; then
    rm -rf "$dir" && mkdir -p "$dir"
    git archive "$base" | tar -x -C "$dir"
    make -C "$dir" -j2 bin/pathtracer > /dev/null
fi

now() { date +%s.%N; }
median() { sort -n | awk '{ v[NR] = $1 } END { printf "%.3f", v[int((NR + 1) / 2)] }'; }
: > "$dir/new.txt"; : > "$dir/old.txt"
for i in $(seq "$runs"); do
    t0=$(now); bin/pathtracer "$@" "$scene"; t1=$(now)
    "$dir/bin/pathtracer" "$@" "$scene"; t2=$(now)
    echo "$t1 - $t0" | bc >> "$dir/new.txt"; echo "$t2 - $t1" | bc >> "$dir/old.txt"
done
new=$(median < "$dir/new.txt") old=$(median < "$dir/old.txt")

# Instructions: one run each under callgrind, single-threaded so that nothing but the code counts.
count() { bin=$1; shift; valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$@" -t 1 "$scene" 2>&1 |
          sed -n 's/.*refs: *//p' | tr -d ,; }
if command -v valgrind > /dev/null; then
    ni=$(count bin/pathtracer "$@") oi=$(count "$dir/bin/pathtracer" "$@")
    ins=$(awk -v n="$ni" -v o="$oi" 'BEGIN { printf "%.1f M vs %.1f M instructions (%+.1f%%)", n / 1e6, o / 1e6, 100 * (n / o - 1) }')
else
    ins="(no valgrind: no instruction counts)"
fi
awk -v f="$*" -v s="$scene" -v n="$new" -v o="$old" -v b="$base" -v r="$runs" -v i="$ins" \
    'BEGIN { printf "%s %s: %s s vs %s s at %s, median of %d (%+.1f%%); %s\n", f, s, n, o, b, r, 100 * (n / o - 1), i }'
