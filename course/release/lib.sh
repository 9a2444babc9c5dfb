# What the release scripts share (sourced by cut, bundle and check, from the repository's top):
# which files each tree holds, and how a file is copied into the student tree.

OUT=release/student
LOGS=release/check
# Split so that no release script holds a marker itself.
MARK_BEGIN='/* BEGIN'' SOLUTION */'
MARK_END='/* END'' SOLUTION */'
MARK_STUB='/* STUB'':'
MARK_INSTRUCTOR_BEGIN='<!-- BEGIN'' INSTRUCTOR -->'
MARK_INSTRUCTOR_END='<!-- END'' INSTRUCTOR -->'

die() { echo "${0##*/}: $*" >&2; exit 2; }

# The course's parts (course/course.mk's COURSE_PARTS, which make passes on): the release, the
# bundle and their check hold these parts and nothing of the others.
COURSE_PARTS=${COURSE_PARTS:-1 2 3 4 5}
for n in $COURSE_PARTS; do
    case "$n" in [1-9]) ;; *) die "COURSE_PARTS=\"$COURSE_PARTS\": expected part numbers 1 to 9, such as \"1 2 3 4 5\"" ;; esac
    [ -n "$(find parts -maxdepth 1 -name "part${n}_*" -type d 2>/dev/null)" ] ||
        die "COURSE_PARTS names part $n, but the repository has no parts/part${n}_*/ folder"
done
# Parts 1-5 are the framework's own callees (the render loop calls parts 1 to 5 whatever the course;
# only parts 6 to 9 are compiled in where the course has them, PL_HAS_PART6..9): every course has them.
for n in 1 2 3 4 5; do
    case " $COURSE_PARTS " in *" $n "*) ;; *) die "COURSE_PARTS=\"$COURSE_PARTS\": expected parts 1 to 5 (CS184's first assignment, which the framework and every later part build on), then any of 6 to 9" ;; esac
done
# Whether part $1 is one of the course's.
part_chosen() { case " $COURSE_PARTS " in *" $1 "*) return 0 ;; esac; return 1; }
# Whether file $1 belongs to a part the course left out: its folder, its suite, its handout text,
# its references.
part_left_out() {
    local n
    case "$1" in
        parts/part[1-9]_*) n=${1#parts/part} ;;
        tests/part[1-9]/*) n=${1#tests/part} ;;
        handout/part[1-9].md|handout/part[1-9]_*) n=${1#handout/part} ;;
        reference_images/part[1-9]/*|reference_images/hidden/part[1-9]/*) n=${1#*images/}; n=${n#hidden/}; n=${n#part} ;;
        *) return 1 ;;
    esac
    ! part_chosen "${n%%[!0-9]*}"
}
absolute() { case "$1" in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
code_version() { git describe --always --dirty 2>/dev/null || echo unknown; }

# ---- which files: build outputs, the student tree's exclusions, the bundle's inclusions ---------

# Build outputs and scratch, tracked by mistake or not: never released, in no tree. (grade-out/ was
# once committed by mistake: a grading run's output folder.)
build_output() {
    case "$1" in
        build/*|bin/*|out/*|release/*|grade-out/*|*/grade-out/*|node_modules/*|*/node_modules/*) return 0 ;;
        *.o|*.d|*.a|*.so|*.gcda|*.gcno|*.pyc|*/__pycache__/*|core|core.[0-9]*|*/core.[0-9]*|*.tmp|*~) return 0 ;;
    esac
    return 1
}

# What a student tree must not hold: build outputs, CI, everything instructor-only (course/: the
# release scripts, the references maker, the bundle and its tests, mutants, calibration), the hidden
# cases and their references, anything named as solution material.
excluded() {
    build_output "$1" && return 0
    part_left_out "$1" && return 0
    case "$1" in
        .ci/*|course/*|grading/hidden/*|reference_images/hidden/*) return 0 ;;
        */solution/*|solution/*|*.solution.*) return 0 ;;
    esac
    return 1
}

# What the autograder bundle holds: the whole course as the grader needs it (framework, parts with
# their solutions, the grader, tests, every grading case and reference, hidden ones included,
# scenes, tools), copied as is; not CI, course/ (its run_autograder and setup.sh are copied to the
# bundle's top by bundle), the handout, benchmarks or the fuzzer, nor build outputs.
bundle_excluded() {
    build_output "$1" && return 0
    part_left_out "$1" && return 0
    case "$1" in
        Makefile|README.md|framework/*|parts/*|grader/*|grading/*|reference_images/*|scenes/*|third_party/*|tools/*|tests/*) return 1 ;;
    esac
    return 0
}

# The files a release is made of, NUL-separated, into $1 ($2: the filter, excluded by default): git's
# -z output is never quoted, so names with blanks, tabs, quotes or non-ASCII letters are copied like
# any other. RELEASE_UNTRACKED=1 adds untracked, not ignored files (a release tried before a commit).
list_files() {
    git rev-parse --git-dir >/dev/null 2>&1 || die "not a git repository: the release copies tracked files"
    if [ "${RELEASE_UNTRACKED:-0}" = 1 ]; then
        git ls-files -z --cached --others --exclude-standard
    else
        git ls-files -z --cached
    fi | while IFS= read -r -d '' f; do
        "${2:-excluded}" "$f" || { [ -e "$f" ] && printf '%s\0' "$f"; }  # skip files deleted but not yet committed
    done >"$1"
}

# ---- copying into the student tree ---------------------------------------------------------------

# Copies markdown file $1 to $2 without its instructor sections, and with the sections of a part
# (<!-- BEGIN PART 9 --> ... <!-- END PART 9 -->: what a document says of one part) only where the
# course has that part; the part markers themselves are dropped. Fails, naming the line, on a
# section left open, nested or a stray END.
strip_markdown() {
    awk -v b="$MARK_INSTRUCTOR_BEGIN" -v e="$MARK_INSTRUCTOR_END" -v name="$1" -v parts=" $COURSE_PARTS " '
        { t = $0; gsub(/^[ \t]+|[ \t\r]+$/, "", t) }
        t == b { if (open) { printf "%s:%d: nested instructor section (opened at line %d)\n", name, NR, open > "/dev/stderr"; bad = 1; exit 2 }
                 open = NR; next }
        t == e { if (!open) { printf "%s:%d: END INSTRUCTOR without a BEGIN\n", name, NR > "/dev/stderr"; bad = 1; exit 2 }
                 open = 0; next }
        t ~ /^<!-- BEGIN PART [1-9] -->$/ {
                 if (part) { printf "%s:%d: nested part section (opened at line %d)\n", name, NR, part > "/dev/stderr"; bad = 1; exit 2 }
                 part = NR; n = substr(t, 17, 1); drop = index(parts, " " n " ") == 0; next }
        t ~ /^<!-- END PART [1-9] -->$/ {
                 if (!part || substr(t, 15, 1) != n) { printf "%s:%d: END PART without its BEGIN\n", name, NR > "/dev/stderr"; bad = 1; exit 2 }
                 part = 0; drop = 0; next }
        !open && !drop { print }
        END { if (!bad && open) { printf "%s:%d: instructor section never closed\n", name, open > "/dev/stderr"; exit 2 }
              if (!bad && part) { printf "%s:%d: part section never closed\n", name, part > "/dev/stderr"; exit 2 } }
    ' "$1" >"$2"
}

# Whether $1 is a grading cases file: the release copies it with the course's parts only.
cases_file() { case "$1" in grading/cases.json|grading/hidden/cases.json) return 0 ;; esac; return 1; }

# Copies cases file $1 to $2 with only the course's parts (COURSE_PARTS), through $points_tool
# (bin/release_points --only): a course that stops after part 5 hands out no case of parts 6-9.
copy_cases() { "$points_tool" --only "$COURSE_PARTS" "$1" "$2"; }

# Copies one file $1 into tree $2 as a student gets it: C through the stripper ($strip) unless $3 is
# 1 (its part is solved), markdown without instructor sections, the cases file with the course's
# parts only, anything else as is. Sets $stripped.
copy_one() {
    stripped=0
    cases_file "$1" && { copy_cases "$1" "$2/$1"; return; }
    case "$1" in
        *.c|*.h)
            [ "$3" = 1 ] && { cp -p -- "$1" "$2/$1"; return; }
            "$strip" "$1" "$2/$1" || return 1
            stripped=1
            if [ -x "$1" ]; then chmod 755 "$2/$1"; else chmod 644 "$2/$1"; fi ;;
        *.md) strip_markdown "$1" "$2/$1" ;;
        *) cp -p -- "$1" "$2/$1" ;;
    esac
}

# Copies the files listed (NUL-separated) in $2 into the new folder $1, C sources through the
# stripper. With $3 = N, parts 1..N keep their solutions (a student who solved them in order).
# Sets $summary and $failed; fails if any file failed.
copy_tree() {
    dest=$1 solved_up_to=${3:-0}
    rm -rf "$dest" && mkdir -p "$dest" || die "cannot create $dest"
    files=0 n_stripped=0 failed=0
    while IFS= read -r -d '' f; do
        mkdir -p -- "$dest/$(dirname -- "$f")"
        solved=0
        case "$f" in
            parts/part[1-9]_*/*) k=${f#parts/part}; k=${k%%_*}; [ "$k" -le "$solved_up_to" ] && solved=1 ;;
        esac
        if copy_one "$f" "$dest" "$solved"; then n_stripped=$((n_stripped + stripped)); else failed=$((failed + 1)); fi
        files=$((files + 1))
    done <"$2"
    # Without .git the Makefile takes the code version from here (sidecars record it).
    echo "pathlab $(code_version) student release" >"$dest/VERSION" || failed=$((failed + 1))
    summary="$files files, $n_stripped C sources passed through strip_solutions"
    [ "$failed" = 0 ]
}
