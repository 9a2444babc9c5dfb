#!/bin/sh
# make test-grade-local: a student's `make grade` on a machine without the autograder's sandbox
# gives the autograder's verdicts. For the solution and two catalogued bugs (course/mutants/), a
# student tree (release/student with the parts solved, the bug applied) is graded twice at one seed:
#   local       bin/grade built in that tree, run there as a user who cannot have namespaces (nobody
#               when this runs as root, else the caller): it must say once, on one line, that the
#               code runs unconfined and the official grade comes from the autograder;
#   autograder  this repository's bin/grade --submission TREE (the course's other parts, the sandbox
#               this machine allows);
# and each public test's name, status and score in the two results.json must be equal. A bug is
# compared on its own part only: locally a later part is built on the student's buggy part, in the
# autograder on the course's. The bug of part 3 fails its image cases twice: each was rendered again
# (grader/grade_image.h) and differed again, but for those too noisy. Each bug's patch names what the
# grader must tell the student about it (course/mutants/says.sh), checked both ways. Ends with
# "N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
root=$PWD
SEED=${SEED:-20261124}
STUDENT=release/student
MESSAGE="grade: no sandbox on this machine: your own code runs unconfined; your official grade comes from the autograder"
[ -d "$STUDENT" ] && [ -x bin/grade ] || { echo "grade-local: run make release bin/grade first" >&2; exit 2; }
. tests/common/need.sh
. course/mutants/says.sh
need jq jq grade-local  # reads results.json (the grader's own reading is jansson's)
# Scratch outside the repository, readable by nobody on the way down.
work=$(mktemp -d /tmp/pathlab-grade-local-XXXXXX) && chmod 755 "$work" || exit 2
trap 'rm -rf "$work"' EXIT INT TERM
passed=0 failed=0
pass() { passed=$((passed + 1)); echo "  ok    $1"; }
fail() { failed=$((failed + 1)); echo "  FAIL  $1"; [ -z "${2:-}" ] || sed 's/^/        /' "$2" | tail -n 20; }

# Runs a shell command in the student tree $1 as a user without namespaces.
as_student() {
    if [ "$(id -u)" = 0 ]; then
        chown -R nobody "$work/$1" && setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups \
            env HOME="$work" sh -c "cd '$work/$1' && $2"
    else
        (cd "$work/$1" && sh -c "$2")
    fi
}

# Each test of results.json $1 as "name<TAB>status<TAB>score", public ones only.
verdicts() { jq -r '.tests[] | select(.visibility == "visible") | "\(.name)\t\(.status)\t\(.score)"' "$1"; }

# Grades tree $1 (patch $2 applied, or none) on part(s) $3 both ways and compares.
compare() {
    name=$1 patch=$2 parts=$3 tree=$work/$1
    cp -a "$STUDENT" "$tree" || { fail "$name: cannot copy the release"; return; }
    for d in "$STUDENT"/parts/*/; do  # the solutions of the release's parts (the course's, no other)
        d=$(basename "$d") && cp -a "parts/$d/." "$tree/parts/$d/" || { fail "$name: cannot copy parts/$d"; return; }
    done
    if [ -n "$patch" ] && ! patch -s -p1 -d "$tree" <"course/mutants/$patch.patch"; then
        fail "$name: the patch no longer applies"; return
    fi
    bin/grade --submission "$tree" --public --parts "$parts" --seed "$SEED" --out "$work/$name-autograder" \
        >"$work/$name-autograder.log" 2>&1
    as_student "$name" "make -s bin/grade >/dev/null && bin/grade --parts $parts --seed $SEED --out out/grade" \
        >"$work/$name-local.log" 2>&1
    n=$(grep -cxF "$MESSAGE" "$work/$name-local.log")
    if [ "$n" = 1 ]; then pass "$name: make grade says once that it runs unconfined"
    else fail "$name: make grade should say once: $MESSAGE" "$work/$name-local.log"; fi
    a=$work/$name-autograder/results.json l=$tree/out/grade/results.json
    if [ ! -s "$a" ] || [ ! -s "$l" ]; then
        fail "$name: both graders write results.json" "$work/$name-autograder.log"; return
    fi
    verdicts "$a" >"$work/$name-a.txt" && verdicts "$l" >"$work/$name-l.txt"
    if [ -s "$work/$name-a.txt" ] && diff "$work/$name-a.txt" "$work/$name-l.txt" >"$work/$name.diff"; then
        pass "$name, part $parts: the same $(wc -l <"$work/$name-a.txt") verdicts ($(cut -f2 "$work/$name-a.txt" | sort | uniq -c | xargs))"
    else
        fail "$name, part $parts: the verdicts differ (< autograder, > local)" "$work/$name.diff"
    fi
    # What the bug's patch says the grader must tell the student (course/mutants/says.sh), both ways.
    [ -z "$patch" ] && return
    for way in autograder local; do
        if [ $way = local ]; then json=$l; else json=$a; fi
        mutant_says "course/mutants/$patch.patch" "$parts" "$json" "$work/$name-$way.log" >"$work/$name-says.txt"
        if [ $? = 0 ]; then pass "$name ($way): the messages its patch names ($(grep -c '^  ok' "$work/$name-says.txt"))"
        else fail "$name ($way): a message its patch names is missing or wrong" "$work/$name-says.txt"; fi
    done
}

echo "== make grade without the sandbox vs the autograder (seed $SEED)"
compare solution "" 1,3,5
# A part the release left out (COURSE_PARTS) is not the tree's to grade, whatever cases.json lists:
# asking for it says so, naming the parts there are.
for n in 6 7 8 9; do
    ls -d parts/part${n}_* >/dev/null 2>&1 && ! ls -d "$STUDENT"/parts/part${n}_* >/dev/null 2>&1 || continue
    if as_student solution "bin/grade --parts $n --out out/grade-left-out" >"$work/left-out.log" 2>&1; then
        fail "solution: bin/grade --parts $n grades a part the release left out" "$work/left-out.log"
    elif grep -q "part $n is not one of this course's" "$work/left-out.log"; then
        pass "solution: bin/grade --parts $n says part $n is not one of this course's ($(sed -n "s/.*this course's (\(.*\))/\1/p" "$work/left-out.log"))"
    else fail "solution: bin/grade --parts $n should say the part is not the course's" "$work/left-out.log"; fi
    break
done
compare part1-pixel-corner-not-centre part1-pixel-corner-not-centre 1
compare part3-bsdf-without-pi part3-bsdf-without-pi 3
# A comparison that cannot fail proves nothing: the bugs must have lost points.
for m in part1-pixel-corner-not-centre part3-bsdf-without-pi; do
    if grep -q "	failed	" "$work/$m-a.txt" 2>/dev/null; then pass "$m: fails in both"
    else fail "$m: expected failed verdicts, got none"; fi
done
# A bug's failed image case was rendered twice (grader/grade_image.h) and failed both renders, unless
# what failed is a figure chance cannot explain, which is never rendered again (here the noise
# ratio: an albedo not divided by pi is pi times noisier too).
a=$work/part3-bsdf-without-pi-autograder/results.json
lost='[.tests[] | select(.name | startswith("Part 3: image")) | select(.status == "failed")'
n=$(jq "$lost] | length" "$a" 2>/dev/null)
twice=$(jq "$lost | select(.output | startswith(\"Rendered twice\")) | select(.output | contains(\"differs too\"))] | length" "$a" 2>/dev/null)
noisy=$(jq "$lost | select(.output | startswith(\"Rendered twice\") | not) | select(.output | contains(\"(more than 1.15x)\"))] | length" "$a" 2>/dev/null)
if [ -n "$n" ] && [ "${twice:-0}" -gt 0 ] && [ $((twice + noisy)) = "$n" ]; then
    pass "part3-bsdf-without-pi: $twice failed image cases rendered twice and different both times, $noisy too noisy (never again)"
else fail "part3-bsdf-without-pi: of its ${n:-?} failed image cases, ${twice:-?} were rendered twice and differ too and ${noisy:-?} are too noisy"; fi
echo "grade-local: $passed passed, $failed failed"
[ "$failed" = 0 ]
