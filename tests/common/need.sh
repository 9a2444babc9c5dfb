# Test machinery, sourced by the shell tests: `need COMMAND PACKAGE TEST` makes sure COMMAND exists
# before TEST uses it. A missing one is installed from Debian's PACKAGE when the test runs as root (CI,
# a fresh machine); otherwise TEST prints that it is skipped, and why, and exits 0: a tool missing
# here says nothing about what TEST checks, and a student without root must not see a failure.
need() {
    command -v "$1" >/dev/null && return 0
    if [ "$(id -u)" != 0 ]; then
        echo "$3: SKIPPED: $1 is missing and installing it ($2) needs root"
        exit 0
    fi
    echo "$3: installing $2"
    # The package lists of a fresh machine may be stale or absent: update them only when needed.
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$2" >/dev/null 2>&1 ||
        { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$2" >/dev/null; }
}
