#!/bin/sh
# The traces the handouts show (section "Debugging with a trace" of each handout/part<N>.md). A
# block in a handout is written as
#     <!-- trace: ARGS -->
#     ```text
#     ...the output of bin/pathtracer ARGS...
#     ```
# and this script either rewrites every block from a fresh run of the course's solution (--write), or
# checks that each is what the run prints today (--check, the default: a handout's trace cannot go
# stale). handout/figures.sh calls it with --out to keep each part's traces under out/figures/ (one
# part's only, when given one).
# Usage: handout/traces.sh [--check | --write | --out DIR [partN]]
set -eu
cd "$(dirname "$0")/.."
BIN=${BIN:-bin}
mode=${1:---check}
${MAKE:-make} --no-print-directory -s "$BIN/pathtracer"
status=0
only=
[ "$mode" != --out ] || only=${3:-}
for md in handout/part*.md; do  # the course's parts: a release holds only its own
    part=$(basename "$md" .md)
    [ -z "$only" ] || [ "$part" = "$only" ] || continue
    n=0
    # --write rewrites from the last block up, so that a block that grows moves no marker still to come.
    grep -n '^<!-- trace: .* -->$' "$md" | if [ "$mode" = --write ]; then sort -t: -k1,1nr; else cat; fi |
    while IFS=: read -r line rest; do
        args=$(echo "$rest" | sed 's/^<!-- trace: \(.*\) -->$/\1/')
        n=$((n + 1))
        got=$(mktemp)
        # shellcheck disable=SC2086  # the arguments are words on purpose
        "$BIN/pathtracer" $args > "$got"
        case "$mode" in
        --out)
            mkdir -p "${2:-out/figures}/$part"
            cp "$got" "${2:-out/figures}/$part/trace$n.txt"
            echo "$BIN/pathtracer $args > ${2:-out/figures}/$part/trace$n.txt" ;;
        --write)
            # Replace the fenced block after the marker line with the fresh output.
            awk -v start="$line" -v file="$got" '
                NR == start + 1 { print "```text"; while ((getline l < file) > 0) print l; skipping = 1; next }
                skipping && /^```$/ { print; skipping = 0; next }
                !skipping { print }' "$md" > "$md.tmp" && mv "$md.tmp" "$md"
            echo "wrote $md:$line" ;;
        *)
            shown=$(mktemp)
            awk -v start="$line" 'NR > start + 1 && /^```$/ { exit } NR > start + 1 { print }' "$md" > "$shown"
            if ! cmp -s "$shown" "$got"; then
                echo "$md:$line: the trace differs from what 'bin/pathtracer $args' prints now (handout/traces.sh --write):"
                diff "$shown" "$got" | head -5
                rm -f "$shown" "$got"
                exit 1
            fi
            rm -f "$shown" ;;
        esac
        rm -f "$got"
    done || status=1
done
[ "$mode" = --check ] && [ $status -eq 0 ] && echo "handout traces: every one is what bin/pathtracer prints"
exit $status
