#!/bin/bash
# Gradescope's image setup (the autograder bundle's setup.sh; instructor tooling, not in the student
# release). Gradescope runs it once, as root, when it builds the autograder image, with the bundle
# unzipped in /autograder/source. It installs the Debian/Ubuntu packages the build needs (the one
# list in tools/setup, libseccomp-dev among them for the sandbox) and builds the renderer and the
# grader, and the course's objects with the grader's flags (bin/grade --prebuild, out/grader-prebuild,
# root's alone), so that run_autograder only grades.
set -euo pipefail
cd "$(dirname "$0")"

missing=
for p in $(sh tools/setup --print-build-packages); do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "setup.sh: installing:$missing"
    if [ "$(id -u)" = 0 ]; then sudo=""; else sudo="sudo"; fi
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
fi

# The grader drops student code to this user when it runs as root (Gradescope's images have it).
id nobody >/dev/null 2>&1 || echo "setup.sh: warning: no user 'nobody': student code would run as root" >&2

make -j"$(nproc 2>/dev/null || echo 2)" all bin/grade
# The course's objects with the grader's flags, once: each grading then only copies and links them.
bin/grade --prebuild
echo "setup.sh: built $(cat VERSION 2>/dev/null || echo pathlab); run_autograder grades /autograder/submission"
