#!/bin/sh
# Test machinery: not part of any assignment.
# A class made of the course's catalogues, for the class grader's test and benchmark: each patch
# (course/mutants/*.patch: a realistic bug; course/alternatives/*.patch: a correct implementation
# that is not the solution) applied to a copy of the solution's parts/, as the submission folder
# DIR/<the patch's name>/parts; "solution" names the solution itself. A name followed by ".zip"
# makes that submission a zip of a repository-like folder (parts/ one folder down), as a zipped
# clone comes.
#   course/class/make_class.sh DIR NAME[.zip] ...   NAME: a patch's name (no folder, no .patch) or solution
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:?usage: make_class.sh DIR NAME[.zip] ...}
shift
mkdir -p "$dir"
for arg in "$@"; do
    name=${arg%.zip}
    sub=$(mktemp -d "${TMPDIR:-/tmp}/pathlab-class-sub.XXXXXX")
    mkdir -p "$sub/$name-main"
    cp -a "$root/parts" "$sub/$name-main/"
    if [ "$name" != solution ]; then
        patch=$(ls "$root"/course/mutants/"$name".patch "$root"/course/alternatives/"$name".patch 2>/dev/null | head -n 1)
        [ -n "$patch" ] || { echo "make_class.sh: no patch named $name" >&2; rm -rf "$sub"; exit 1; }
        patch -s -p1 -d "$sub/$name-main" <"$patch"
    fi
    if [ "$arg" != "$name" ]; then
        (cd "$sub" && zip -qr "$dir/$name.zip" "$name-main")
    else
        mkdir -p "$dir/$name" && mv "$sub/$name-main/parts" "$dir/$name/"
    fi
    rm -rf "$sub"
done
