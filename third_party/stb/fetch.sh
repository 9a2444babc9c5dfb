#!/bin/sh
# Re-fetches stb's two image headers from Debian's package libstb-dev and checks they are the
# vendored copies.
#   third_party/stb/fetch.sh          verify: download, check hashes, compare with the files here
#   third_party/stb/fetch.sh --update replace the files here (after you change VERSION/hashes below)
# Why vendored: Homebrew has no stb formula; the build takes the system's stb where pkg-config finds
# one (Debian, Ubuntu) and these copies elsewhere (the Makefile's STB setting).
# Needs Debian or Ubuntu (apt-get, dpkg-deb): apt-get download checks the package against Debian's
# signed index; the headers' SHA-256 below pin the files (the package's own hash varies by CPU).
set -eu
VERSION=0.0~git20220908.8b5f1f3+ds-1
IMAGE_SHA256=91f435e0fc6a620018b878b9859c74dff60d28046f87e649191ad6f35a98c722
WRITE_SHA256=cbd5f0ad7a9cf4468affb36354a1d2338034f2c12473cf1a8e32053cb6914a05

here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
chmod 755 "$work"  # apt's download user writes here
cd "$work"
apt-get download -qq "libstb-dev=$VERSION"
dpkg-deb -x libstb-dev_*.deb pkg
inc=pkg/usr/include/stb
echo "$IMAGE_SHA256  $inc/stb_image.h" | sha256sum -c --quiet
echo "$WRITE_SHA256  $inc/stb_image_write.h" | sha256sum -c --quiet
if [ "${1:-}" = "--update" ]; then
    cp "$inc/stb_image.h" "$inc/stb_image_write.h" "$here/"
    echo "stb: updated to Debian libstb-dev $VERSION"
else
    cmp "$inc/stb_image.h" "$here/stb_image.h"
    cmp "$inc/stb_image_write.h" "$here/stb_image_write.h"
    echo "stb: the vendored files are Debian libstb-dev $VERSION, hashes checked"
fi
