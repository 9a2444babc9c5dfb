#!/bin/bash
# Test machinery: the Gradescope autograder bundle end to end (make test-autograder, after make
# release). Unzips release/autograder.zip into a temporary root's source/ and runs its setup.sh (as
# Gradescope builds its image), then, for each case, makes Gradescope's layout (source/,
# submission/, results/) and runs run_autograder as root, checking results.json against a JSON
# Schema of Gradescope's format (gradescope_results.schema.json, with Debian's python3-jsonschema,
# installed here when missing) and the points each part got:
#   solution     the course's parts, one folder down (a zipped repository): full marks on every part
#   stubbed      the student release's parts: zero on every part, the grader finishing
#   mutants      a few of course/mutants: points lost on their own part, full marks on another
#   adversaries  course/autograder/adversarial/*.c (each replaces one part file; its header names
#                the part, the base ("stub": the part as released, or "solution") and the points it
#                should get: "expect: unit=0|full|lost images=0|full|lost"), graded on their part
#                and one other, which must keep full marks ("other: none": their own part only);
#                "present: TEXT" / "absent: TEXT" lines say what results.json must (not) hold,
#                "absent-files: PATH..." what must not exist afterwards, "timeout: S" the
#                autograder's limit (AUTOGRADER_TIMEOUT); a line "/* === FILE parts/... === */"
#                starts another file of the submission (two files of a part, or a name of its own);
#                no results.json may hold a line of a hidden scene
#   no-parts, linked-part, timeout   run_autograder's own fallbacks: an upload without parts/, a
#                part folder that is a symbolic link to the solution, a grader out of time
#   make-function-name, compile-private-tmp   the build stage: a file named like a make function is
#                refused; a file planted in the shared /tmp is out of the compile's view
# Afterwards no file of the sandbox's user may be left in /tmp, /var/tmp or /dev/shm.
# Settings: AUTOGRADER_TEST_JOBS (2) cases at once; AUTOGRADER_TEST_SEED (12345) the grader's seed
# (fixed: a correct part fails a case about once in a thousand seeds); AUTOGRADER_TEST_ONLY (a
# regular expression of case names); AUTOGRADER_TEST_KEEP=1 keeps the temporary root.
set -u
cd "$(dirname "$0")/../.." || exit 2
repo=$PWD
JOBS=${AUTOGRADER_TEST_JOBS:-2}
SEED=${AUTOGRADER_TEST_SEED:-12345}
ONLY=${AUTOGRADER_TEST_ONLY:-.}
SCHEMA=$repo/course/autograder/gradescope_results.schema.json
ISOLATION_PART=3  # the other part each mutant and adversary is graded on (the quickest to grade)
start=$(date +%s)

say() { echo "test-autograder: $*"; }
. tests/common/need.sh
need jq jq test-autograder  # reads results.json as a student reads it (expect_text)
[ -s release/autograder.zip ] || { say "FAILED: release/autograder.zip missing (run make release)"; exit 1; }
if [ "$(id -u)" != 0 ]; then
    say "note: not root: run_autograder cannot run student code as another user; results may differ from Gradescope's"
fi

# The validator: Debian's python3-jsonschema for Debian's python3.
PY=/usr/bin/python3
[ -x "$PY" ] || PY=$(command -v python3)
if [ -z "$PY" ]; then say "SKIPPED: no python3 to read results.json"; exit 0; fi
if ! "$PY" -c 'import jsonschema' 2>/dev/null; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
        say "installing python3-jsonschema (Debian's JSON Schema validator)"
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-jsonschema >/dev/null 2>&1 ||
            { apt-get update -qq >/dev/null 2>&1 &&
              DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-jsonschema >/dev/null 2>&1; }
    fi
fi
"$PY" -c 'import jsonschema' 2>/dev/null && schema_ok=1 ||
    { schema_ok=0; say "note: results.json is NOT checked against the schema: python3-jsonschema could not be installed"; }

tmp=$(mktemp -d /tmp/pathlab-autograder-test.XXXXXX) || exit 2
chmod 755 "$tmp"  # like /autograder: the sandbox's user reaches the scenes the grader renders
cleanup() { if [ "${AUTOGRADER_TEST_KEEP:-0}" = 1 ]; then say "kept $tmp"; else rm -rf "$tmp"; fi; }
trap cleanup EXIT
trap 'exit 130' INT TERM

# ---- the image: the bundle unzipped into source/ and set up as Gradescope does ------------------
src=$tmp/image/source
mkdir -p "$src" && unzip -q release/autograder.zip -d "$src" || { say "FAILED: cannot unzip the bundle"; exit 1; }
t0=$(date +%s)
if ! (cd "$src" && bash ./setup.sh) >"$tmp/setup.log" 2>&1; then
    say "FAILED: setup.sh failed:"; tail -n 20 "$tmp/setup.log"; exit 1
fi
say "setup.sh: $(( $(date +%s) - t0 )) s"

# ---- one case: a Gradescope root with source/ (the image's), submission/, results/ ---------------
# new_root NAME: prints the root's path; the submission folder is empty.
new_root() {
    r=$tmp/cases/$1
    mkdir -p "$r/submission" "$r/results" && ln -s "$src" "$r/source" && echo "$r"
}

# grade NAME PARTS [ENV...]: runs run_autograder (the bundle's copy, as Gradescope does) in NAME's
# root, on PARTS; its output goes to the root's run.log.
grade() {
    name=$1 parts=$2; shift 2
    r=$tmp/cases/$name
    t=$(date +%s)
    env AUTOGRADER_ROOT="$r" AUTOGRADER_PARTS="$parts" AUTOGRADER_SEED="$SEED" "$@" \
        bash "$src/run_autograder" >"$r/run.log" 2>&1
    echo "$?" >"$r/status"
    echo $(( $(date +%s) - t )) >"$r/seconds"
}

# The solution's parts with FILE replaced by REPLACEMENT (an adversary) or PATCH applied (a mutant).
solution_parts() { cp -a "$repo/parts" "$1/"; }

# ---- checks of one case's results ------------------------------------------------------------
# verdict NAME OK DETAIL: records the case's verdict line.
verdict() {
    r=$tmp/cases/$1
    printf '%s\t%s\t%s\t%s\n' "$2" "$1" "$(cat "$r/seconds" 2>/dev/null || echo -)" "$3" >"$r/verdict"
}

# read_results NAME: sets parsed (results.py's lines), problems (schema, exit status, grader output).
read_results() {
    r=$tmp/cases/$1
    problems=
    [ "$(cat "$r/status")" = 0 ] || problems="$problems run_autograder exited $(cat "$r/status");"
    if [ ! -s "$r/results/results.json" ]; then
        problems="$problems no results.json;"; parsed=; return
    fi
    parsed=$("$PY" "$repo/course/autograder/results.py" "$SCHEMA" "$r/results/results.json" 2>&1)
    case "$(echo "$parsed" | sed -n 's/^schema: //p')" in
        valid) ;;
        skipped*) [ "$schema_ok" = 1 ] && problems="$problems schema check skipped;" ;;
        *) problems="$problems results.json $(echo "$parsed" | sed -n 's/^schema: //p');" ;;
    esac
    ls -A "$r/results" | grep -vqx results.json && problems="$problems other files in results/: $(ls -A "$r/results" | tr '\n' ' ');"
}

# part_line N: "UNIT UNIT_MAX IMAGES IMAGES_MAX TESTS" of part N, or nothing.
part_line() { echo "$parsed" | awk -v n="$1" '$1 == "part" && $2 == n { print $3, $4, $5, $6, $7 }'; }
graded_by_grader() { echo "$parsed" | grep -q '^output pathlab grader'; }

# expect_part N UNIT IMAGES: UNIT and IMAGES are "full", "0", "lost" (below full) or "any".
expect_part() {
    line=$(part_line "$1")
    if [ -z "$line" ]; then problems="$problems part $1 not graded;"; return; fi
    set -- "$1" "$2" "$3" $line
    check_value "$1" "unit tests" "$2" "$4" "$5"
    check_value "$1" "images" "$3" "$6" "$7"
    summary="$summary part $1: unit $4/$5, images $6/$7;"
}
check_value() {  # part what expected got max
    case "$3" in
        full) awk -v g="$4" -v m="$5" 'BEGIN { exit !(g == m) }' ;;
        0) awk -v g="$4" 'BEGIN { exit !(g == 0) }' ;;
        lost) awk -v g="$4" -v m="$5" 'BEGIN { exit !(g < m) }' ;;
        *) true ;;
    esac || problems="$problems part $1 $2 $4/$5, expected $3;"
}
# lost_part N: the part's total is below its maximum.
expect_lost() {
    line=$(part_line "$1")
    [ -n "$line" ] || { problems="$problems part $1 not graded;"; return; }
    set -- $line
    awk -v a="$1" -v b="$3" -v m="$2" -v n="$4" 'BEGIN { exit !(a + b < m + n) }' ||
        problems="$problems its part kept full marks ($1 + $3);"
    summary="$summary own part $(awk -v a="$1" -v b="$3" 'BEGIN { print a + b }')/$(awk -v m="$2" -v n="$4" 'BEGIN { print m + n }');"
}
finish() {
    if [ -z "$problems" ]; then verdict "$1" PASS "${summary# }"; else verdict "$1" FAIL "${problems# }${summary:+ (${summary# })}"; fi
}

# expect_text ADVERSARY RESULTS: the adversary's "present: TEXT" lines must be in results.json as a
# student reads it (its outputs with Markdown's backslash escapes undone), its "absent: TEXT" lines
# and every hidden scene's distinctive lines in neither that nor the raw file, and none of its
# "absent-files: PATH..." may exist.
expect_text() {
    tp=$(dirname "$(dirname "$2")")/text-problems
    read=$(dirname "$(dirname "$2")")/results-read.txt
    { jq -r '.output // empty, (.tests[]? | .name, .output)' "$2" 2>/dev/null | sed 's/\\\([[:punct:]]\)/\1/g'; cat "$2"; } >"$read"
    sed -n 's/^ \* present: *//p' "$1" | while IFS= read -r t; do
        grep -qF -- "$t" "$read" || echo "results.json lacks \"$t\";"; done >"$tp"
    sed -n 's/^ \* absent: *//p' "$1" | while IFS= read -r t; do
        grep -qF -- "$t" "$read" && echo "results.json holds \"$t\";"; done >>"$tp"
    for scene in "$repo"/grading/hidden/*.dae; do
        grep -E '^ *<(source|float_array|p|triangles|light|node)[ >]' "$scene" | head -n 20 | while IFS= read -r t; do
            grep -qF -- "$t" "$read" && echo "results.json holds a line of $(basename "$scene");"; done
    done | sort -u >>"$tp"
    for p in $(sed -n 's/^ \* absent-files: *//p' "$1"); do
        [ ! -e "$p" ] || { echo "$p exists: student code wrote outside its sandbox;"; rm -rf "$p"; }
    done >>"$tp"
    problems="$problems$(tr '\n' ' ' <"$tp")"
    rm -f "$tp" "$read"
}

# ---- the cases -------------------------------------------------------------------------------

case_solution() {
    r=$(new_root solution); mkdir -p "$r/submission/pathlab-main"; solution_parts "$r/submission/pathlab-main"
    grade solution 1,2,3,4,5
    read_results solution; summary=
    graded_by_grader || problems="$problems not the grader's results;"
    for p in 1 2 3 4 5; do expect_part "$p" full full; done
    finish solution
}

case_stubbed() {
    r=$(new_root stubbed); cp -a "$repo/release/student/parts" "$r/submission/"
    grade stubbed 1,2,3,4,5
    read_results stubbed; summary=
    graded_by_grader || problems="$problems not the grader's results (did it crash?);"
    for p in 1 2 3 4 5; do expect_part "$p" 0 0; done
    finish stubbed
}

# mutant PATCH: the part folders themselves at the top of the upload (no parts/ above them).
case_mutant() {
    name=mutant-$(basename "$1" .patch); part=$(basename "$1" | sed -n 's/^part\([0-9]\)-.*/\1/p')
    other=$ISOLATION_PART; [ "$part" = "$ISOLATION_PART" ] && other=5
    r=$(new_root "$name"); solution_parts "$r"
    if ! patch -s -p1 -d "$r" <"$1"; then problems=" the patch does not apply;"; summary=; finish "$name"; return; fi
    mv "$r/parts"/* "$r/submission/" && rmdir "$r/parts"
    grade "$name" "$part,$other"
    read_results "$name"; summary=
    graded_by_grader || problems="$problems not the grader's results;"
    expect_lost "$part"
    expect_part "$other" full full
    finish "$name"
}

case_adversary() {
    f=$1 name=adv-$(basename "$1" .c)
    part=$(sed -n 's/^ \* part: *\([1-5]\).*/\1/p' "$f")
    file=$(sed -n 's/^ \* replaces: *\([^ ]*\).*/\1/p' "$f")
    unit=$(sed -n 's/^ \* expect:.*unit=\([a-z0-9]*\).*/\1/p' "$f")
    images=$(sed -n 's/^ \* expect:.*images=\([a-z0-9]*\).*/\1/p' "$f")
    other=$ISOLATION_PART; [ "$part" = "$ISOLATION_PART" ] && other=5
    grep -q '^ \* other: *none' "$f" && other=  # the newer adversaries: their own part only (time)
    base=$(sed -n 's/^ \* base: *\([a-z]*\).*/\1/p' "$f")
    r=$(new_root "$name"); solution_parts "$r/submission"
    if [ -z "$part" ] || [ -z "$unit" ] || [ -z "$images" ] || [ ! -f "$repo/$file" ]; then
        problems=" its header lacks part:, replaces: (an existing part file) or expect: unit=.. images=..;"; summary=
        finish "$name"; return
    fi
    # base: stub -- the attacked part as released (every task a stub), so that it earns nothing
    # but what the attack could win; base: solution -- the course's part.
    folder=$(echo "$file" | cut -d/ -f1-2)
    if [ "$base" = stub ]; then rm -rf "$r/submission/$folder" && cp -a "$repo/release/student/$folder" "$r/submission/$folder"; fi
    # The adversary's own file, and the files after its "/* === FILE path === */" lines (an attack
    # that needs two files of the part, or a file of a name of its own), each where its line says.
    awk -v first="$r/submission/$file" -v top="$r/submission/" '
        BEGIN { out = first }
        /^\/\* === FILE .* === \*\/$/ { close(out); out = top substr($0, 13, length($0) - 19); next }
        { print > out }' "$f"
    limit=$(sed -n 's/^ \* timeout: *\([0-9][0-9]*\).*/\1/p' "$f")
    grade "$name" "$part${other:+,$other}" ${limit:+AUTOGRADER_TIMEOUT=$limit}
    read_results "$name"; summary=
    graded_by_grader || problems="$problems not the grader's results;"
    grep -q '"forged"' "$r/results/results.json" && problems="$problems the forged results.json is in place;"
    expect_part "$part" "$unit" "$images"
    [ -z "$other" ] || expect_part "$other" full full
    expect_text "$f" "$r/results/results.json"
    finish "$name"
}

# run_autograder's own fallbacks (no grading, or almost none).
case_no_parts() {
    r=$(new_root no-parts); mkdir -p "$r/submission/src"; echo 'int main(void) { return 0; }' >"$r/submission/src/main.c"
    grade no-parts 1,2,3,4,5
    read_results no-parts; summary=
    graded_by_grader && problems="$problems graded an upload without parts/;"
    echo "$parsed" | grep -q '^total 0$' || problems="$problems score not 0;"
    grep -q 'No parts/ folder' "$r/results/results.json" || problems="$problems no explanation;"
    [ "$(echo "$parsed" | grep -c '^part ')" = 5 ] || problems="$problems not a zero per part;"
    finish no-parts
}

case_linked_part() {  # a part folder that is a link to the course's solution is not followed
    r=$(new_root linked-part); solution_parts "$r/submission"
    rm -rf "$r/submission/parts/part5_adaptive"
    ln -s "$src/parts/part5_adaptive" "$r/submission/parts/part5_adaptive"
    grade linked-part 5
    read_results linked-part; summary=
    expect_part 5 0 0
    finish linked-part
}

case_timeout() {  # the grader out of time: the fallback, valid, score 0
    r=$(new_root timeout); solution_parts "$r/submission"
    grade timeout 2 AUTOGRADER_TIMEOUT=3
    read_results timeout; summary=
    echo "$parsed" | grep -q '^total 0$' || problems="$problems score not 0;"
    grep -q 'ran out of time' "$r/results/results.json" || problems="$problems no explanation;"
    finish timeout
}

# Attacks on the build stage (issue 29's first class). A file *named* like a make function ran a
# shell when the build went through make: with part 1 solved and parts 2..5 stubs, that shell
# planted the course's objects and the whole course scored full marks. Now a name outside
# [a-z0-9_]+.c/.h is refused before anything reads the part, and a stubbed part earns nothing.
case_make_function_name() {
    r=$(new_root make-function-name); mkdir -p "$r/submission/parts"
    cp -a "$repo/parts/part1_raygen" "$r/submission/parts/"
    cp -a "$repo/release/student/parts/part2_bvh" "$r/submission/parts/"
    : >"$r/submission/parts/part1_raygen/x\$(shell cp -r ..\$(subst ,,)build pathlab-stash).c"
    grade make-function-name 1,2
    read_results make-function-name; summary=
    graded_by_grader || problems="$problems not the grader's results;"
    expect_part 1 0 0
    expect_part 2 0 0
    grep -q 'characters other than a-z, 0-9 and' "$r/results/results.json" || problems="$problems no refusal naming the rule;"
    grep -q 'pathlab-stash' "$r/results/results.json" && problems="$problems the refusal quotes the name;"
    finish make-function-name
}

# The compile sees the machine read-only, with a /tmp of its own: a file planted in the shared /tmp,
# readable by everyone, is not there for an #include (a build stage that could read it could also
# have written there for a later stage to find).
case_compile_private_tmp() {
    r=$(new_root compile-private-tmp); solution_parts "$r/submission"
    planted=$(mktemp /tmp/pathlab-planted.XXXXXX) && chmod 644 "$planted" && echo 'int pl_planted;' >"$planted"
    printf '#include "%s"\n' "$planted" >>"$r/submission/parts/part5_adaptive/adaptive.c"
    grade compile-private-tmp 5
    rm -f "$planted"
    read_results compile-private-tmp; summary=
    if [ -n "$(awk '$1 == "part" && $2 == 5' <<<"$parsed")" ] && grep -q 'No such file or directory' "$r/results/results.json"; then
        expect_part 5 0 0
    elif grep -q 'no PID or mount namespace' "$r/run.log"; then
        summary="(this machine gives no mount namespace: the shared /tmp is in view, as the staff log says)"
    else
        problems="$problems the compile read a file planted in the shared /tmp;"
    fi
    finish compile-private-tmp
}

# The cases, longest first so that JOBS of them keep the cores busy to the end.
{
    echo "case_adversary $repo/course/autograder/adversarial/loops-forever.c"
    echo case_solution
    echo case_stubbed
    for m in part1-camera-y-not-flipped part3-bsdf-without-pi part5-standard-deviation-not-error; do
        echo "case_mutant $repo/course/mutants/$m.patch"
    done
    for f in "$repo"/course/autograder/adversarial/*.c; do
        [ "$(basename "$f")" = loops-forever.c ] || echo "case_adversary $f"
    done
    echo case_no_parts
    echo case_linked_part
    echo case_make_function_name
    echo case_compile_private_tmp
    echo case_timeout
} >"$tmp/cases.txt"

mkdir -p "$tmp/cases"
running=0
while read -r fn arg; do
    label=${arg:+$(basename "$arg")}
    echo "$fn ${label:-}" | grep -qE -- "$ONLY" || continue
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do sleep 1; done
    say "start $fn ${label:-}"
    $fn $arg &
done <"$tmp/cases.txt"
wait

# ---- the table ---------------------------------------------------------------------------------
echo
printf '%-5s %-48s %5s  %s\n' "" "case" "s" "points (or what went wrong)"
failed=0 passed=0
for v in "$tmp"/cases/*/verdict; do
    [ -f "$v" ] || continue  # no case matched AUTOGRADER_TEST_ONLY
    IFS=$'\t' read -r ok name secs detail <"$v"
    printf '%-5s %-48s %5s  %s\n' "$ok" "$name" "$secs" "$detail"
    if [ "$ok" = PASS ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done
for d in "$tmp"/cases/*/; do
    [ -d "$d" ] || continue
    [ -f "$d/verdict" ] || { echo "FAIL  $(basename "$d"): the case did not finish"; failed=$((failed + 1)); }
done
# Nothing outside the sandbox touched: the system() adversary's target, had it run, and nothing the
# sandbox's user made in the shared temporary folders outlives the gradings.
[ -e /tmp/stolen ] && { echo "FAIL  /tmp/stolen exists: student code ran a shell command"; failed=$((failed + 1)); }
left=$(find /tmp /var/tmp /dev/shm -xdev -user nobody 2>/dev/null | head -n 5)
[ -z "$left" ] || { echo "FAIL  files of the sandbox's user outlived the gradings: $left"; failed=$((failed + 1)); }
echo
[ $((passed + failed)) -gt 0 ] || { say "FAILED: no case matched AUTOGRADER_TEST_ONLY='$ONLY'"; exit 1; }
say "$passed passed, $failed failed, $(( $(date +%s) - start )) s (seed $SEED, $JOBS at once)"
if [ "$failed" != 0 ]; then
    say "logs: each case's run.log and results/ under $tmp/cases (kept)"
    AUTOGRADER_TEST_KEEP=1
    exit 1
fi
