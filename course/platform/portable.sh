#!/bin/sh
# make test-portable: a student's laptop, imitated on this Debian machine (README.md, "Platforms").
#  (a) the student release (release/student, from make release) with every part solved, built with
#      gcc and with clang, each with -std=c11 -D_POSIX_C_SOURCE=200809L -Werror and a pkg-config
#      that knows no stb (as on Homebrew): every compile line has those flags and the vendored stb,
#      none has _GNU_SOURCE but the autograder's Linux-only files (the Makefile's LINUX_SRC), none
#      the system's stb; bin/grade builds; the framework and part suites pass;
#  (b) a pkg-config that says OpenEXR 2.5 (Ubuntu 22.04): the build stops before compiling anything,
#      with one message naming the way out; one that lacks jansson: the build names it and tools/setup;
#  (c) tools/setup on what it cannot install on (Ubuntu 22.04, Fedora, FreeBSD, macOS without
#      Xcode's tools): exit status 1 and the list of what the build needs;
#  (d) the release ships the devcontainer.
# Scratch trees in release/portable/. Ends with "N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
OUT=release/portable
STUDENT=release/student
passed=0 failed=0
pass() { passed=$((passed + 1)); echo "  ok    $1"; }
fail() { failed=$((failed + 1)); echo "  FAIL  $1"; [ -z "${2:-}" ] || sed 's/^/        /' "$2" | tail -n 20; }
[ -d "$STUDENT" ] || { echo "portable: no $STUDENT: run make release first" >&2; exit 2; }
rm -rf "$OUT" && mkdir -p "$OUT/fake" || exit 2
REAL_PKG_CONFIG=$(command -v pkg-config) || { echo "portable: no pkg-config" >&2; exit 2; }

# A pkg-config as on another machine, in folder $1: the packages in $2 do not exist; OpenEXR has
# version $3 when given. Everything else is the real pkg-config's answer.
fake_pkg_config() {
    mkdir -p "$1"
    cat >"$1/pkg-config" <<EOF
#!/bin/sh
for a in "\$@"; do
    for m in $2; do [ "\$a" = "\$m" ] && { echo "Package \$m was not found" >&2; exit 1; }; done
done
exr='${3:-}'
case " \$* " in
    *" OpenEXR "*) if [ -n "\$exr" ]; then
        case "\$1" in
            --modversion) echo "\$exr"; exit 0 ;;
            --atleast-version=*) [ "\$(printf '%s\n%s\n' "\${1#*=}" "\$exr" | sort -V | head -n 1)" = "\${1#*=}" ]; exit ;;
        esac
    fi ;;
esac
exec "$REAL_PKG_CONFIG" "\$@"
EOF
    chmod 755 "$1/pkg-config"
}

# (a) The release, solved, with compiler $1: strict flags on every compile line, then the suites.
strict_build() {
    cc=$1 tree=$OUT/$1 log=$OUT/$1.log
    command -v "$cc" >/dev/null || { fail "($cc) no $cc on this machine"; return; }
    cp -a "$STUDENT" "$tree" || { fail "($cc) cannot copy the release"; return; }
    suites=framework
    for d in "$STUDENT"/parts/part*_*/; do  # the release's parts (the course's), solved
        d=$(basename "$d") && suites="$suites ${d%%_*}"
        cp -a "parts/$d/." "$tree/parts/$d/" || { fail "($cc) cannot copy parts/$d"; return; }
    done
    if ! PATH="$PWD/$OUT/fake/no-stb:$PATH" make -C "$tree" -j2 V=1 CC="$cc" WERROR=1 all bin/grade bin/imgtool \
        $(for s in $suites; do echo "bin/test-$s"; done) >"$log" 2>&1; then
        fail "($cc) the release builds with -Werror" "$log"; return
    fi
    grep -E "^$cc .* -c -o " "$log" >"$log.cc"
    linux_only=$(make -C "$tree" -s --no-print-directory -f Makefile -f - print-linux-src <<'EOF'
print-linux-src: ; @echo $(LINUX_SRC)
EOF
)
    bad=$(awk -v linux_only=" $linux_only " '
        { file = $NF; linux = index(linux_only, " " file " ") > 0
          ok = / -std=c11 / && / -Werror / && / -Ithird_party\/stb / && (linux || / -D_POSIX_C_SOURCE=200809L /)
          if (!ok || (/ -D_GNU_SOURCE/ && !linux) || /\/usr\/include\/stb/) print file }' "$log.cc")
    if [ ! -s "$log.cc" ] || [ -n "$bad" ]; then
        fail "($cc) every file compiled strict, vendored stb, no _GNU_SOURCE: not $(echo $bad)"
    else
        pass "($cc) $(wc -l <"$log.cc") files compiled with -std=c11 -D_POSIX_C_SOURCE=200809L -Werror and the vendored stb (Linux-only: $linux_only)"
    fi
    for s in $suites; do
        if PATH="$PWD/$OUT/fake/no-stb:$PATH" make -C "$tree" CC="$cc" WERROR=1 "test-$s" >"$OUT/$cc-$s.log" 2>&1
        then pass "($cc) make test-$s"
        else fail "($cc) make test-$s" "$OUT/$cc-$s.log"
        fi
    done
}

# (b) The build with a pkg-config that says $2 (fake folder $1): fails, compiles nothing, says $3
# and $4.
refused_build() {
    log=$OUT/$1.log
    touch "$OUT/gcc/framework/vec.h"  # every object out of date: a compile would show
    if PATH="$PWD/$OUT/fake/$1:$PATH" make -C "$OUT/gcc" CC=gcc >"$log" 2>&1; then
        fail "(b) $2: the build should stop" "$log"
    elif grep -q '^  CC ' "$log" || ! grep -qF "$3" "$log" || ! grep -qF "$4" "$log"; then
        fail "(b) $2: expected no compile, '$3' and '$4'" "$log"
    else
        pass "(b) $2: stops before compiling: $(grep -o '\*\*\* .*' "$log" | cut -c5-90)..."
    fi
}

# (c) tools/setup on a platform it does not install on: exit 1, saying $3 and listing the libraries.
refused_setup() {
    log=$OUT/setup-$1.log
    printf '%s\n' "$2" >"$OUT/os-release-$1"
    PL_SETUP_UNAME=${4:-Linux} PL_SETUP_OS_RELEASE="$PWD/$OUT/os-release-$1" sh "$STUDENT/tools/setup" >"$log" 2>&1
    code=$?
    if [ "$code" = 1 ] && grep -qF "$3" "$log" && grep -q 'OpenEXR 3.1 or later' "$log"; then
        pass "(c) tools/setup on $1: exit 1, '$3' and the list"
    else
        fail "(c) tools/setup on $1: expected exit 1, '$3' and the list (exit $code)" "$log"
    fi
}

fake_pkg_config "$OUT/fake/no-stb" "stb"
fake_pkg_config "$OUT/fake/exr25" "" 2.5.0
fake_pkg_config "$OUT/fake/no-jansson" "jansson"
echo "== (a) the release, solved, strict C11 + POSIX, vendored stb"
strict_build gcc
strict_build clang
echo "== (b) what the build says on machines it cannot build on"
if [ -d "$OUT/gcc" ]; then
    refused_build exr25 "OpenEXR 2.5" "OpenEXR 2.5.0 is too old: pathlab needs 3.1 or later" "use Ubuntu 24.04"
    refused_build no-jansson "no jansson" 'pkg-config finds no jansson' 'run `sh tools/setup`'
else
    fail "(b) no gcc tree to build in"
fi
echo "== (c) tools/setup where it cannot install"
refused_setup ubuntu-22.04 'ID=ubuntu
VERSION_ID="22.04"
PRETTY_NAME="Ubuntu 22.04.4 LTS"' "Ubuntu 22.04.4 LTS is too old: Ubuntu 24.04 or later"
refused_setup fedora 'ID=fedora
VERSION_ID=40
PRETTY_NAME="Fedora Linux 40"' "Fedora Linux 40: no installer here"
refused_setup freebsd '' "FreeBSD: no installer here" FreeBSD
refused_setup macos-without-xcode '' "xcode-select --install" Darwin
echo "== (d) the devcontainer"
if cmp -s .devcontainer/devcontainer.json "$STUDENT/.devcontainer/devcontainer.json"; then
    pass "(d) the release ships .devcontainer/devcontainer.json"
else
    fail "(d) the release ships .devcontainer/devcontainer.json"
fi
echo "portable: $passed passed, $failed failed"
[ "$failed" = 0 ]
