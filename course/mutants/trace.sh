#!/bin/sh
# Test machinery: not part of any assignment.
# The marks of --trace-pixel (framework/trace.h) against the mutant catalogue: each row below names a
# catalogued student bug, a trace command and the "!!" line the bug must produce in it. The patch is
# applied to a scratch copy (as course/mutants/run.sh does), bin/pathtracer built there, and the same
# command run on the solution must print no "!!" line at all (a mark that fires on correct code is a
# defect too). Then the same for correct code written differently: the solution and each of parts
# 3, 4, 6, 7, 8 and 9's correct alternatives (course/alternatives: other draw orders, roulette
# conventions, a recursion, CS184's radiance scale through glass, another disc mapping) traced over a sweep of renders (-o 0 and -o 1, -H, one and
# several light samples, a thin lens, every course scene) print no "!!" line. Last, the grader's pointer: a failing case's --trace-pixel command
# shows the bug. The rows from part7-pdf-missing-jacobian on, and part 8's and part 9's density rows, are
# marked by the density checks (framework/trace_density.c): a sampler's pdf against its own samples.
# Usage: course/mutants/trace.sh           (make trace-mutants)
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
scratch="$root/build/trace-mutants"
for tool in pathtracer strip_solutions grade; do
    [ -x "$root/bin/$tool" ] || { echo "trace-mutants: bin/$tool is not built (make trace-mutants builds what it needs)"; exit 2; }
done
mkdir -p "$scratch"
failed=0
# patch | flags of the trace (scene relative to the root) | text the mark must contain. The row
# "stub:FILE" strips FILE's solutions as the student release does (a half-written tree) instead.
# The rows are one single-quoted string: no row may hold a quote (an apostrophe ends the list).
rows='stub:parts/part3_direct/direct.c|-r 64 48 -m 1 --trace-pixel 32 30 scenes/cornell_spheres.dae|stub: Part 3, task 3.3: zero_bounce_radiance() is not implemented yet
part3-emission-signed-cosine|-r 64 48 -m 0 --trace-pixel 32 41 scenes/cornell_spheres.dae|radiance must be finite and not negative
part3-pdf-zero-with-f|-r 64 48 -m 2 --trace-pixel 20 10 scenes/cornell_spheres.dae|pdf is 0 but f is
part3-sample-points-into-surface|-r 64 48 -m 2 --trace-pixel 20 10 scenes/cornell_spheres.dae|below the surface it leaves
part1-triangle-normal-not-normalised|-r 64 48 --normals --trace-pixel 30 15 scenes/cornell_bunny.dae|not 1
part3-bsdf-without-pi|-r 64 48 -m 2 --trace-pixel 20 10 scenes/cornell_spheres.dae|throughput above 1 after a diffuse bounce
part3-shadow-ray-ignored|-r 64 48 -s 4 -m 1 --trace-pixel 20 6 scenes/cornell_spheres.dae|nearer than the light and is still counted
part3-shadow-ray-hits-light|-r 64 48 -m 1 --trace-pixel 32 30 scenes/cornell_spheres.dae|the light samples add up to
part3-hemisphere-divides-by-light-samples-only|-r 64 48 -s 128 -m 1 -H -l 2 --trace-pixel 30 12 scenes/cornell_two_lights.dae|the hemisphere samples add up to
part3-shadow-ray-from-raw-hit-point|-r 160 120 -s 64 -m 1 -l 4 --seed 160154358618 --trace-pixel 95 97 scenes/cornell_grazing.dae|the surface it starts on
part4-no-roulette-compensation|-r 64 48 -s 16 -m 8 --trace-pixel 20 10 scenes/cornell_spheres.dae|does not divide the throughput
part4-roulette-test-inverted|-r 64 48 -s 16 -m 8 --trace-pixel 20 10 scenes/cornell_spheres.dae|but divides the throughput by
part5-standard-deviation-not-error|-r 64 48 -s 64 -l 4 -a 8 0.1 -m 1 --trace-pixel 32 30 scenes/cornell_spheres.dae|adaptive_converged says go on
stub:parts/part9_lens/lens.c|-r 64 48 -s 2 -m 0 -b 0.1 -d 2.8 --trace-pixel 40 20 scenes/cornell_spheres.dae|the camera ray spans no distance: thin_lens_ray (task 9.2) is a stub
part9-focus-along-the-ray|-r 64 48 -s 2 -m 0 -b 0.1 -d 2.8 --trace-pixel 5 5 scenes/cornell_spheres.dae|the lens ray misses the pinhole ray
part9-lens-in-world-axes|-r 64 48 -s 2 -m 0 -b 0.1 -d 3 --trace-pixel 20 20 scenes/lights_point_dir.dae|the lens ray starts off the lens
stub:parts/part6_specular/specular.c|-r 64 48 -m 1 --trace-pixel 24 20 scenes/cornell_mirror_glass.dae|stub: Part 6, task 6.2: mirror_sample_f() is not implemented yet
part6-mirror-f-keeps-the-cosine|-r 64 48 -s 4 -m 2 --trace-pixel 24 20 scenes/cornell_mirror_glass.dae|this reflection weighs
part6-glass-pdf-not-scaled|-r 64 48 -s 4 -m 2 --trace-pixel 43 14 scenes/cornell_mirror_glass.dae|this refraction weighs
stub:parts/part7_microfacet/microfacet.c|-r 64 48 -m 1 --trace-pixel 42 18 scenes/cornell_microfacet.dae|stub: Part 7, task 7.4: microfacet_f() is not implemented yet
part8-pdf-missing-sine|-r 32 24 -s 1 -m 1 -l 3 -e scenes/sky.exr --trace-pixel 6 3 scenes/env_shapes.dae|the samples of env_sample_importance do not follow env_pdf
part8-conditional-row-stride-width|-r 32 24 -s 4 -m 1 -l 16 -e scenes/sky.exr --trace-pixel 28 2 scenes/env_shapes.dae|is not the density of its direction
part8-row-search-one-off|-r 32 24 -s 1 -m 1 -l 3 -e scenes/sky.exr --trace-pixel 6 3 scenes/env_shapes.dae|is not the density of its direction
part8-texel-corner-not-within|-r 32 24 -s 1 -m 1 -l 3 -e scenes/sky.exr --trace-pixel 6 3 scenes/env_shapes.dae|the samples of env_sample_importance do not follow env_pdf
part8-uniform-theta-crowds-poles|-r 32 24 -s 1 -m 1 -l 3 --env-uniform -e scenes/studio.exr --trace-pixel 6 3 scenes/env_shapes.dae|the samples of env_sample_uniform do not follow the uniform density
part7-pdf-missing-jacobian|-r 64 48 -s 4 -m 5 --trace-pixel 20 10 scenes/cornell_microfacet.dae|microfacet_pdf integrates to
part7-sampled-theta-alpha-not-squared|-r 64 48 -s 4 -m 5 --trace-pixel 20 10 scenes/cornell_microfacet.dae|the samples of microfacet_sample_f do not follow microfacet_pdf
part7-half-azimuths-of-h|-r 64 48 -s 4 -m 5 --trace-pixel 20 10 scenes/cornell_microfacet.dae|the samples of microfacet_sample_f do not follow microfacet_pdf
part7-beckmann-cos-squared|-r 64 48 -s 4 -m 5 --trace-pixel 20 10 scenes/cornell_microfacet.dae|the samples of microfacet_sample_f do not follow microfacet_pdf
part3-sampler-disagrees-with-pdf|-r 64 48 -m 2 --trace-pixel 20 10 scenes/cornell_spheres.dae|the samples of bsdf_sample_f do not follow bsdf_pdf
part9-disc-radius-not-square-rooted|-r 64 48 -s 2 -m 0 -b 0.1 -d 2.8 --trace-pixel 5 5 scenes/cornell_spheres.dae|lens points do not follow the uniform density over the lens
part9-lens-direction-not-unit|-r 64 48 -s 2 -m 0 -b 0.1 -d 2.8 --trace-pixel 5 5 scenes/cornell_spheres.dae|direction has length'
# A scratch copy of the tree in $1 (the release objects reused: make rebuilds what changes).
fresh_copy() {
    rm -rf "$1" && mkdir -p "$1"
    (cd "$root" && cp -a Makefile framework parts tests scenes third_party "$1"/)
    [ -d "$root/build/release" ] && mkdir -p "$1/build" && cp -a "$root/build/release" "$1/build/"
    return 0
}
# Applies patch $2 to the copy in $1 (its files dated now) and builds bin/pathtracer there; says
# BROKEN with the reason and fails otherwise.
patch_and_build() {
    if ! patch -s -p1 -d "$1" < "$2"; then echo "BROKEN  $(basename "$2" .patch): the patch no longer applies"; return 1; fi
    touch $(sed -n 's/^+++ b\///p' "$2" | sed "s|^|$1/|")
    build "$1" "$(basename "$2" .patch)"
}
build() {
    make -C "$1" --no-print-directory bin/pathtracer > "$1/log.txt" 2>&1 || { echo "BROKEN  $2: does not build"; return 1; }
}
echo "$rows" | while IFS='|' read -r name flags expect; do
    dir="$scratch/$(echo "$name" | tr ':/' '__')"
    fresh_copy "$dir"
    case "$name" in
    stub:*)
        file=${name#stub:}
        "$root/bin/strip_solutions" "$root/$file" "$dir/$file" || { echo "BROKEN  $name: cannot strip $file"; exit 1; }
        build "$dir" "$name" || exit 1 ;;
    *)
        patch_and_build "$dir" "$root/course/mutants/$name.patch" || exit 1 ;;
    esac
    clean=$(cd "$root" && bin/pathtracer $flags 2>/dev/null | grep -c '^ *!! ')
    line=$(cd "$dir" && bin/pathtracer $flags 2>/dev/null | grep -m 1 -F "$expect")
    if [ "$clean" != 0 ]; then echo "FALSE   $name: the solution's trace has $clean marks: bin/pathtracer $flags"; exit 1; fi
    if [ -z "$line" ]; then echo "MISSED  $name: no mark containing '$expect' in bin/pathtracer $flags"; exit 1; fi
    echo "marked  $name: $(echo "$line" | sed 's/^ *//' | cut -c 1-110)"
done || failed=1
[ $failed -eq 0 ] && echo "trace marks: every mutant marked, no mark on the solution"

# Correct code, traced widely: no mark anywhere.
sweep='-m 1 -l 4|-m 1 -l 4 -H|-m 2 -o 0 -l 1|-m 3 -o 0 -l 4|-m 5 -l 2|-m 5 -l 4 -H|-m 4 -o 0 --no-rr -l 2|-m 8 -o 1 -l 1|-m 2 -l 2 -b 0.15 -d 3'
scenes='cornell_spheres cornell_two_lights lights_point_dir cornell_grazing env_shapes cornell_mirror_glass cornell_microfacet'
# env_shapes has no light of its own: it is swept under its two maps instead (part 8).
env_sweep='-m 1 -l 4 -e scenes/sky.exr|-m 3 -l 2 --env-uniform -e scenes/studio.exr|-m 2 -l 2 -e scenes/studio.exr'
for alt in solution "$root"/course/alternatives/part3-*.patch "$root"/course/alternatives/part4-*.patch \
           "$root"/course/alternatives/part6-*.patch "$root"/course/alternatives/part7-*.patch \
           "$root"/course/alternatives/part8-*.patch \
           "$root"/course/alternatives/part9-*.patch; do
    name=$(basename "$alt" .patch) dir=$root
    if [ "$alt" != solution ]; then
        dir="$scratch/alt-$name"
        fresh_copy "$dir"
        patch_and_build "$dir" "$alt" || { failed=1; continue; }
    fi
    marks=0 traces=0 first=
    for scene in $scenes; do
        for pixel in "20 10" "33 30" "50 40"; do
            if [ "$scene" = env_shapes ]; then echo "$env_sweep"; else echo "$sweep"; fi | tr '|' '\n' > "$scratch/sweep.txt"
            while read -r flags; do
                cmd="$flags -r 64 48 -s 16 --seed 7 --trace-pixel $pixel scenes/$scene.dae"
                n=$(cd "$dir" && bin/pathtracer $cmd 2>/dev/null | grep -c '^ *!! ')
                traces=$((traces + 1))
                [ "$n" = 0 ] || { marks=$((marks + n)); [ -n "$first" ] || first=$cmd; }
            done < "$scratch/sweep.txt"
        done
    done
    if [ "$marks" = 0 ]; then echo "clean   $name: $traces traces, no mark"
    else echo "FALSE   $name: $marks marks in $traces traces of correct code, first in bin/pathtracer $first"; failed=1; fi
done

# The grader points at it: a submission with part3-bsdf-without-pi fails its part 3 image cases, and
# the first --trace-pixel command results.json names, run in that submission's tree, marks the bug.
name=part3-bsdf-without-pi
sub="$scratch/grade-$name"
rm -rf "$sub" && mkdir -p "$sub" && cp -a "$root/parts" "$sub/"
patch -s -p1 -d "$sub" < "$root/course/mutants/$name.patch"
"$root/bin/grade" --submission "$sub" --public --parts 3 --out "$sub/out" > "$sub/grade.txt" 2>&1 || true
cmd=$(grep -o 'bin/pathtracer [^`"\\]*--trace-pixel [0-9]* [0-9]* [^ `"\\]*' "$sub/out/results.json" | head -n 1)
if [ -z "$cmd" ] || ! grep -q -- '--trace-pixel' "$sub/grade.txt"; then
    echo "MISSED  grader: no --trace-pixel command in results.json or make grade's output ($sub/out)"; failed=1
elif ! (cd "$scratch/$name" && $cmd 2>/dev/null | grep -q '^ *!! '); then
    echo "MISSED  grader: '$cmd' shows no mark in the $name tree"; failed=1
else
    echo "pointed grader: results.json names '$cmd', whose trace marks the bug"
fi
exit $failed
