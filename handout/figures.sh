#!/bin/sh
# The figures of every part's handout (each handout/part<N>.md of the course), one command each, written to
# out/figures/part<N>/. Run all:  make figures     One part:  handout/figures.sh part4
# It builds what it needs first (bin/pathtracer, bin/imgtool and bin/acne_figure, through make), so it also works on a
# fresh tree. Each command is printed before it runs, so it can be copied and changed.
# Settings (environment): BIN (bin), OUT (out/figures).
set -eu
cd "$(dirname "$0")/.."
BIN=${BIN:-bin}
OUT=${OUT:-out/figures}
T="-t 2 -q"
R="-r 320 240"
bunny=scenes/cornell_bunny.dae
spheres=scenes/cornell_spheres.dae
empty=scenes/cornell_empty.dae
mirror_glass=scenes/cornell_mirror_glass.dae
microfacet=scenes/cornell_microfacet.dae
only=${1:-all}
case "$only" in
    all|part1|part2|part3|part4|part5|part6|part7|part8|part9) ;;
    *) echo "usage: handout/figures.sh [all|part1|part2|part3|part4|part5|part6|part7|part8|part9]" >&2; exit 2 ;;
esac

${MAKE:-make} --no-print-directory -s "$BIN/pathtracer" "$BIN/imgtool" "$BIN/acne_figure"

say() { echo "$*"; "$@"; }
run() {  # run OUT.png pathtracer-args...
    out=$1; shift
    mkdir -p "$(dirname "$out")"
    say "$BIN/pathtracer" "$@" -f "$out"
}
want() { [ "$only" = all ] || [ "$only" = "$1" ]; }

if want part1; then
    d=$OUT/part1
    # 1.1-1.3: normal shading of the spheres and the empty box; 1.4: 16 samples per pixel
    run $d/spheres.png $T --normals -r 480 360 $spheres
    run $d/empty.png $T --normals -r 480 360 $empty
    run $d/spheres_s16.png $T --normals -s 16 -r 480 360 $spheres
fi

if want part2; then
    d=$OUT/part2
    # 2.2-2.3: the bunny through the BVH, and the heat map of node boxes visited per pixel
    run $d/bunny.png $T --normals -r 400 300 $bunny
    mkdir -p $d
    say "$BIN/pathtracer" $T --normals -r 400 300 --heatmap $d/bunny_heatmap.png $bunny
fi

if want part3; then
    d=$OUT/part3
    # 3.4 / 3.5: hemisphere sampling against light sampling, same samples and time budget
    run $d/bunny_hemisphere.png $T $R -s 16 -l 8 -m 1 -H $bunny
    run $d/bunny_importance.png $T $R -s 16 -l 8 -m 1 $bunny
    # 3.5: light rays per area light at one camera ray per pixel
    for l in 1 4 16 64; do run $d/bunny_l$l.png $T $R -s 1 -l $l -m 1 $bunny; done
    run $d/spheres_importance.png $T $R -s 64 -l 4 -m 1 $spheres
    # 3.4: shadow acne: shadow rays from the raw hit point (left) and through spawn.h (right), on
    # the side-lit box, which sits 100 m from the origin, where the raw points' error shows
    say "$BIN/acne_figure" -s 16 -r 320 240 scenes/cornell_grazing.dae $d/acne.png
fi

if want part4; then
    d=$OUT/part4
    # 4.1: direct light only, and the indirect light alone (all bounces minus the direct ones)
    run $d/bunny_direct.hdr $T $R -s 64 -l 4 -m 1 $bunny
    run $d/bunny_all.hdr $T $R -s 64 -l 4 -m 5 $bunny
    say "$BIN/imgtool" sub $d/bunny_all.hdr $d/bunny_direct.hdr $d/bunny_indirect.png
    run $d/bunny_direct.png $T $R -s 64 -l 4 -m 1 $bunny
    # 4.3: the k-th bounce alone
    for k in 0 1 2 3 4 5; do run $d/bunny_bounce$k.png $T $R -s 64 -l 4 -m $k -o 0 $bunny; done
    # 4.3: max depth ladder, all bounces up to -m, with Russian roulette
    for m in 0 1 2 3 4 5 8 16 100; do run $d/bunny_depth$m.png $T $R -s 64 -l 4 -m $m $bunny; done
    # 4.4: samples per pixel ladder
    for s in 1 2 4 8 16 64 256; do run $d/spheres_s$s.png $T $R -s $s -l 4 -m 5 $spheres; done
fi

if want part5; then
    d=$OUT/part5
    # 5.1: adaptive sampling and its sample-rate map (written beside it as *_rate.png)
    run $d/bunny_adaptive.png $T $R -s 1024 -a 64 0.05 -l 1 -m 5 $bunny
    run $d/spheres_adaptive.png $T $R -s 1024 -a 64 0.05 -l 1 -m 5 $spheres
fi
if want part6 && [ -d parts/part6_specular ]; then
    d=$OUT/part6
    # 6.1-6.5: the mirror and glass spheres, direct light only, all bounces (the caustic), the second bounce alone
    run $d/mirror_glass_m1.png $T $R -s 64 -l 2 -m 1 $mirror_glass
    run $d/mirror_glass_m5.png $T $R -s 64 -l 2 -m 5 $mirror_glass
    run $d/mirror_glass_bounce2.png $T $R -s 64 -l 2 -m 2 -o 0 $mirror_glass
fi
if want part7 && [ -d parts/part7_microfacet ]; then
    d=$OUT/part7
    # 7.1-7.6: the metals lit directly by light sampling, all bounces, then direct light by hemisphere sampling
    run $d/microfacet_m1.png $T $R -s 64 -l 4 -m 1 $microfacet
    run $d/microfacet_m5.png $T $R -s 64 -l 2 -m 5 $microfacet
    run $d/microfacet_hemisphere.png $T $R -s 64 -l 4 -m 1 -H $microfacet
fi
if want part8 && [ -d parts/part8_envlight ]; then
    d=$OUT/part8
    # 8.1 against 8.4: the sky at the same samples, uniform then by importance; then the studio, all bounces
    run $d/sky_uniform.png $T $R -s 16 -m 1 --env-uniform -e scenes/sky.exr scenes/env_shapes.dae
    run $d/sky_importance.png $T $R -s 16 -m 1 -e scenes/sky.exr scenes/env_shapes.dae
    run $d/studio.png $T $R -s 64 -m 5 -e scenes/studio.exr scenes/env_shapes.dae
    run $d/open_box_sky.png $T $R -s 64 -m 5 -e scenes/sky.exr scenes/cornell_open.dae
fi
if want part9 && [ -d parts/part9_lens ]; then
    d=$OUT/part9
    # 9.2: a pinhole, then the lens focused on the front sphere (2.8 m), then on the back one (3.45 m)
    run $d/spheres_pinhole.png $T $R -s 64 -l 2 -m 5 $spheres
    run $d/spheres_focus_front.png $T $R -s 64 -l 2 -m 5 -b 0.1 -d 2.8 $spheres
    run $d/spheres_focus_back.png $T $R -s 64 -l 2 -m 5 -b 0.1 -d 3.45 $spheres
fi
# "Debugging with a trace": the handout's traces of the parts asked for, as files beside the figures.
BIN=$BIN sh handout/traces.sh --out "$OUT" $([ "$only" = all ] || echo "$only")
echo "figures: $OUT/"
