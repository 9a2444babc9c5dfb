#!/bin/bash
# Benchmark: not part of any assignment. The class grader's throughput and memory (bench/RESULTS.md):
# a class of N submissions made from the catalogues (the solution, every correct alternative of parts
# 1-5, then catalogued bugs of parts 1-5 in name order), graded on parts 1-5 (the first assignment,
# COURSE_PARTS' default: what a course grades), locally with the default jobs, or (slurm) as a job
# array on a one-node Slurm cluster of this machine (course/shared/slurm_cluster.sh). Prints
# submissions per hour and each grading's peak memory (the resident memory of bin/grade and all its
# children, sampled every half second). As root, from the course's root, after make bin/grade-class.
#   course/class/bench.sh [N (40)] [local|slurm]
set -u
cd "$(dirname "$0")/../.." || exit 2
n=${1:-40} where=${2:-local}
tmp=$(mktemp -d /tmp/pathlab-class-bench.XXXXXX) && chmod 755 "$tmp"
cluster=
cleanup() { [ -n "$cluster" ] && sh course/shared/slurm_cluster.sh down "$cluster" >/dev/null 2>&1; rm -rf "$tmp"; }
trap cleanup EXIT
names=$( { echo solution; ls course/alternatives/part[1-5]-*.patch; ls course/mutants/part[1-5]-*.patch |
          grep -v part5-wrong-statistic-red-channel; } | xargs -n1 basename | sed 's/\.patch$//' | head -n "$n")
sh course/class/make_class.sh "$tmp/subs" $names || exit 1
echo "class: $(ls "$tmp/subs" | wc -l) submissions, parts 1-5; $(nproc) cores"

# Each grading's peak memory: every bin/grade --submission and its descendants, summed, each 0.5 s.
sample_memory() {
    exec python3 - "$1" <<'PY'
import os, sys, time
out = open(sys.argv[1], 'w')
peak = {}
def children():
    kids = {}
    for p in filter(str.isdigit, os.listdir('/proc')):
        try:
            ppid = int(open('/proc/%s/stat' % p).read().rsplit(')', 1)[1].split()[1])
            kids.setdefault(ppid, []).append(int(p))
        except Exception: pass
    return kids
def rss(pid):
    try: return int(open('/proc/%d/statm' % pid).read().split()[1]) * os.sysconf('SC_PAGE_SIZE')
    except Exception: return 0
while True:
    kids = children()
    for p in [q for ps in kids.values() for q in ps]:
        try: cmd = open('/proc/%d/cmdline' % p, 'rb').read().split(b'\0')
        except Exception: continue
        if cmd[:2] != [b'bin/grade', b'--submission']: continue
        total, todo = 0, [p]
        while todo:
            q = todo.pop(); total += rss(q); todo += kids.get(q, [])
        key = b' '.join(cmd[2:7])
        peak[key] = max(peak.get(key, 0), total)
    out.seek(0); out.truncate(); out.write('\n'.join(str(v) for v in peak.values())); out.flush()
    time.sleep(0.5)
PY
}
report_memory() {
    sort -n "$1" | awk '{ v[NR] = $1 / 1048576 } END { if (NR) printf "memory per grading (one part, peak RSS of bin/grade and its children): median %.0f MB, max %.0f MB over %d gradings\n", v[int((NR + 1) / 2)], v[NR], NR }'
}

# One run, local or as a Slurm job array on a one-node cluster of this machine (the nodes' processes
# are sampled all the same: they are this machine's).
sample_memory "$tmp/memory.txt" &
sampler=$!
args=(--submissions "$tmp/subs" --out "$tmp/out" --secret "$tmp/secret" --parts 1,2,3,4,5)
start=$(date +%s.%N)
if [ "$where" = slurm ]; then
    cluster=$tmp/cluster
    eval "$(sh course/shared/slurm_cluster.sh up "$cluster")" && export SLURM_CONF || exit 1
    start=$(date +%s.%N)
    bin/grade-class "${args[@]}" --slurm >"$tmp/submit.log" 2>&1
    final=$(sed -n 's/.*report as job \([0-9]*\).*/\1/p' "$tmp/submit.log")
    while squeue -h -j "${final:-0}" 2>/dev/null | grep -q .; do sleep 1; done
    cpu="(CPU not measured: the jobs are slurmd's children)"
else
    /usr/bin/time -f '%U %S' -o "$tmp/cpu.txt" nice bin/grade-class "${args[@]}" >"$tmp/local.log" 2>&1
    cpu=$(awk -v n="$n" '{ printf "CPU %.0f s (%.1f s a submission: at most %.0f an hour on '"$(nproc)"' idle cores)", $1 + $2, ($1 + $2) / n, '"$(nproc)"' * 3600 * n / ($1 + $2) }' "$tmp/cpu.txt")
fi
end=$(date +%s.%N)
kill "$sampler" 2>/dev/null
grep -h 'students (' "$tmp/local.log" "$tmp/out/work/slurm/final.log" 2>/dev/null | tail -n 1
awk -v n="$n" -v s="$start" -v e="$end" -v w="$where" -v c="$cpu" 'BEGIN {
    printf "%s: %d submissions in %.0f s wall: %.0f submissions per hour; %s\n", w, n, e - s, n * 3600 / (e - s), c }'
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
report_memory "$tmp/memory.txt"
