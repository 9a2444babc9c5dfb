# The checks of release-check that build and run the student tree, sourced by check: it builds
# warning-free (b), every mix of solved and stubbed parts links (m), its suites fail only with "not
# implemented" (c), trees solved in order pass (o), the stubbed renderer draws magenta (d). Builds
# happen in copies under $LOGS, never in release/student.

# make in the tree $1, free of this make's flags and variables (SAN=1, say), in bounded time.
tree_make() {
    (cd "$1" && shift && unset MAKEFLAGS MFLAGS MAKELEVEL && \
        timeout "${RELEASE_TIMEOUT:-300}" make --no-print-directory "$@")
}

# What a crash looks like in make's, cmocka's, the sanitizers' or the shell's words.
CRASH='Segmentation fault|Aborted|core dumped|Bus error|Illegal instruction|Floating point exception|Killed|Sanitizer|runtime error:|Test failed with exception|Terminated'

# The cmocka tests of a log that failed with no "not implemented" line between RUN and FAILED.
failed_without_todo() {
    awk '/^\[ RUN      \]/ { name = $NF; todo = 0 }
         /not implemented/ { todo = 1 }
         /^\[  FAILED  \]/ && name != "" && $NF == name { if (!todo) printf " %s", name; name = "" }
         /^\[       OK \]/ { name = "" }' "$1"
}

# Runs suite $2 in tree $1 into log $3; sets $rc.
run_suite() {
    # A failed cmocka assert jumps out of the test before its cleanup, so on stubs the leak checker
    # would report every test's scene: leaks are the solution tests' concern (make test SAN=1).
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
        tree_make "$1" -j"${RELEASE_JOBS:-2}" WERROR=1 SAN="${RELEASE_SAN:-1}" "test-$2" >"$3" 2>&1
    rc=$?
}

# Why the stubbed suite in log $1 (exit status $rc) is unsound, or nothing. With $2, the task
# functions that must each be reported "not implemented".
suite_problems() {
    problems=
    [ "$rc" = 0 ] && problems="it passed with its tasks stubbed"
    [ "$rc" = 124 ] && problems="it ran out of time (${RELEASE_TIMEOUT:-300} s)"
    crash=$(grep -E "$CRASH" "$1" | head -n 3)
    [ -n "$crash" ] && problems="${problems:+$problems; }it crashed: $crash"
    # make reports the binary's exit status as "Error N"; above 127 means a signal.
    status=$(sed -n 's/.*\] Error \([0-9][0-9]*\)$/\1/p' "$1" | tail -n 1)
    [ -n "$status" ] && [ "$status" -gt 127 ] && problems="${problems:+$problems; }exit status $status"
    missing=
    for fn in ${2:-}; do
        grep 'not implemented' "$1" | grep -qw "$fn" || missing="$missing $fn"
    done
    [ -n "$missing" ] && problems="${problems:+$problems; }no \"not implemented\" for:$missing"
    wrong=$(failed_without_todo "$1")
    [ -n "$wrong" ] && problems="${problems:+$problems; }failed without saying \"not implemented\":$wrong"
    echo "$problems"
}

suites_with_tests() {
    for s in framework $(printf 'part%s ' $COURSE_PARTS); do
        ls "$1/tests/$s/"*.c >/dev/null 2>&1 && echo "$s"
    done
}

check_build() {
    targets=all
    for s in $(suites_with_tests "$TREE"); do targets="$targets bin/test-$s"; done
    if tree_make "$TREE" -k -j"${RELEASE_JOBS:-2}" WERROR=1 SAN=0 $targets >"$LOGS/build.log" 2>&1; then
        pass "(b) the student tree builds with WERROR=1 ($targets)"
    else
        fail "(b) the student tree builds with WERROR=1 ($targets)"
        show "$LOGS/build.log" 30
    fi
}

# Every mix of solved and stubbed parts links warning-free with WERROR=1 (link-time optimisation
# warns only when it sees the parts together: a solved part 3 beside a stubbed part 1 once warned
# "may be used uninitialized"). The 2^n mixes of the course's n parts (32 for parts 1-5) are visited
# in Gray-code order, so each step swaps one part's folder, recompiles it and links bin/pathtracer
# again, in one scratch copy of the built tree. RELEASE_MIX_PARTS narrows the parts mixed (the
# others stay stubbed): a check of a longer course whose first parts' mixes another run proved.
check_combinations() {
    tree="$LOGS/mixes"
    what="(m) every mix of solved and stubbed parts links bin/pathtracer warning-free with WERROR=1"
    rm -rf "$tree" && cp -a "$TREE" "$tree" || { fail "$what: cannot copy $TREE"; return; }
    local course=(${RELEASE_MIX_PARTS:-$COURSE_PARTS})
    [ -z "${RELEASE_MIX_PARTS:-}" ] || what="$what, of parts ${RELEASE_MIX_PARTS} (RELEASE_MIX_PARTS; the others stubbed)"
    mixes=$(((1 << ${#course[@]}) - 1))
    prev=0 bad=
    for i in $(seq 1 $mixes); do
        mask=$((i ^ (i >> 1)))
        k=0; while [ $(((mask ^ prev) >> k)) != 1 ]; do k=$((k + 1)); done  # the part that changes
        part=$(cd parts && ls -d "part${course[k]}_"* 2>/dev/null | head -n 1)
        [ -n "$part" ] || continue
        if [ $(((mask >> k) & 1)) = 1 ]; then src="parts/$part"; else src="$TREE/parts/$part"; fi
        rm -rf "$tree/parts/$part" && cp -r "$src" "$tree/parts/$part" && touch "$tree/parts/$part"/*
        prev=$mask
        solved=""; for j in "${!course[@]}"; do [ $(((mask >> j) & 1)) = 1 ] && solved="$solved${course[j]}"; done
        tree_make "$tree" WERROR=1 SAN=0 all >"$LOGS/mix-$solved.log" 2>&1 || bad="$bad ${solved:-none}"
    done
    if [ -z "$bad" ]; then
        pass "$what ($mixes mixes beside the all-stubbed tree of (b))"
        rm -rf "$tree" "$LOGS"/mix-*.log
    else
        fail "$what: failed with parts solved:$bad (logs: $LOGS/mix-<solved parts>.log)"
    fi
}

# Every suite of the student tree as a student first sees it.
check_student_suites() {
    for s in $(suites_with_tests "$TREE"); do
        log="$LOGS/student-test-$s.log"
        run_suite "$TREE" "$s" "$log"
        if [ "$s" = framework ]; then
            if [ "$rc" = 0 ]; then
                pass "(c) student tree: make test-framework passes"
            else
                fail "(c) student tree: make test-framework passes (exit $rc)"
                show "$log"
            fi
            continue
        fi
        problems=$(suite_problems "$log")
        what="(c) student tree: make test-$s fails, every failure saying \"not implemented\", no crash"
        if [ -z "$problems" ]; then pass "$what"; else fail "$what: $problems"; show "$log"; fi
    done
}

# The tree with the course's parts up to N solved and the later ones stubbed: a student working
# through the parts in order. Part N's suite must pass there (a solved part is not held back by
# later stubs), and the next part's must fail saying "not implemented" for each of its tasks. Each
# tree is built once and runs only these two suites.
check_ordered() {
    n=$1 next=$(echo " $COURSE_PARTS " | sed -n "s/.* $1 \([0-9]\).*/\1/p")
    tree="$LOGS/solved-1-to-$n"
    if ! copy_tree "$tree" "$LOGS/files.txt" "$n" 2>"$tree.copy.log"; then
        fail "(o) parts 1..$n solved: the tree could not be made"
        show "$tree.copy.log"
        return
    fi
    ok=1
    if ls "tests/part$n/"*.c >/dev/null 2>&1; then
        log="$tree-test-part$n.log"
        run_suite "$tree" "part$n" "$log"
        what="(o) parts 1..$n solved, later parts stubbed: make test-part$n passes"
        if [ "$rc" = 0 ]; then
            pass "$what"
        else
            ok=0
            failed_tests=$(sed -n 's/^\[  FAILED  \] \([^ ]*\)$/\1/p' "$log" | sort -u | tr '\n' ' ')
            fail "$what (exit $rc; failed: ${failed_tests:-see log})"
            grep -m 5 'not implemented' "$log" | sed 's/^/      | /'
            show "$log" 10
        fi
    fi
    if [ -n "$next" ]; then
        fns=$(awk -v n="$next" '$1 == n {print $3}' "$LOGS/tasks.txt")
        what="(o) parts 1..$n solved, part $next stubbed: make test-part$next says \"not implemented\" for each task, no crash"
        if [ -z "$fns" ] || ! ls "tests/part$next/"*.c >/dev/null 2>&1; then
            fail "$what: no task banners in parts/part${next}_*/ or no tests in tests/part$next/"
            return
        fi
        log="$tree-test-part$next.log"
        run_suite "$tree" "part$next" "$log"
        problems=$(suite_problems "$log" "$fns")
        # A test that passes with its part stubbed cannot tell a stub from a solution: only a note,
        # since a suite may also test framework code its part relies on.
        passing=$(sed -n 's/^\[       OK \] //p' "$log" | tr '\n' ' ')
        [ -n "$passing" ] && echo "note  part $next: these pass with the part stubbed: $passing"
        if [ -z "$problems" ]; then
            pass "$what ($(echo $fns | wc -w) task functions)"
        else
            ok=0
            fail "$what: $problems"
            show "$log"
        fi
    fi
    [ -z "$next" ] && ! check_readme_tests "$tree" "$n" && ok=0
    [ "$ok" = 1 ] && rm -rf "$tree"
}

# The README's second command (its test command: the second line of its first sh block, without the
# comment), as a student runs it.
readme_test_command() {
    awk '/^```sh/ { inside = 1; next } /^```/ { if (inside) exit } inside { n++; if (n == 2) { sub(/#.*/, ""); print; exit } }' "$1/README.md"
}

# (p) In tree $1, where every part of the course is solved (up to part $2), the README's test command
# passes: what every student meets once done. (Before, a grader test edited grading/cases.json by the
# repository's layout, which the release writes again, and failed in every solved student tree.)
check_readme_tests() {
    cmd=$(readme_test_command "$1")
    what="(p) every part of the course solved (1..$2): the README's test command ('$cmd') passes"
    case "$cmd" in
        "make test"|"make test "*) ;;
        *) fail "$what: expected the README's second command to be make test, found '$cmd'"; return 1 ;;
    esac
    log="$1-readme-test.log"
    tree_make "$1" -j"${RELEASE_JOBS:-2}" ${cmd#make} >"$log" 2>&1
    rc=$?
    if [ "$rc" = 0 ]; then pass "$what"; return 0; fi
    failed_tests=$(sed -n 's/^\[  FAILED  \] \([^ ]*\)$/\1/p' "$log" | sort -u | tr '\n' ' ')
    fail "$what (exit $rc; failed: ${failed_tests:-see log})"
    show "$log" 15
    return 1
}

check_render() {
    scene=scenes/cornell_spheres.dae
    [ -f "$TREE/$scene" ] || scene=$(cd "$TREE" && ls scenes/*.dae 2>/dev/null | head -n 1)
    if [ -z "$scene" ]; then
        fail "(d) stubbed render: no scene in scenes/"
        return
    fi
    png=$(absolute "$LOGS/stub_render.png")
    log="$LOGS/render.log"
    (cd "$TREE" && timeout 120 bin/pathtracer -t 2 -r 64 48 -f "$png" "$scene") >"$log" 2>&1
    rc=$?
    what="(d) the stubbed renderer draws $scene magenta"
    if [ "$rc" != 0 ] || grep -qE "$CRASH" "$log"; then
        fail "$what: bin/pathtracer exited with $rc"
        show "$log"
        return
    fi
    if ! grep -q 'not implemented' "$log"; then
        fail "$what: it did not say which task is not implemented"
        show "$log"
        return
    fi
    stats=$("$stats_tool" stats "$png" 2>&1)
    fraction=$(echo "$stats" | sed -n 's/.*magenta fraction \([0-9.]*\)$/\1/p')
    if [ -n "$fraction" ] && awk -v f="$fraction" 'BEGIN { exit !(f >= 0.9) }'; then
        pass "$what ($stats)"
    else
        fail "$what: ${stats:-no image} (want a magenta fraction >= 0.9)"
    fi
}

