#!/bin/sh
# Test machinery: the grader's HTML report opened in a real browser (headless Chromium from Debian)
# and screenshotted. Grades this tree's part 1 (public cases, against reference_images/),
# then checks the page loads its pictures, shows a verdict per case, and renders to a non-blank
# screenshot (out/report-test/screenshot.png, worth a look). Installs chromium when root and missing;
# otherwise skips with the reason. Run it with `make test-report`.
set -eu
cd "$(dirname "$0")/../.."
out=out/report-test
. tests/common/need.sh
need chromium chromium test-report
fail() { echo "test-report: FAILED: $*"; exit 1; }
rm -rf "$out"
mkdir -p out
bin/grade --out "$out" --parts 1 --seed 7 >"$out.log" 2>&1 || true
page="$out/report/index.html"
[ -f "$page" ] || fail "no report at $page (see $out.log)"
grep -q "spheres_normals" "$page" || fail "the report does not name the case spheres_normals"
for img in $(sed -n 's/.*<img src="\([^"]*\)".*/\1/p' "$page" | tr ' ' '\n' | sed -n 's/.*src="\([^"]*\)".*/\1/p'); do
    [ -s "$out/report/$img" ] || fail "the report shows $img, which is missing"
done
n=$(grep -o '<img src="' "$page" | wc -l)
[ "$n" -ge 3 ] || fail "expected at least one case with its three pictures, found $n pictures"
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1280,1600 \
    --screenshot="$PWD/$out/screenshot.png" "file://$PWD/$page" >/dev/null 2>&1 || fail "chromium could not render the page"
[ -s "$out/screenshot.png" ] || fail "no screenshot"
bin/imgtool stats "$out/screenshot.png" >/dev/null || fail "the screenshot is not a PNG"
echo "test-report: passed: $n pictures; screenshot in $out/screenshot.png"
