#!/bin/sh
# Test machinery: the grader's containment at process level (make test-grader-process; needs the
# solution tree, builds and grades part 1 twice: about two minutes on two cores).
# 1. Each part's unit_tests in grading/cases.json is the number of tests its suite runs, every test
#    belongs to exactly one of the part's unit_tasks, and each task's "tests" is how many it has.
# 2. A submission whose part 1 calls system() only under -pthread's _REENTRANT scores zero for the
#    part, the message naming `system` (the allow-list reads the objects the build linked).
# 3. A submission that does not compile shows the compiler's own message in results.json and in
#    the HTML report.
# 4. As root: no grading tree outlives its grading, and nobody can read the references, the hidden
#    cases, results.json or the report.
# 5. As a user that is not root, untrusted children still get a process limit (the grader's suite
#    run as nobody).
# 6. A submission cannot take code that is not its own: an #include from outside its folder, a
#    symbolic link in place of a file, or a function that replaces a library's (cmocka's assert)
#    each scores zero for the part, the message naming it.
# 7. As root: nothing secret is in reach of student code. bin/grade-probe sweeps the file system as
#    student code runs (confined as the build's compiler, then as a suite's or a render's code, with
#    the grading's sandbox folder, while part 3 is graded) for byte sequences of every part's solution, every reference EXR and every hidden case
#    and scene, and finds none; the same sweep run on a folder holding one of them finds it. It
#    sweeps the course's tree, the grader's output and sandbox folders and the usual shared places
#    (/var/tmp, /dev/shm, /home, /root, /etc, /opt, /srv), not all of /: on a shared machine other
#    checkouts of the course are readable there, which says nothing about the grader. Then the
#    filter, as the grader installs it, refuses what the probe tries (exec, fork, files, sockets...),
#    and `#include "/dev/zero"` ends the build fast with the limit it ran past.
# 8. (the compiler's limits, above) 9. A grading stopped by SIGTERM while student code runs exits
#    143 and leaves no process and no sandbox folder behind (bin/grade's janitor, grade_main.c).
set -eu
cd "$(dirname "$0")/../.."
out=out/sandbox-test
fail() { echo "test-grader-process: FAILED: $*"; exit 1; }
. tests/common/need.sh
need jq jq test-grader-process  # reads results.json here (the grader's own reading is jansson's)
rm -rf "$out"
mkdir -p "$out"

# 1. the expected counts are the suites' own
for n in $(jq -r '.parts[].part' grading/cases.json); do
    ls parts/*/part$n.h >/dev/null 2>&1 || continue  # a part the course left out
    want=$(sed -n "/\"part\": $n,/,/unit_tests/s/.*\"unit_tests\": *\([0-9]*\).*/\1/p" grading/cases.json)
    mkdir -p "$out/suite$n"
    CMOCKA_MESSAGE_OUTPUT=xml CMOCKA_XML_FILE="$PWD/$out/suite$n/%g.xml" bin/test-part$n >/dev/null 2>&1 ||
        fail "the solution's part $n suite fails"
    got=$(cat "$out/suite$n"/*.xml | grep -c '<testcase')
    [ "$got" = "$want" ] || fail "part $n: cases.json says unit_tests $want, the suite runs $got"
    # Every test belongs to exactly one task, and each task's "tests" is how many it has.
    sed -n 's/.*<testcase name="test_\([^"]*\)".*/\1/p' "$out/suite$n"/*.xml > "$out/suite$n/names"
    jq -r ".parts[] | select(.part == $n) | .unit_tasks[] | \"\(.task) \(.tests) \(.match | join(\" \"))\"" grading/cases.json > "$out/suite$n/tasks"
    while read -r test; do
        owners=0
        while read -r task count prefixes; do
            for prefix in $prefixes; do case "$test" in "$prefix"*) owners=$((owners + 1)); break ;; esac; done
        done < "$out/suite$n/tasks"
        [ "$owners" = 1 ] || fail "part $n: test_$test belongs to $owners tasks of cases.json's unit_tasks, not one"
    done < "$out/suite$n/names"
    while read -r task count prefixes; do
        have=0
        while read -r test; do
            for prefix in $prefixes; do case "$test" in "$prefix"*) have=$((have + 1)); break ;; esac; done
        done < "$out/suite$n/names"
        [ "$have" = "$count" ] || fail "part $n: task $task has $have tests in the suite, cases.json says $count"
    done < "$out/suite$n/tasks"
    echo "  part $n: unit_tests $want, as the suite runs, each in one task of the stated size"
done

# A submission: the solution's parts, part 1 changed by $1 (appended to pixel.c).
submission() {
    rm -rf "$out/sub"
    mkdir -p "$out/sub"
    cp -r parts "$out/sub/"
    printf '%s\n' "$1" >>"$out/sub/parts/part1_raygen/pixel.c"
}
unit_output() { jq -r '.tests[] | select(.name == "Part 1: unit tests") | .output' "$1/results.json"; }
part1_score() { jq '[.tests[] | select(.name | startswith("Part 1:")) | .score] | add' "$1/results.json"; }

# 2. system() behind _REENTRANT (defined by the build's -pthread, not by a plain recompile)
submission '#ifdef _REENTRANT
#include <stdlib.h>
int pl_sneaky(void) { return system("true"); }
#endif'
mkdir -p "$out/tmp" && chmod 711 "$out/tmp"  # the grader's sandbox folder goes here (TMPDIR)
TMPDIR=$PWD/$out/tmp bin/grade --submission "$out/sub" --parts 1 --seed 1 --out "$out/reentrant" >"$out/reentrant.log" 2>&1 || true
unit_output "$out/reentrant" | grep -q "calls 'system'" || fail "system() under _REENTRANT was not refused (see $out/reentrant.log)"
[ "$(part1_score "$out/reentrant")" = 0 ] || fail "system() under _REENTRANT scored $(part1_score "$out/reentrant")"
echo "  system() under _REENTRANT: refused, part 1 scores 0"

# 4. what nobody can reach after a grading, as root
if [ "$(id -u)" = 0 ]; then
    # No grading tree outlives its grading (what a tree may hold is the sweep's concern, below).
    [ -z "$(ls -A "$out/tmp")" ] || fail "the grading left $(ls -A "$out/tmp") in its TMPDIR"
    grep -q 'unit tests' "$out/reentrant.log" || fail "the grading did not run ($out/reentrant.log)"
    as_nobody() { setpriv --reuid=nobody --regid=nogroup --clear-groups "$@" >/dev/null 2>&1; }
    ref=$(find reference_images -name '*.exr' | head -1)
    for secret in "$ref" grading/hidden/cases.json "$out/reentrant/results.json" "$out/reentrant/report/index.html"; do
        [ -e "$secret" ] || fail "$secret is missing"
        if as_nobody cat "$secret"; then fail "nobody can read $secret"; fi
    done
    as_nobody cat grading/cases.json || fail "nobody cannot read the public cases: the check above proves nothing"
    echo "  as nobody: references, hidden cases, results.json and the report are unreadable"

    # 5. not root: the grader's own suite, as nobody, checks its children's process limit
    # (a copy: bin/ is root's alone once bin/grade --submission ran here as root)
    copy=$(mktemp -d /tmp/pathlab-nproc.XXXXXX) && chmod 755 "$copy" && cp bin/test-grader "$copy/"
    (cd "$copy" && PL_TEST_FILTER='*process_limit*' setpriv --reuid=nobody --regid=nogroup --clear-groups \
        ./test-grader) >"$out/nproc.log" 2>&1 || { rm -rf "$copy"; fail "not root, an untrusted child has no process limit (see $out/nproc.log)"; }
    rm -rf "$copy"
    grep -q 'PASSED.*1 test' "$out/nproc.log" || fail "the process-limit test did not run as nobody ($out/nproc.log)"
    echo "  as nobody (not root): untrusted children have a process limit"
else
    echo "  (not root: the checks as nobody are skipped)"
fi

# 3. a part that does not compile
submission 'int pl_broken(void) { return undeclared_thing; }'
bin/grade --submission "$out/sub" --parts 1 --seed 1 --out "$out/broken" >"$out/broken.log" 2>&1 || true
unit_output "$out/broken" | grep -q "undeclared_thing.*undeclared" ||
    fail "results.json does not carry the compiler's message (see $out/broken/results.json)"
page="$out/broken/report/index.html"
grep -q "undeclared_thing" "$page" || fail "the HTML report does not carry the compiler's message"
echo "  a part that does not build: the compiler's message is in results.json and the report"
# 6. code that is not the submission's own
refused() {  # $1: what; $2: the message results.json must carry (an extended regular expression)
    bin/grade --submission "$out/sub" --parts 1 --seed 1 --out "$out/taken" >"$out/taken.log" 2>&1 || true
    unit_output "$out/taken" | grep -qE -- "$2" || fail "$1 was not refused (see $out/taken/results.json)"
    [ "$(part1_score "$out/taken")" = 0 ] || fail "$1 scored $(part1_score "$out/taken")"
    echo "  $1: refused, part 1 scores 0"
}
printf 'static int outside_the_folder;\n' >"$out/outside.h"
submission "#include \"$PWD/$out/outside.h\""
# (Refused by the dependency check; or, where the tree sits under /tmp, not even in the compile's
# view: its /tmp is its own.)
refused "an #include from outside the part's folder" "includes a file that is neither its part's own|outside\.h: No such file or directory"
submission ''
rm "$out/sub/parts/part1_raygen/pixel.c"
ln -s "$PWD/parts/part1_raygen/pixel.c" "$out/sub/parts/part1_raygen/pixel.c"
refused "a symbolic link in place of a file" "holds a symbolic link named like C code"
submission 'void _assert_true(const unsigned long result, const char *const expression, const char *const file, const int line) { (void)result; (void)expression; (void)file; (void)line; }'
refused "a function that replaces cmocka's _assert_true" 'defines a global name reserved to the C implementation'

# 7. nothing secret in reach, as root (the stubbed submission needs the course's strip tool)
strip=${STRIP_TOOL:-}  # the course's stub maker (course/course.mk), absent from other trees
if [ "$(id -u)" = 0 ] && { [ -z "$strip" ] || [ ! -x "$strip" ]; }; then
    echo "  (no stub maker, not the course's own tree: the sweep is skipped)"
elif [ "$(id -u)" = 0 ]; then
    # The needles, hex: solution lines (40+ characters, 8 a file), 48 bytes at a quarter, the middle
    # and three quarters of each reference EXR, and at every sixteenth of each hidden file (a chunk
    # the public files share is dropped below, and a hidden cases.json is mostly the same JSON as
    # the public one). Kept in a file only root can read.
    needles=$out/needles
    hexof() { od -An -tx1 -v | tr -d ' \n'; }
    : >"$needles.raw"
    marker=SOLUTION  # the region's markers, spelt apart so this file holds none
    for f in parts/*/*.c; do
        awk -v b="BEGIN $marker" -v e="END $marker" 'index($0, b) { on = 1; next } index($0, e) { on = 0 } on' "$f" |
            sed 's/^[[:space:]]*//' | awk 'length($0) >= 40 && !/^\/[*\/]/' | head -n 8 |
            while IFS= read -r line; do printf '%s' "$line" | hexof; echo; done >>"$needles.raw"
    done
    # (A public case's preview PNG is not one: it is shipped, and a report of a student's own make
    # grade holds the same bytes; its EXR, the reference itself, is.)
    for f in $(find reference_images grading/hidden -type f); do
        case "$f" in reference_images/part*/*.png) continue ;; esac
        size=$(wc -c <"$f"); [ "$size" -ge 192 ] || continue
        # A hidden cases file is mostly JSON the public one shares: fifteen places, not three, so
        # that some of its needles stay secret whatever the parts' cases look like.
        case "$f" in grading/hidden/*) pieces=16 ;; *) pieces=4 ;; esac
        i=1
        while [ $i -lt $pieces ]; do
            at=$((size * i / pieces)); i=$((i + 1))
            tail -c +"$at" "$f" | head -c 48 | hexof >>"$needles.raw"; echo >>"$needles.raw"
        done
    done
    # A secret the student release also holds is no secret (a solution line that repeats framework
    # code, a hidden scene's chunk that a public scene shares): those needles are dropped.
    # The public cases' preview PNGs too: a hidden case may look the same as a public one (the bunny
    # at another leaf size), and then its preview is no secret either.
    public="framework tests scenes tools third_party fuzz handout bench grading/cases.json Makefile README.md
            $(echo reference_images/part*/*.png)"
    PL_SWEEP_NEEDLES=$(grep . "$needles.raw" | paste -sd, -) bin/grade-probe sweep $public >"$out/public.log" 2>&1 || true
    sed -n 's/^FOUND secret \([0-9]*\) in .*/\1/p' "$out/public.log" | sort -un >"$out/public.ids"
    grep . "$needles.raw" | awk 'NR == FNR { drop[$1 + 1] = 1; next } !(FNR in drop)' "$out/public.ids" - >"$needles.kept"
    count=$(grep -c . "$needles.kept")
    [ "$count" -ge 40 ] || fail "only $count secrets to look for"
    PL_SWEEP_NEEDLES=$(paste -sd, - <"$needles.kept"); export PL_SWEEP_NEEDLES
    chmod 600 "$needles.raw" "$needles.kept"
    # The sweep can fail: a folder holding a hidden scene, readable, is found.
    bait=$(mktemp -d /tmp/pathlab-bait.XXXXXX); chmod 755 "$bait"
    cp grading/hidden/cases.json "$bait/"; chmod 644 "$bait/cases.json"
    cp bin/grade-probe "$bait/"
    if setpriv --reuid=nobody --regid=nogroup --clear-groups "$bait/grade-probe" sweep "$bait" >"$out/bait.log" 2>&1; then
        rm -rf "$bait"; fail "the sweep does not find a hidden case in plain sight ($out/bait.log)"
    fi
    # A stubbed submission (the graded part earns nothing, the sweep is what matters), graded in the
    # background, its sandbox folder under a TMPDIR of its own. Once part 3's tree is built (its
    # suite and renders are then under way, for a minute), the probe sweeps as each untrusted stage
    # is confined: the build's compiler and the code of a suite or a render (bin/grade-probe stage).
    rm -rf "$out/sub" && mkdir -p "$out/sub"
    for f in parts/*/*; do mkdir -p "$out/sub/$(dirname "$f")"; done
    for f in parts/*/*.c parts/*/*.h; do "$strip" "$f" "$out/sub/$f" || fail "cannot strip $f"; done
    tmpbase=$(mktemp -d /tmp/pathlab-sweep.XXXXXX); chmod 711 "$tmpbase"
    roots="$PWD $PWD/$out $tmpbase /tmp /var/tmp /dev/shm /home /root /etc /opt /srv"
    TMPDIR=$tmpbase timeout 600 bin/grade --submission "$out/sub" --parts 3 --seed 1 --out "$out/swept" \
        >"$out/swept.log" 2>&1 &
    grading=$!
    sandbox=
    for i in $(seq 1200); do
        sandbox=$(ls -d "$tmpbase"/pathlab-sandbox.*/part3/bin/subject-part3 2>/dev/null | head -n 1)
        [ -n "$sandbox" ] && break
        kill -0 $grading 2>/dev/null || break
        sleep 0.1
    done
    sandbox=${sandbox%/part3/bin/subject-part3}
    : >"$out/sweep-result"
    if [ -n "$sandbox" ]; then
        for stage in build run; do
            st=0; bin/grade-probe stage $stage "$sandbox" $roots >"$out/sweep-$stage.log" 2>&1 || st=$?
            echo "$stage: exit $st: $(tail -n 1 "$out/sweep-$stage.log")" >>"$out/sweep-result"
        done
    fi
    wait $grading || true
    unset PL_SWEEP_NEEDLES
    rm -rf "$bait" "$tmpbase"
    [ -n "$sandbox" ] || fail "part 3's tree never appeared: the sweep did not run ($out/swept.log)"
    [ "$(grep -c 'exit 0: swept [0-9]* files' "$out/sweep-result")" = 2 ] ||
        fail "student code can read a secret: $(cat "$out/sweep-result") (see $out/sweep-*.log)"
    echo "  as each stage's code, while part 3 is graded: $(sed 's/: exit 0: swept \([0-9]*\) files.*/ \1 files/' "$out/sweep-result" | paste -sd, -) swept, none of $count secrets found"
    # The PID and mount namespaces where the machine gives them (a container may refuse): named either way.
    grep -Eq 'protections in force: student code as user nobody; network namespace; (PID and mount namespaces|no PID or mount namespace)[^;]*; seccomp' "$out/swept.log" ||
        fail "the staff log does not name the protections in force ($out/swept.log)"
    echo "  the staff log names the protections in force"
fi

# 8. the compiler's limits: #include "/dev/zero" stops fast, with the limit named
submission '#include "/dev/zero"'
start=$(date +%s)
timeout 600 bin/grade --submission "$out/sub" --parts 1 --seed 1 --out "$out/zero" >"$out/zero.log" 2>&1 || true
unit_output "$out/zero" | grep -q "part 1's build ran past its memory limit" ||
    fail "#include \"/dev/zero\": no verdict naming the memory limit (see $out/zero/results.json)"
echo "  #include \"/dev/zero\": part 1's build ran past its memory limit ($(( $(date +%s) - start )) s with the course's build)"
# 9. a grading stopped from outside (kill, a CI timeout, Ctrl-C) while student code runs leaves
# nothing behind: no sandbox folder, no process, and it ends as the signal says (143 for SIGTERM)
cp -r parts "$out/spin" && rm -rf "$out/sub" && mkdir -p "$out/sub" && mv "$out/spin" "$out/sub/parts"
sed -i '/^ray camera_generate_ray(/{n;s|^{$|{ for (volatile unsigned long spin = 0;; spin++) continue;|}' "$out/sub/parts/part1_raygen/camera_ray.c"
grep -q 'spin++' "$out/sub/parts/part1_raygen/camera_ray.c" || fail "could not make camera_generate_ray spin"
rm -rf "$out/tmp9" && mkdir -p "$out/tmp9" && chmod 711 "$out/tmp9"
TMPDIR=$PWD/$out/tmp9 bin/grade --submission "$out/sub" --parts 1 --seed 1 --out "$out/stopped" >"$out/stopped.log" 2>&1 &
grader=$!
# The processes whose command line names the grading's TMPDIR and $1 (the stages run from its
# sandbox folder, and the grader's own compilers write their temporary files there).
in_tmp9() {
    for p in /proc/[0-9]*; do
        { tr '\0' ' ' <"$p/cmdline" | grep "$PWD/$out/tmp9/" | grep -q -- "$1" && echo "${p#/proc/}"; } 2>/dev/null
    done
    return 0
}
waited=0
while [ -z "$(in_tmp9 subject-part1)" ] && [ "$waited" -lt 300 ] && kill -0 "$grader" 2>/dev/null; do
    sleep 1; waited=$((waited + 1))
done
[ -n "$(in_tmp9 subject-part1)" ] || { kill "$grader" 2>/dev/null; fail "the spinning part 1 never ran in $out/tmp9 (see $out/stopped.log)"; }
kill -TERM "$grader"
status=0
wait "$grader" || status=$?
[ "$status" = 143 ] || fail "a grading stopped by SIGTERM exited with $status, not 143 (see $out/stopped.log)"
left=$(in_tmp9 /)
[ -z "$left" ] || { kill -9 $left 2>/dev/null; fail "processes of a stopped grading outlived it: $left"; }
[ -z "$(ls -A "$out/tmp9")" ] || fail "a grading stopped by SIGTERM left $(ls -A "$out/tmp9") in its TMPDIR"
echo "  a grading stopped by SIGTERM while student code ran: exit 143, no process and no folder left"
echo "test-grader-process: passed"
