#!/bin/sh
# Test machinery: builds follow content, not dates, and never mix compilers (make test-fresh-build).
# In a scratch copy of the tree, with the solution's part 5:
#   1. make test-part5 passes;
#   2. adaptive.c replaced by a wrong one (1.96 -> 0.5) dated in the past (cp -a, an unzip): the suite
#      must fail, so the stale objects of the right code were not kept;
#   3. the right adaptive.c put back, dated in the past too: the suite passes again;
#   4. make CC=clang test-part5 after the gcc build: passes, and no linker message about objects of
#      the other compiler ("plugin needed", "file format not recognized");
#   5. make test-part5 with the default compiler again: passes, relinked from its own objects.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
scratch="$root/build/fresh-build"
fail() { echo "test-fresh-build: FAILED: $*"; exit 1; }
. "$root/tests/common/need.sh"
need clang clang test-fresh-build
rm -rf "$scratch"
mkdir -p "$scratch"
(cd "$root" && cp -a Makefile framework grader parts tests scenes third_party tools "$scratch"/)  # grader: make test-part<N> inspects the part first (bin/inspect-part)
cd "$scratch" || exit 1
file=parts/part5_adaptive/adaptive.c
cp -p "$file" right.c
sed 's/1\.96/0.5/' right.c > wrong.c
cmp -s right.c wrong.c && fail "could not make the wrong adaptive.c (the solution no longer holds 1.96)"
log=log.txt
run() { make -j2 --no-print-directory "$@" > "$log" 2>&1; }
run test-part5 || { tail -20 "$log"; fail "1. the solution's part 5 suite fails"; }
echo "  1. the suite passes"
cp wrong.c "$file"; touch -d '2001-01-01' "$file"
run test-part5 && fail "2. a wrong adaptive.c dated 2001 left the suite green: its old objects were kept"
echo "  2. a wrong adaptive.c dated 2001 is rebuilt: the suite fails"
cp right.c "$file"; touch -d '2001-01-01' "$file"
run test-part5 || { tail -20 "$log"; fail "3. the right adaptive.c put back, dated 2001: the suite fails"; }
echo "  3. the right one put back, dated 2001: the suite passes"
run CC=clang test-part5 || { tail -20 "$log"; fail "4. make CC=clang test-part5 after a gcc build fails"; }
grep -qE "plugin needed|file format not recognized" "$log" && fail "4. CC=clang met objects of the other compiler"
echo "  4. CC=clang after a gcc build: its own objects, the suite passes"
run test-part5 || { tail -20 "$log"; fail "5. back to the default compiler, the suite fails"; }
grep -qE "plugin needed|file format not recognized" "$log" && fail "5. the default compiler met clang's objects"
echo "  5. back to the default compiler: the suite passes"
echo "test-fresh-build: passed"
