#!/bin/sh
# Instructor tooling: not part of any assignment. `make test-judge`: proves the split suites
# (grader/seam/seam.h) in a scratch copy of the tree, built with LTO=0 as the grader builds:
#   1. the solution: every test of every part passes split (subject | judge, one test at a time),
#      exactly as it passes in test-partN;
#   2. the stubs, one part at a time: the split verdicts equal test-partN's (every test fails), and
#      a test that says "not implemented" there says it split too;
#   3. the attacks of course/judge/attacks/ (each file says what it tries and what must happen, and
#      which part file it replaces): exactly the tests its answers earn pass (its "expect: passes=N"; 0
#      for a stub with a cheat), and
#      the judge always ends by its own verdict (status 1, or 3 for a record stream that broke on a
#      render's worker), never by a crash.
# Usage: course/judge/split_check.sh   (from the Makefile; prints one line a check, fails on any)
#        SPLIT_CHECK_STAGES="attacks" course/judge/split_check.sh   (some of: solution stubs attacks)
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
# The scratch tree lives outside build/: the Makefile includes every .d file under build/, and a
# second tree's would slow every make in this one. It is removed when every check passes.
work=$(mktemp -d "${TMPDIR:-/tmp}/split-check.XXXXXX")
tree="$work/tree"
problems=0
stages=" ${SPLIT_CHECK_STAGES:-solution stubs attacks} "
mkdir -p "$tree"
(cd "$root" && cp -a Makefile framework grader parts tests scenes third_party "$tree"/)

build() {
    make -C "$tree" -j2 --no-print-directory LTO=0 WERROR=1 SAN=0 "$@" > "$work/build.log" 2>&1 && return 0
    tail -n 20 "$work/build.log"
    echo "FAIL  the scratch tree does not build: $* (see $work)"
    exit 1
}

problem() {
    echo "FAIL  $*"
    problems=$((problems + 1))
}

# split N [PATTERN]: part N's tests, each as subject | judge; "<name> pass|fail|todo" lines in
# $work/split-N.txt ("todo": failed saying "not implemented"). A judge that ends otherwise than by
# a verdict is a problem. With $judge_kb set (an attack's "judge memory:" line), each judge runs
# under `ulimit -v` of that many KiB, and one that says it has no memory is a problem: it sized a
# payload by what the record claims instead of what the call can return.
judge_kb=""
split() {
    n=$1 pattern=${2:-*} out="$work/split-$1.txt"
    : > "$out"
    for t in $(cd "$tree" && PL_TEST_LIST=1 PL_TEST_FILTER="$pattern" "bin/judge-part$n" | sed -n 's/^  //p'); do
        (cd "$tree" && PL_TEST_FILTER=$t "bin/subject-part$n" 3>&1 >/dev/null 2>&1 |
            { [ -z "$judge_kb" ] || ulimit -v "$judge_kb"; PL_TEST_FILTER=$t "bin/judge-part$n"; } > "$work/judge.log" 2>&1)
        status=$?
        [ -n "$judge_kb" ] && grep -q "has no memory" "$work/judge.log" &&
            problem "part $n, $t: the judge ran out of its $judge_kb KiB: it allocated what the record claims"
        # cmocka turns a crash inside a test into a failure ("Test failed with exception"): the
        # judge's own crash is a problem all the same.
        grep -q 'failed with exception' "$work/judge.log" && status=crashed
        case $status in
        0) echo "$t pass" ;;
        1 | 3) if grep -q "not implemented" "$work/judge.log"; then echo "$t todo"; else echo "$t fail"; fi ;;
        *) echo "$t crash"; problem "part $n, $t: the judge ended with status $status" ;;
        esac >> "$out"
    done
}

# direct N [PATTERN]: the same verdicts from test-partN in one process, in $work/direct-N.txt.
direct() {
    n=$1 pattern=${2:-*} out="$work/direct-$1.txt"
    (cd "$tree" && PL_TEST_FILTER="$pattern" "bin/test-part$n" > "$work/direct.log" 2>&1)
    : > "$out"
    for t in $(sed -n 's/^\[       OK \] //p' "$work/direct.log"); do echo "$t pass" >> "$out"; done
    for t in $(sed -n 's/^\[  FAILED  \] \(test_[A-Za-z0-9_]*\)$/\1/p' "$work/direct.log" | sort -u); do
        if awk -v t="$t" '/^\[ RUN      \] /{on = ($4 == t)} on' "$work/direct.log" | grep -q "not implemented"
        then echo "$t todo"; else echo "$t fail"; fi >> "$out"
    done
}

# same N LABEL: split and direct verdicts agree, test by test.
same() {
    sort "$work/split-$1.txt" > "$work/a"
    sort "$work/direct-$1.txt" > "$work/b"
    if cmp -s "$work/a" "$work/b"; then echo "ok    part $1, $2: $(wc -l < "$work/a") tests, split verdicts = test-part$1's ($(grep -c ' pass' "$work/a") pass)"
    else problem "part $1, $2: split and direct verdicts differ:"; diff "$work/a" "$work/b" | sed 's/^/      /'; fi
}

# The parts the tree has (parts/part<N>_*/), in order.
parts=$(cd "$root/parts" && ls -d part[1-9]_* | sed 's/^part\([1-9]\)_.*/\1/' | sort -n | tr '\n' ' ')

# wanted STAGE: the parts a stage runs on, or none when SPLIT_CHECK_STAGES leaves it out.
wanted() {
    case $stages in *" $1 "*) echo $parts ;; esac
}

# ---- 1. the solution --------------------------------------------------------------------------
all_bins=""
for n in $parts; do all_bins="$all_bins bin/subject-part$n bin/judge-part$n bin/test-part$n"; done
build $all_bins
for n in $(wanted solution); do
    start=$(date +%s)
    split $n
    direct $n
    same $n "solution (split: $(($(date +%s) - start)) s with the direct run)"
    grep -qv ' pass$' "$work/split-$n.txt" && problem "part $n: the solution fails split: $(grep -v ' pass$' "$work/split-$n.txt" | head -n 3 | tr '\n' ' ')"
done

# ---- 2. the stubs, one part at a time -----------------------------------------------------------
make -C "$root" --no-print-directory bin/strip_solutions > "$work/strip.log" 2>&1 || { echo "FAIL  bin/strip_solutions does not build"; exit 1; }
for n in $(wanted stubs); do
    for f in "$root"/parts/part${n}_*/*.c; do
        "$root/bin/strip_solutions" "$f" "$tree/parts/$(basename "$(dirname "$f")")/$(basename "$f")" || problem "strip $f"
    done
    build "bin/subject-part$n" "bin/judge-part$n" "bin/test-part$n"
    split $n
    direct $n
    same $n "stubs"
    grep -q ' pass$' "$work/split-$n.txt" && problem "part $n: a stub passes split: $(grep ' pass$' "$work/split-$n.txt" | head -n 3 | tr '\n' ' ')"
    cp "$root"/parts/part${n}_*/*.c "$tree/parts/$(basename "$(dirname "$f")")/"
done

# ---- 3. the attacks -----------------------------------------------------------------------------
for attack in $(case $stages in *" attacks "*) ls "$root"/course/judge/attacks/*.c ;; esac); do
    name=$(basename "$attack" .c)
    # Its header, in the catalogue's one format (course/README.md, "Attacks"): part, replaces,
    # tests (the tests it is graded on: part 2's whole suite takes half a minute), judge memory (the
    # judge's address space), expect: passes=N.
    key() { sed -n "s/^ \* $1: \(.*\)$/\1/p" "$attack" | head -n 1; }
    n=$(key part)
    replaces=$(key replaces)
    folder=$(basename "$(dirname "$replaces")")
    file=$(basename "$replaces")
    pattern=$(key tests)
    judge_kb=$(key "judge memory" | sed -n 's/^\([0-9]*\) MiB$/\1/p')
    judge_kb=${judge_kb:+$((judge_kb * 1024))}
    earned=$(key expect | sed -n 's/^passes=\([0-9]*\)$/\1/p')
    [ -f "$root/$replaces" ] && [ "$folder" = "$(basename "$(dirname "$(ls "$root"/parts/part${n}_*/part$n.h)")")" ] ||
        { problem "attack $name: its replaces: line names no file of part ${n:-?}'s folder"; continue; }
    cp "$root/parts/$folder/$file" "$tree/parts/$folder/$file.inc"  # for an attack that wraps the course's code
    cp "$attack" "$tree/parts/$folder/$file"
    build "bin/subject-part$n" "bin/judge-part$n"
    split "$n" "${pattern:-*}"
    passed=$(grep -c ' pass$' "$work/split-$n.txt")
    if [ "$passed" = "$earned" ]; then echo "ok    attack $name (part $n): $(wc -l < "$work/split-$n.txt") tests, $passed pass, as its answers earn"
    else problem "attack $name (part $n): $passed tests pass, its answers earn ${earned:-?}"; fi
    cp "$root/parts/$folder"/*.c "$tree/parts/$folder/"
    rm -f "$tree/parts/$folder/$file.inc"
done

if [ $problems -eq 0 ]; then
    rm -rf "$work"
    echo "test-judge: the split suites agree with test-partN and hold against every attack"
    exit 0
fi
echo "test-judge: $problems problems (the scratch tree is kept: $work)"
exit 1
