#!/bin/sh
# The figures of handout/part3.md, part4.md and part5.md, one pathtracer command each, written to
# build/figures/part<N>/. Run all:  make figures     One part:  handout/figures.sh part4
# Each command is printed before it runs, so it can be copied and changed.
set -eu
BIN=${BIN:-bin}
T="-t 2 -q"
R="-r 320 240"
bunny=scenes/cornell_bunny.dae
spheres=scenes/cornell_spheres.dae
only=${1:-all}

run() {  # run OUT.png pathtracer-args...
    out=$1; shift
    mkdir -p "$(dirname "$out")"
    echo "$BIN/pathtracer $* -f $out"
    "$BIN/pathtracer" "$@" -f "$out"
}

if [ "$only" = all ] || [ "$only" = part3 ]; then
    d=build/figures/part3
    # 3.4 / 3.5: hemisphere sampling against light sampling, same samples and time budget
    run $d/bunny_hemisphere.png $T $R -s 16 -l 8 -m 1 -H $bunny
    run $d/bunny_importance.png $T $R -s 16 -l 8 -m 1 $bunny
    # 3.5: light rays per area light at one camera ray per pixel
    for l in 1 4 16 64; do run $d/bunny_l$l.png $T $R -s 1 -l $l -m 1 $bunny; done
    run $d/spheres_importance.png $T $R -s 64 -l 4 -m 1 $spheres
fi

if [ "$only" = all ] || [ "$only" = part4 ]; then
    d=build/figures/part4
    # 4.1: direct light only, and the indirect light alone (all bounces minus the direct ones)
    run $d/bunny_direct.hdr $T $R -s 64 -l 4 -m 1 $bunny
    run $d/bunny_all.hdr $T $R -s 64 -l 4 -m 5 $bunny
    echo "$BIN/transport_img sub $d/bunny_all.hdr $d/bunny_direct.hdr $d/bunny_indirect.png"
    "$BIN/transport_img" sub $d/bunny_all.hdr $d/bunny_direct.hdr $d/bunny_indirect.png
    run $d/bunny_direct.png $T $R -s 64 -l 4 -m 1 $bunny
    # 4.3: the k-th bounce alone
    for k in 0 1 2 3 4 5; do run $d/bunny_bounce$k.png $T $R -s 64 -l 4 -m $k -o 0 $bunny; done
    # 4.3: max depth ladder, all bounces up to -m, with Russian roulette
    for m in 0 1 2 3 4 5 8 16 100; do run $d/bunny_depth$m.png $T $R -s 64 -l 4 -m $m $bunny; done
    # 4.4: samples per pixel ladder
    for s in 1 2 4 8 16 64 256; do run $d/spheres_s$s.png $T $R -s $s -l 4 -m 5 $spheres; done
fi

if [ "$only" = all ] || [ "$only" = part5 ]; then
    d=build/figures/part5
    # 5.1: adaptive sampling and its sample-rate map (written beside it as *_rate.png)
    run $d/bunny_adaptive.png $T $R -s 1024 -a 64 0.05 -l 1 -m 5 $bunny
    run $d/spheres_adaptive.png $T $R -s 1024 -a 64 0.05 -l 1 -m 5 $spheres
fi
