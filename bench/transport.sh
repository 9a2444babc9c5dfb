#!/bin/bash
# Light transport benchmark: whole-process wall time of the renders the course's compiled
# program was timed on (480x360, -s 64 -l 4 -m 5, 2 threads; it always samples
# adaptively with batch 32 and tolerance 0.05, so pathlab runs with -a 32 0.05 too), and the noise
# of each render as relMSE against a converged render of the same scene.
# Environment: BIN (bin), REF_SPP (1024: samples per pixel of the converged renders, cached in
# build/bench/transport/ and redone when the scene is newer), THREADS (2).
set -eu
BIN=${BIN:-bin}
REF_SPP=${REF_SPP:-1024}
THREADS=${THREADS:-2}
out=build/bench/transport
mkdir -p "$out"
common="-r 480 360 -l 4 -m 5 -t $THREADS -q"

now() { date +%s.%N; }
elapsed() { echo "$1 $2" | awk '{printf "%.2f", $2 - $1}'; }
field() { sed -n "s/.*\"$1\": *\([0-9.e+-]*\).*/\1/p" "$2" | head -n 1; }

# name scene cs184_seconds
for row in "bunny scenes/cornell_bunny.dae 21.6" "spheres scenes/cornell_spheres.dae 16.9"; do
    set -- $row
    name=$1 scene=$2 cs184=$3
    ref="$out/${name}_converged_${REF_SPP}.hdr"
    if [ ! -f "$ref" ] || [ "$scene" -nt "$ref" ]; then
        echo "transport bench: rendering the converged $name ($REF_SPP spp, once; cached in $ref)"
        "$BIN/pathtracer" $common -s "$REF_SPP" -f "$ref" "$scene"
    fi
done

echo "load average before the timed renders: $(cut -d ' ' -f 1-3 /proc/loadavg) (the machine is shared: wall times include waiting)"
printf '\n%-8s %-26s %9s %7s %9s %8s %9s %9s %8s\n' scene "flags (+ -r 480 360 -l 4 -m 5)" seconds "cpu s" "spp mean" "Mrays" relMSE "CS184 s" speedup
for row in "bunny scenes/cornell_bunny.dae 21.6" "spheres scenes/cornell_spheres.dae 16.9"; do
    set -- $row
    name=$1 scene=$2 cs184=$3
    ref="$out/${name}_converged_${REF_SPP}.hdr"
    for flags in "-s 64 -a 32 0.05" "-s 64"; do
        tag=$(echo "$flags" | tr -d ' .-')
        img="$out/${name}_${tag}.hdr"
        t0=$(now)
        cpu=$( { TIMEFORMAT='%U %S'; time "$BIN/pathtracer" $common $flags -f "$img" "$scene"; } 2>&1 | tail -n 1 | awk '{printf "%.2f", $1 + $2}')
        t1=$(now)
        secs=$(elapsed "$t0" "$t1")
        json="${img%.hdr}.json"
        rays=$(field rays_traced "$json" | awk '{printf "%.1f", $1 / 1e6}')
        spp=$(field mean_samples_per_pixel "$json")
        rel=$("$BIN/imgtool" relmse "$img" "$ref")
        speed=$(echo "$cs184 $secs" | awk '{printf "%.2fx", $1 / $2}')
        case "$flags" in *-a*) ;; *) cs184=-; speed=- ;; esac
        printf '%-8s %-26s %9s %7s %9s %8s %9s %9s %8s\n' "$name" "$flags" "$secs" "$cpu" "$spp" "$rays" "$rel" "$cs184" "$speed"
    done
done
echo "(seconds: whole process, wall clock; cpu s: user + system time of all its threads)"
echo "(relMSE = mean of (x - ref)^2 / (ref^2 + 0.01) against the ${REF_SPP}-spp render, whose own noise adds about 64/${REF_SPP} of a 64-spp render's)"
