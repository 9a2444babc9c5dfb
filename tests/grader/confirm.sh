#!/bin/sh
# Test machinery: a case that fails on its p-value alone is rendered once more and judged on that
# render (grader/grade_image.h), and only such a case. bin/grade grades scratch trees that hold this
# tree's files but whose bin/pathtracer is a wrapper around this tree's renderer:
#   flaky   the first render of each pair is wrong (normal shading in place of the case's light: a
#           p-value failure, nothing else) and the second is the case itself, so every case fails
#           its first render and passes on its second: the case passes, and the report says it was
#           rendered twice, with both seeds. It is also what a student who has read the grader would
#           try against the rule, and it scores only because its second render is right, which
#           takes a right part (student code cannot tell which render it is: both get a seed);
#   biased  every render is wrong: both renders fail, and so does the case;
#   det     part 1's deterministic case from the wrong scene: a failure that is not chance, never
#           rendered again.
# Each is graded 3 times with --calibrate on one case (grazing_direct, part 3, about 2 s a render;
# spheres_normals, part 1), whose counts say how many first renders and how many cases failed, and
# the wrapper counts its renders.
# The flaky tree is also graded as a student's make grade would (part 3, its public cases), for the
# report's words. Run it with `make test-grade-confirm`; about 15 seconds on two cores.
set -eu
cd "$(dirname "$0")/../.."
root=$PWD
out=out/confirm-test
fail() { echo "test-grade-confirm: FAILED: $*"; exit 1; }
. tests/common/need.sh
need jq jq test-grade-confirm  # reads results.json here (the grader's own reading is jansson's)
rm -rf "$out"
mkdir -p "$out"

# A scratch tree: every top-level entry of this one linked, and bin/ of links but pathtracer.
tree() {
    t=$out/$1
    mkdir -p "$t/bin"
    for f in "$root"/*; do case $(basename "$f") in bin|Makefile) ;; *) ln -s "$f" "$t/" ;; esac; done
    # The grader makes a student's tree before grading it; this one is made already, and make must
    # not link a renderer over the wrapper.
    printf '%%:\n\t@:\n' >"$t/Makefile"
    for f in "$root"/bin/*; do [ "$(basename "$f")" = pathtracer ] || ln -s "$f" "$t/bin/"; done
    # $2: which calls render wrong, by the call's number n (1, 2, ...): a shell test on $n.
    # $3: the flags a wrong render adds; $4: the scene it renders instead of the case's (the last
    # argument), or nothing.
    cat >"$t/bin/pathtracer" <<EOF
#!/bin/sh
n=\$(( \$(cat "$root/$t/calls" 2>/dev/null || echo 0) + 1 ))
echo \$n >"$root/$t/calls"
if $2 && [ -n "${4:-}" ]; then
    i=0 last=\$#
    for a; do i=\$((i + 1)); [ \$i = 1 ] && set --; [ \$i = \$last ] || set -- "\$@" "\$a"; done
    set -- "\$@" "$root/${4:-}"
fi
if $2; then exec "$root/bin/pathtracer" $3 "\$@"; fi
exec "$root/bin/pathtracer" "\$@"
EOF
    chmod 755 "$t/bin/pathtracer"
}
tree flaky '[ $((n % 2)) = 1 ]' --normals
tree biased true --normals
# det: part 1's deterministic case rendered from the wrong scene (the bunny's box for the spheres'),
# a failure no second render could change.
tree det true '' scenes/cornell_bunny.dae

# Graded 3 times: "first-render-failures case-failures renders" for one case of one part.
counts() {  # $1: the tree, $2: the part, $3: the case
    (cd "$out/$1" && bin/grade --calibrate 3 --parts "$2" --cases "$3") >"$out/$1.log" 2>&1 || true
    line=$(grep "^part$2/$3" "$out/$1.log") || fail "$1: no calibration line (see $out/$1.log)"
    echo "$(echo "$line" | awk '{print $3, $4}') $(cat "$out/$1/calls")"
}
got=$(counts flaky 3 grazing_direct)
[ "$got" = "3 0 6" ] || fail "flaky: expected 3 first-render failures, 0 cases failed, 6 renders; got $got"
echo "  a wrong first render and a right second one: 3 first renders fail, no case does (6 renders)"
got=$(counts biased 3 grazing_direct)
[ "$got" = "3 3 6" ] || fail "biased: expected 3 first-render failures, 3 cases failed, 6 renders; got $got"
echo "  a wrong render every time: 3 first renders fail, so do the 3 cases (6 renders)"
got=$(counts det 1 spheres_normals)
[ "$got" = "3 3 3" ] || fail "deterministic: expected 3 failures, 3 cases failed, 3 renders (never again); got $got"
echo "  a deterministic case's failure is never rendered again (3 renders for 3 failures)"

# The report's words: the flaky tree graded as make grade does, part 3's public cases.
(cd "$out/flaky" && bin/grade --parts 3 --seed 5 --out "$root/$out/grade") >"$out/grade.log" 2>&1 ||
    fail "the flaky tree lost points: every second render is the case's own (see $out/grade.log)"
json=$out/grade/results.json
cases=$(jq '[.tests[] | select(.name | startswith("Part 3: image"))] | length' "$json")
twice=$(jq '[.tests[] | select(.name | startswith("Part 3: image")) | select(.output | startswith("Rendered twice: the first render (seed 5)"))
            | select(.output | contains("the first failure was chance"))] | length' "$json")
[ "$cases" -gt 0 ] && [ "$twice" = "$cases" ] ||
    fail "$twice of part 3's $cases image cases say they were rendered twice from seed 5 (see $json)"
grep -q "Rendered twice" "$out/grade/report/index.html" || fail "the HTML report does not say a case was rendered twice"
echo "  the report says each of part 3's $cases cases was rendered twice, from seed 5, and why"
echo "test-grade-confirm: passed"
