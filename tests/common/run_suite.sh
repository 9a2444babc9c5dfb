#!/bin/sh
# Test machinery: runs one suite for make test-<suite> and ends with one line that says how it went,
# naming every failed test in the suite's order, so that the last thing on screen is never another
# group's "[  PASSED  ]". Each failed test is listed with what it checks: the comment above its
# function in its source file (the failure's own message, above, says what went wrong). With
# LIST=1 it counts the tests listed instead.
#   tests/common/run_suite.sh NAME PROGRAM     (NAME: test-part3; exit status: the program's)
set -u
name=$1 exe=$2
out=$(mktemp) || exit 2
trap 'rm -f "$out" "$out.status"' EXIT
# The program's output goes to the screen as it comes (its stdout is line-buffered: filter.c) and
# to a file for the summary.
{ "$exe"; echo $? > "$out.status"; } 2>&1 | tee "$out"
status=$(cat "$out.status" 2>/dev/null || echo 2)
# cmocka names a failed test after it ran and again in its group's summary: keep the first of each.
failed=$(sed -n 's/^\[  FAILED  \] \(test_[A-Za-z0-9_]*\)$/\1/p' "$out" | awk '!seen[$0]++')
ran=$(grep -c '^\[ RUN      \] ' "$out")
if [ -n "${PL_TEST_LIST:-}" ] && [ "$PL_TEST_LIST" != 0 ]; then
    echo "$name: $(grep -c '^  test_' "$out") tests listed (none run)"
elif [ -z "$failed" ] && [ "$status" = 0 ]; then
    echo "$name: all $ran tests passed"
elif [ -z "$failed" ]; then
    echo "$name: FAILED with status $status after $ran tests, none of them failed on its own: the suite stopped (a crash?) or its checks at exit failed (see above)"
else
    echo "$name: $(echo "$failed" | wc -l | tr -d ' ') of $ran tests FAILED:"
    for t in $failed; do
        # The comment block just above "static void <test>(" in the suite's sources, on one line.
        why=$(awk -v fn="static void $t(" '
            index($0, fn) == 1 { sub(/ +$/, "", text); print text; exit }
            /^\/\*/ { text = ""; inside = 1 }
            inside { line = $0; gsub(/^ *\/?\*+\/? ?|\*\/ *$/, "", line); text = text (text == "" ? "" : " ") line;
                     if ($0 ~ /\*\//) inside = 0; next }
            !/^[[:space:]]*$/ { text = "" }' tests/*/*.c course/*/test_*.c 2>/dev/null | head -n 1)
        # What the test checks, said as such: its comment describes the test, not the cause of this failure.
        echo "  $t${why:+ (it checks: $why)}"
    done
fi
exit "$status"
