#!/bin/sh
# Test machinery: not part of any assignment.
# The grader against the mutant catalogue (issue 10): each course/mutants/*.patch (a realistic student
# bug) applied to a copy of parts/, graded as a submission with bin/grade; the mutant must lose
# points on its own part. (Other parts are built from the solution in isolated grading, so a mutant
# cannot cost them points by construction; `make mutants` checks its own suite catches it.)
# The framework mutant (part5-wrong-statistic-red-channel) patches the framework, not a part: it is
# skipped here. What a patch says the grader must tell the student ("Says:", "Prints:", "Never says:"
# lines: course/mutants/says.sh) is checked too. Usage: course/mutants/grade.sh [patch ...]
# (make grade-mutants)
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/tests/common/need.sh"
. "$root/course/mutants/says.sh"
need jq jq grade-mutants
scratch="$root/build/grade-mutants"
[ $# -gt 0 ] || set -- "$root"/course/mutants/*.patch
lost=0; kept=0; skipped=0; unsaid=0
for patch in "$@"; do
    name=$(basename "$patch" .patch)
    part=$(echo "$name" | sed -n 's/^part\([0-9]\)-.*/\1/p')
    if sed -n 's/^+++ b\///p' "$patch" | grep -qv '^parts/'; then
        echo "SKIP    $name: patches the framework, not a part"; skipped=$((skipped + 1)); continue
    fi
    if ! grep -qE "\"part\": *$part," "$root/grading/cases.json"; then
        echo "SKIP    $name: the grader has no cases for part $part yet (make mutants checks its suite catches it)"
        skipped=$((skipped + 1)); continue
    fi
    sub="$scratch/$name/submission"
    rm -rf "$scratch/$name"
    mkdir -p "$sub"
    cp -a "$root/parts" "$sub/"
    if ! patch -s -p1 -d "$sub" < "$patch"; then echo "BROKEN  $name: the patch no longer applies"; continue; fi
    (cd "$root" && bin/grade --submission "$sub" --parts "$part" --out "$scratch/$name/out" --seed 12345 \
        > "$scratch/$name/table.txt" 2>&1)
    line=$(grep "^$part " "$scratch/$name/table.txt")
    score=$(echo "$line" | sed -n 's/.* \([0-9.]*\) \/ \([0-9.]*\)$/\1/p')
    max=$(echo "$line" | sed -n 's/.* \([0-9.]*\) \/ \([0-9.]*\)$/\2/p')
    # What the bug costs, unit tests and images apart (grading/CALIBRATION.md's table).
    costs=$(jq -r --arg p "Part $part: " '[.tests[] | select(.name | startswith($p))] |
        "unit \([.[] | select(.name | endswith("unit tests"))][0] | "\(.score)/\(.max_score)"), images \(
        [.[] | select(.name | endswith("unit tests") | not) | .score] | add)/\(
        [.[] | select(.name | endswith("unit tests") | not) | .max_score] | add)"' \
        "$scratch/$name/out/results.json" 2>/dev/null)
    if [ -n "$score" ] && [ "$score" != "$max" ]; then
        echo "LOSES   $name: part $part scores $score / $max ($costs)"; lost=$((lost + 1))
    else
        echo "KEEPS   $name: part $part scores ${score:-?} / ${max:-?} (see $scratch/$name/out)"; kept=$((kept + 1))
    fi
    mutant_says "$patch" "$part" "$scratch/$name/out/results.json" "$scratch/$name/table.txt" || unsaid=$((unsaid + 1))
done
echo "grade-mutants: $lost lose points on their part, $kept keep full marks, $skipped skipped, $unsaid with a message missing"
[ "$kept" = 0 ] && [ "$unsaid" = 0 ]
