#!/bin/sh
# Test machinery: the references from a real Slurm job array equal the local ones, byte for byte
# (issue 12). Brings up a single-node cluster from Debian's packages (course/shared/slurm_cluster.sh),
# submits the range array and its merge job for a few small cases, waits, compares with a local
# run on 1 job and on 2, then checks that a range deleted after the fact is rendered again alone,
# that a truncated range file is refused at the merge, and stops the daemons it started. Needs root (it installs slurm-wlm and munge and runs the
# daemons); otherwise it says so and skips. Run it with `make test-slurm`.
set -eu
cd "$(dirname "$0")/../.."
CASES=${SLURM_TEST_CASES:-"spheres_normals_jitter point_directional"}

if [ "$(id -u)" != 0 ]; then
    echo "test-slurm: SKIPPED: needs root to install slurm-wlm and munge and to run their daemons"
    exit 0
fi
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    echo "test-slurm: installing slurm-wlm and munge"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null 2>&1 ||
        { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null; }
fi
make -s bin/pathtracer bin/references

tmp=$(mktemp -d /tmp/pathlab-slurm.XXXXXX)
# The daemons are waited for as they stop; a job step's helper (slurmstepd) may still write for a
# moment after, so a first removal that finds a directory filling up is tried once more.
cleanup() { course/shared/slurm_cluster.sh down "$tmp/cluster" || true; rm -rf "$tmp" 2>/dev/null || { sleep 1; rm -rf "$tmp"; }; }
trap cleanup EXIT INT TERM
eval "$(course/shared/slurm_cluster.sh up "$tmp/cluster")"
export SLURM_CONF

fail() { echo "test-slurm: FAILED: $*"; exit 1; }

# The job array, then wait for the merge job to leave the queue.
bin/references --slurm --out "$tmp/slurm" --work "$tmp/slurm-work" $CASES | tee "$tmp/submit.txt"
merge=$(sed -n 's/.*merge as job \([0-9]*\).*/\1/p' "$tmp/submit.txt")
[ -n "$merge" ] || fail "no merge job id in the submission's output"
i=0
while squeue -h -j "$merge" 2>/dev/null | grep -q .; do
    i=$((i + 1)); [ $i -le 600 ] || fail "the merge job did not finish in 10 minutes"
    sleep 1
done
bin/references --status --out "$tmp/slurm" --work "$tmp/slurm-work" $CASES

# The same references made locally, on 1 job and on 2.
bin/references --jobs 1 --out "$tmp/local1" --work "$tmp/work1" $CASES >/dev/null
bin/references --jobs 2 --out "$tmp/local2" --work "$tmp/work2" $CASES >/dev/null
for f in $(cd "$tmp/local1" && find . -type f | sort); do
    cmp "$tmp/local1/$f" "$tmp/local2/$f" || fail "$f differs between 1 and 2 local jobs"
    cmp "$tmp/local1/$f" "$tmp/slurm/$f" || fail "$f differs between the local run and the Slurm array"
done
n=$(cd "$tmp/local1" && find . -name '*.exr' | wc -l)
[ "$n" -ge 2 ] || fail "expected at least 2 references, found $n"

# A range lost (a task killed mid-way) is rendered again alone, and the result is the same.
victim=$(find "$tmp/work1" -name '[0-9]*-[0-9]*.exr' | sort | head -n 1)
rm "$victim" "$tmp"/local1/*/*.json
bin/references --jobs 1 --out "$tmp/local1" --work "$tmp/work1" $CASES >"$tmp/rerun.txt" 2>&1 ||
    fail "the run after losing one range failed: $(cat "$tmp/rerun.txt")"
grep -q " 1 range(s)" "$tmp/rerun.txt" || fail "after losing one range, expected exactly that range to be rendered again"
for f in $(cd "$tmp/local2" && find . -type f | sort); do
    cmp "$tmp/local1/$f" "$tmp/local2/$f" || fail "$f differs after the lost range was rendered again"
done
# A corrupted range file is refused before merging, and the reference it would change is untouched.
# (a range file: the case's work folder also holds the probe render of the case's own flags)
victim=$(find "$tmp/work1" -name '[0-9]*-[0-9]*.exr' | sort | tail -n 1)
head -c 300 "$victim" > "$victim.cut" && mv "$victim.cut" "$victim"
rm "$tmp"/local1/*/*.json
if bin/references --merge-only --out "$tmp/local1" --work "$tmp/work1" $CASES >"$tmp/corrupt.txt" 2>&1; then
    fail "a truncated range file was merged"
fi
for f in $(cd "$tmp/local2" && find . -name '*.exr' | sort); do
    cmp "$tmp/local1/$f" "$tmp/local2/$f" || fail "$f changed although its merge was refused"
done
echo "test-slurm: passed: $n references from the Slurm array equal the local ones (1 and 2 jobs) byte for byte"
