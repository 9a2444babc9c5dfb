# The checks of release-check that read the trees without building them, sourced by check: what the
# student tree, the bundle and the Classroom workflow hold, and the copying tools' own handling of
# odd names. Each check_* prints one PASS or FAIL line, lettered as check's header lists them.

check_banners() {
    if ! "$strip" --tasks parts/*/*.c >"$LOGS/tasks.txt" 2>"$LOGS/tasks.err"; then
        fail "(e) task banners agree with their solution regions, stubs, headers and handout sections"
        show "$LOGS/tasks.err"
        return
    fi
    problems=0
    # One banner per function across all files; each task lives in its part's folder and its
    # function is declared in that part's header.
    dups=$(awk '{print $2, $3}' "$LOGS/tasks.txt" | sort | uniq -d)
    if [ -n "$dups" ]; then
        echo "      task banners repeated in several files: $dups"
        problems=1
    fi
    while read -r part id fn where; do
        dir=$(dirname "${where%:*}")
        case "$dir" in
            parts/part${part}_*) ;;
            *) echo "      $where: banner of part $part outside parts/part${part}_*/"; problems=1 ;;
        esac
        if ! grep -qw "$fn" "$dir"/*.h 2>/dev/null; then
            echo "      $where: $fn() is not declared in $dir/*.h"
            problems=1
        fi
        # The banner sends the student to the handout's section of the same number.
        if ! grep -q "^#.*$(echo "$id" | sed 's/\./\\./g')" "handout/part$part.md" 2>/dev/null || ! grep -qw "$fn" "handout/part$part.md"; then
            echo "      $where: handout/part$part.md has no heading for task $id or never names $fn"
            problems=1
        fi
    done <"$LOGS/tasks.txt"
    if [ "$problems" = 0 ]; then
        pass "(e) task banners agree with their solution regions, stubs, headers and handout sections ($(wc -l <"$LOGS/tasks.txt") task functions)"
    else
        fail "(e) task banners agree with their solution regions, stubs, headers and handout sections"
    fi
}

# Nothing of the instructor's machine or tooling: no build outputs, CI or course/.
check_contents() {
    leftovers=$(cd "$OUT" && find . -path ./build -o -path ./bin -o -path ./out -o -path ./release -o \
        -name grade-out -o -name '*.o' -o -path ./.ci -o -path ./course |
        sed 's|^\./||' | tr '\n' ' ')
    if [ -n "$leftovers" ]; then
        fail "(i) $OUT holds no build outputs, CI or course/ (instructor-only): found $leftovers"
    elif [ ! -s "$OUT/VERSION" ]; then
        fail "(i) $OUT has a VERSION stamp"
    else
        pass "(i) $OUT holds no build outputs, CI or course/; VERSION: $(cat "$OUT/VERSION")"
    fi
}

# The parts the cases files of tree $1 list (read by the grader's own loader, bin/release_points;
# $2: the hidden file's path, or /nonexistent for the student tree) against the course's: the
# parts of the repository's files that COURSE_PARTS names, no more and no fewer. Prints the problem
# ("; ...") or nothing.
cases_parts_problem() {
    local got want
    got=$("$points_tool" "$1/grading/cases.json" "$1/$2" 2>&1 | awk '{ printf "%s ", $1 }')
    want=$("$points_tool" grading/cases.json "$2" 2>&1 |
        awk -v parts=" $COURSE_PARTS " 'index(parts, " " $1 " ") { printf "%s ", $1 }')
    [ "$got" = "$want" ] || printf '; its cases files list parts %s(the course'"'"'s: %s)' "${got:-none }" "$want"
}

# Nothing hidden in the student tree: no grading/hidden or reference_images/hidden, no case marked
# hidden in any JSON file (the grader's own case loader, bin/release_points, counts no hidden
# points in its grading/cases.json), and no file with the bytes of a hidden file, under any name.
check_hidden() {
    what="(j) $OUT holds no hidden case, hidden scene or hidden reference, and no case of a part the course left out"
    problems=
    for d in grading/hidden reference_images/hidden; do
        [ -e "$OUT/$d" ] && problems="$problems; $d exists"
    done
    problems="$problems$(cases_parts_problem "$OUT" /nonexistent)"
    marked=$(grep -rlE '"visibility"[[:space:]]*:[[:space:]]*"hidden"' "$OUT" 2>/dev/null | sed "s|^$OUT/||" | tr '\n' ' ')
    [ -n "$marked" ] && problems="$problems; cases marked hidden in: $marked"
    if [ -x "$points_tool" ]; then
        if "$points_tool" "$OUT/grading/cases.json" /nonexistent >"$LOGS/student-points.txt" 2>&1; then
            hidden_points=$(awk '{ s += $4 } END { print s + 0 }' "$LOGS/student-points.txt")
            [ "$hidden_points" = 0 ] || problems="$problems; its grading/cases.json gives hidden cases $hidden_points points"
        else
            problems="$problems; its grading/cases.json does not load: $(head -c 300 "$LOGS/student-points.txt")"
        fi
    fi
    # The same bytes under another name: a hidden reference or scene copied somewhere by mistake.
    # A public case's own reference may look the same as a hidden one (a preview of the same image:
    # bunny_normals and bunny_normals_leaf1 differ in work per ray, not in pixels): that is public.
    find grading/hidden reference_images/hidden -type f -exec sha256sum {} + 2>/dev/null | sort >"$LOGS/hidden.sha"
    (cd "$OUT" && find . -type f -exec sha256sum {} +) | sed 's| \./| |' | sort >"$LOGS/student.sha"
    copies=
    while read -r f h; do
        case "$f" in
            reference_images/part[1-5]/*) cmp -s "$OUT/$f" "$f" && [ -n "$(git ls-files -- "$f")" ] &&
                { echo "note  $f looks the same as $h: a public case's reference, shipped as such"; continue; } ;;
        esac
        copies="$copies $f (= $h)"
    done < <(awk 'NR == FNR { h[$1] = $2; next } ($1 in h) { print $2, h[$1] }' "$LOGS/hidden.sha" "$LOGS/student.sha")
    [ -n "$copies" ] && problems="$problems; copies of hidden files:$copies"
    n=$(wc -l <"$LOGS/hidden.sha")
    [ "$n" -gt 0 ] || problems="$problems; the repository has no hidden files to look for"
    if [ -z "$problems" ]; then pass "$what ($n hidden files looked for by content)"; else fail "$what:${problems#;}"; fi
}

# The autograder bundle (release/autograder.zip, unzipped into $LOGS/bundle as Gradescope does):
# setup.sh and run_autograder at its top and executable; the solutions (every parts/ file the same
# as the repository's, solution markers included); every grading case and reference, hidden ones
# included, byte for byte; nothing of a part the course left out; no build outputs, .git or out/.
check_bundle() {
    what="(k) release/autograder.zip holds setup.sh and run_autograder (executable), the solutions, every case and reference of the course's parts, hidden ones included"
    zip=release/autograder.zip
    [ -s "$zip" ] || { fail "$what: $zip missing"; return; }
    dir=$LOGS/bundle
    rm -rf "$dir" && mkdir -p "$dir"
    if command -v unzip >/dev/null; then
        unzip -q "$zip" -d "$dir" 2>"$LOGS/unzip.log"
    else
        python3 -c 'import sys, zipfile, os
z = zipfile.ZipFile(sys.argv[1])
for i in z.infolist():
    p = z.extract(i, sys.argv[2]); m = i.external_attr >> 16
    if m: os.chmod(p, m & 0o777)' "$zip" "$dir" 2>"$LOGS/unzip.log"
    fi || { fail "$what: cannot unzip $zip"; show "$LOGS/unzip.log"; return; }
    problems=
    for f in setup.sh run_autograder; do
        [ -f "$dir/$f" ] && [ -x "$dir/$f" ] || problems="$problems; $f missing or not executable"
    done
    n=0
    while IFS= read -r f; do
        if part_left_out "$f"; then
            [ -e "$dir/$f" ] && problems="$problems; $f is of a part the course left out (COURSE_PARTS=\"$COURSE_PARTS\")"
            continue
        fi
        n=$((n + 1))
        cases_file "$f" && continue  # the course's parts only: checked below
        cmp -s "$f" "$dir/$f" || problems="$problems; $f missing or different"
    done < <(find parts grading reference_images -type f | sort)
    problems="$problems$(cases_parts_problem "$dir" grading/hidden/cases.json)"
    for d in "$dir"/tests/part*; do
        [ -d "$d" ] && part_left_out "tests/${d##*/}/x" && problems="$problems; tests/${d##*/} is of a part the course left out"
    done
    grep -qF "$MARK_BEGIN" "$dir"/parts/*/*.c 2>/dev/null || problems="$problems; no solution in its parts/"
    [ -s "$dir/grading/hidden/cases.json" ] && [ -n "$(find "$dir/reference_images/hidden" -name '*.exr' 2>/dev/null)" ] ||
        problems="$problems; no hidden cases or references"
    junk=$(cd "$dir" && find . -name .git -o -path ./out -o -path ./build -o -path ./bin -o -path ./release -o \
        -name grade-out -o -name '*.o' | tr '\n' ' ')
    [ -n "$junk" ] && problems="$problems; build outputs or .git: $junk"
    [ -s "$dir/points.txt" ] || problems="$problems; no points.txt"
    if [ -z "$problems" ]; then pass "$what ($n files of parts/, grading/, reference_images/ identical)"
    else fail "$what:${problems#;}"; fi
}

# The student's GitHub Classroom workflow: a step per part with the part's public points.
check_classroom() {
    yml=$OUT/.github/workflows/classroom.yml
    what="(l) $OUT/.github/workflows/classroom.yml: one autograding step per part, with its public points"
    [ -s "$yml" ] || { fail "$what: missing"; return; }
    problems=
    while read -r part unit public hidden; do
        max=$(awk -v a="$unit" -v b="$public" 'BEGIN { printf "%g", a + b }')
        awk -v p="$part" -v m="$max" '
            $0 ~ "command: make grade PARTS=" p "$" { seen = 1 }
            seen && /max-score:/ { ok = ($2 == m); exit }
            END { exit !ok }' "$yml" || problems="$problems; part $part: no step running make grade PARTS=$part worth $max"
    done <"$points"
    grep -q 'classroom-resources/autograding-grading-reporter@v1' "$yml" || problems="$problems; no reporter step"
    if [ -z "$problems" ]; then pass "$what"; else fail "$what:${problems#;}"; fi
}

# Marker text, exact or misspelt (other case, blanks, '_' or '-', either word order, a plural, a line
# comment), of solutions and of instructor sections. The stripper refuses near misses in C; this also covers every other file.
MARKER_TEXT='(begin|end)[[:space:]_-]*(solution|instructor)|\b(solution|instructor)s?[[:space:]_-]*(begin|end)\b|/[*/][[:space:]]*stub[[:space:]]*(:|\*/|$)'

check_markers() {
    grep -rniE -e "$MARKER_TEXT" "$OUT" >"$LOGS/markers.txt"
    if [ -s "$LOGS/markers.txt" ]; then
        fail "(a) no solution or instructor marker, exact or misspelt, left in $OUT"
        head -n 20 "$LOGS/markers.txt" | sed 's/^/      /'
    else
        pass "(a) no solution or instructor marker, exact or misspelt, left in $OUT ($(find "$OUT" -type f | wc -l) files)"
    fi
}

# The instructor's voice: words a student file has no reason to hold. "solution" alone is not on
# the list (a furnace's "full solution" is mathematics); the phrases that speak of the instructor's
# own code are.
VOICE='this solution|the solution (does|uses|spends|keeps|takes)|our solution|reference (solution|implementation)|instructor|mutant|seed report|solution (region|marker)|strip_solutions|make_release'

check_voice() {
    grep -rniIE -e "$VOICE" "$OUT" >"$LOGS/voice.txt"
    if [ -s "$LOGS/voice.txt" ]; then
        fail "(f) no instructor wording in $OUT"
        head -n 20 "$LOGS/voice.txt" | sed 's/^/      /'
    else
        pass "(f) no instructor wording in $OUT"
    fi
}

# Paths into the tree that the tree's text mentions (dir/file.ext under a top-level folder of the
# repository, as in `framework/dae.h`) and `make <target>`s, each checked to exist in the tree, and
# ranges of part suites, each checked to end at the tree's last part (suite_ranges).
# Outputs (build/, bin/, out/, release/) are not looked for (they are not under those folders), nor
# wildcard or placeholder paths (part<N>, part1..part5, *).
check_paths() {
    : >"$LOGS/paths.txt"
    # Code may name what the release withholds on purpose (the Makefile's optional course fragment,
    # the grader's handling of hidden cases, a part the course left out, which the code uses only
    # where it is there); a document a student reads may not.
    grep -rnoIE '(^|[^A-Za-z0-9_./-])(framework|parts|grader|grading|course|tests|tools|scenes|handout|bench)/[A-Za-z0-9_./-]*[A-Za-z0-9_][<*{]?' "$OUT" |
        sed -E 's/^([^:]*):([0-9]+):[^A-Za-z]*/\1:\2: /' |
        while IFS= read -r hit; do
            ref=${hit##*: }
            case "$ref" in *'<'*|*'*'*|*'{'*|*..*) continue ;; esac
            case "$hit" in *.md:*) ;; *) case "$ref" in course/*|grading/hidden*|reference_images/hidden*) continue ;; esac
                                          part_left_out "$ref" && continue ;; esac
            [ -e "$OUT/$ref" ] || echo "${hit#$OUT/} (no such file or folder in the release)"
        done >>"$LOGS/paths.txt"
    # Documents by name (NAME.md, ../elsewhere/NAME.md): the tree must hold a file of that name somewhere.
    grep -rnoIE '[A-Za-z0-9_./-]*[A-Za-z0-9_]\.md\b' "$OUT" | while IFS= read -r hit; do
        doc=${hit##*:}
        case "$doc" in out/*|build/*|*/out/*) continue ;; esac  # files a script writes
        [ -n "$(find "$OUT" -name "${doc##*/}" -print -quit)" ] || echo "${hit#$OUT/} (no such document in the release)"
    done >>"$LOGS/paths.txt"
    targets=$(cd "$OUT" && unset MAKEFLAGS MFLAGS MAKELEVEL && make -pRrq : 2>/dev/null |
        awk -F: '/^[A-Za-z0-9][A-Za-z0-9_.\/-]*:([^=]|$)/ { print $1 }' | sort -u)
    grep -rnoE '`make [a-z][A-Za-z0-9_./<>-]*[A-Za-z0-9_>]' "$OUT" | while IFS= read -r hit; do
        t=${hit##*make }
        case "$t" in *'<'*) continue ;; esac  # a placeholder (`make test-part<N>`), as paths' part<N>
        echo "$targets" | grep -qx -- "$t" || echo "${hit#$OUT/}\` (no such make target in the release)"
    done >>"$LOGS/paths.txt"
    suite_ranges >>"$LOGS/paths.txt"
    if [ -s "$LOGS/paths.txt" ]; then
        fail "(g) every path and make target the student tree mentions exists in it"
        head -n 20 "$LOGS/paths.txt" | sed 's/^/      /'
    else
        pass "(g) every path and make target the student tree mentions exists in it"
    fi
}

# Ranges of part suites ("test-part1 .. test-partN") that the student tree's files and its `make help`
# name: each must run from a suite the tree has to the tree's last part, so that a release of five
# parts is not sent to test-part9, nor one of nine told that its suites stop at test-part5. Prints
# each range that does not.
suite_ranges() {
    local last
    last=$(cd "$OUT" && find tests -maxdepth 1 -name 'part[0-9]*' -type d | sed 's|^tests/||' | sort -V | tail -n 1)
    [ -n "$last" ] || { echo "tests/: no part suite in the release"; return; }
    {
        grep -rnoIE 'test-part[0-9]+`? *\.\. *`?(make )?test-part[0-9]+' "$OUT" | sed "s|^$OUT/||"
        (cd "$OUT" && unset MAKEFLAGS MFLAGS MAKELEVEL && make --no-print-directory help 2>&1) |
            grep -oE 'test-part[0-9]+ *\.\. *test-part[0-9]+' | sed 's/^/make help: /'
    } | while IFS= read -r hit; do
        lo=$(echo "$hit" | grep -oE 'test-part[0-9]+' | head -n 1)
        hi=$(echo "$hit" | grep -oE 'test-part[0-9]+' | tail -n 1)
        [ -d "$OUT/tests/${lo#test-}" ] && [ "$hi" = "test-$last" ] ||
            echo "$hit (the release's part suites end at test-$last)"
    done
}

# The tool's own file handling, on a scratch repository whose names git quotes in its default output
# (a tab, a double quote, non-ASCII letters) or that hold blanks and quotes: each must reach the copy.
check_odd_names() {
    dir=$(absolute "$LOGS/odd-names")
    what="(h) files whose names git quotes are released, not dropped"
    rm -rf "$dir" && mkdir -p "$dir/repo/sub dir" || { fail "$what: cannot create $dir"; return; }
    names=("tab	name.txt" 'quote"d.md' "it's.h" 'ünïcodé.c' 'sub dir/with space.txt')
    missing=
    (
        cd "$dir/repo" && git init -q . && for f in "${names[@]}"; do printf 'int x;\n' >"$f"; done &&
            git add -A && list_files "$dir/list" && copy_tree "$dir/out" "$dir/list"
    ) >"$dir.log" 2>&1 || { fail "$what: the copy failed"; show "$dir.log"; return; }
    for f in "${names[@]}"; do [ -f "$dir/out/$f" ] || missing="$missing '$f'"; done
    if [ -z "$missing" ]; then
        pass "$what (${#names[@]} names)"
        rm -rf "$dir" "$dir.log"
    else
        fail "$what: missing$missing"
    fi
}

# The suites of tree $1 that have tests, in the Makefile's order.
