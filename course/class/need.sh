#!/bin/sh
# Instructor tooling: not part of any assignment.
# What bin/grade-class links beyond the student's libraries: Debian's libarchive-dev (reading zips
# and folders entry by entry, every entry checked before a byte is written) and libssl-dev
# (libcrypto's HMAC-SHA256 for the seeds). Installed here, as root, when pkg-config finds them
# missing; otherwise says what to install. (make grade-class, make test-grade-class)
set -eu
pkg-config --exists libarchive libcrypto 2>/dev/null && exit 0
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    echo "grade-class: installing libarchive-dev and libssl-dev (Debian's)"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libarchive-dev libssl-dev >/dev/null 2>&1 ||
        { apt-get update -qq >/dev/null 2>&1 &&
          DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libarchive-dev libssl-dev >/dev/null; }
fi
pkg-config --exists libarchive libcrypto 2>/dev/null ||
    { echo "grade-class: needs libarchive and libcrypto (Debian: apt-get install libarchive-dev libssl-dev)" >&2; exit 1; }
