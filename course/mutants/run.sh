#!/bin/sh
# Test machinery: not part of any assignment.
# Applies each course/mutants/*.patch to a scratch copy of the tree, builds and runs the suite its
# "Caught by:" line names, and checks that the suite FAILS (the bug is caught). A mutant that does
# not compile, or that the suite passes, is reported and makes the run fail. A mutant whose
# "Caught by:" names no suite is one only grading sees (noise, work): skipped here, judged by
# make grade-mutants.
# Usage: course/mutants/run.sh [patch ...]     (default: every patch)
# MUTANT_JOBS mutants are tried side by side (default: one per core); each prints its own line.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
scratch="$root/build/mutants"

# One mutant: prints one line, "caught", "MISSED", "BROKEN" or "grading" first.
if [ "${1:-}" = "--one" ]; then
    patch=$2
    name=$(basename "$patch" .patch)
    suite=$(sed -n 's/^Caught by: make \(test-[a-z0-9]*\).*/\1/p' "$patch" | head -n 1)
    what=$(sed -n 's/^Mutant: //p' "$patch" | head -n 1)
    if [ -z "$suite" ]; then
        echo "grading $name: caught by grading only (make grade-mutants)"; exit 0
    fi
    dir="$scratch/$name"
    rm -rf "$dir"
    mkdir -p "$dir"
    (cd "$root" && cp -a Makefile framework parts tests scenes third_party "$dir"/)
    # Reuse the release objects: make rebuilds only what the patch touches.
    [ -d "$root/build/release" ] && mkdir -p "$dir/build" && cp -a "$root/build/release" "$dir/build/"
    if ! patch -s -p1 -d "$dir" < "$patch"; then
        echo "BROKEN  $name: the patch no longer applies"; exit 0
    fi
    touch $(sed -n 's/^+++ b\///p' "$patch" | sed "s|^|$dir/|")
    log="$dir/log.txt"
    if ! make -C "$dir" --no-print-directory "bin/$suite" > "$log" 2>&1; then
        echo "BROKEN  $name: does not build (see $log)"; exit 0
    fi
    if (cd "$dir" && "bin/$suite" >> "$log" 2>&1); then
        echo "MISSED  $name: $suite passes with: $what"
    else
        first=$(grep -m 1 -E 'wrong|invalid|disagree|took|expected' "$log" | cut -c 1-150)
        echo "caught  $name ($suite): $first"
    fi
    exit 0
fi

mkdir -p "$scratch"
[ $# -gt 0 ] || set -- "$root"/course/mutants/*.patch
jobs=${MUTANT_JOBS:-$(nproc 2>/dev/null || echo 1)}
results="$scratch/results.txt"
# Each mutant builds in its own copy, so they can run side by side; a line is printed whole.
printf '%s\n' "$@" | xargs -P "$jobs" -I '{}' sh "$0" --one '{}' | tee "$results"
caught=$(grep -c '^caught ' "$results"); missed=$(grep -c '^MISSED ' "$results")
broken=$(grep -c '^BROKEN ' "$results"); skipped=$(grep -c '^grading ' "$results")
echo "mutants: $caught caught, $missed missed, $broken broken, $skipped left to grading"
[ "$missed" -eq 0 ] && [ "$broken" -eq 0 ] && [ $((caught + skipped)) -eq $# ]
