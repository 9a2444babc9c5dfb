#!/bin/sh
# Re-fetches lodepng's C source from the npm package `lodepng` and checks it is the vendored copy.
#   third_party/lodepng/fetch.sh          verify: fetch, check hashes, compare with the files here
#   third_party/lodepng/fetch.sh --update replace the files here (after you change VERSION/hashes below)
# Why vendored: Debian packages lodepng only as a C++ build; the grader is C.
set -eu
VERSION=2.3.0
TGZ_SHA256=a89c5b358d7df778a72489479c9977fb58305caa905a1b3afe1d6481667a3680
C_SHA256=4a6a2e6432877d64541cf244e20e646b6539c00f57b17751faeaaa553f699f69
H_SHA256=f761b2bbc5ea479da03cc8d8d365d8eac53c327884573e5831f6d379c7f1b071

here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work"
npm pack --silent "lodepng@$VERSION" >/dev/null
echo "$TGZ_SHA256  lodepng-$VERSION.tgz" | sha256sum -c --quiet
tar xzf "lodepng-$VERSION.tgz" package/vendor/lodepng.c package/vendor/lodepng.h
echo "$C_SHA256  package/vendor/lodepng.c" | sha256sum -c --quiet
echo "$H_SHA256  package/vendor/lodepng.h" | sha256sum -c --quiet
if [ "${1:-}" = "--update" ]; then
    cp package/vendor/lodepng.c package/vendor/lodepng.h "$here/"
    echo "lodepng: updated to npm lodepng@$VERSION"
else
    cmp package/vendor/lodepng.c "$here/lodepng.c"
    cmp package/vendor/lodepng.h "$here/lodepng.h"
    echo "lodepng: the vendored files are npm lodepng@$VERSION, hashes checked"
fi
