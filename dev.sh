#!/usr/bin/env bash
# One entry point for a fresh Debian machine:
#   ./dev.sh            install the Debian packages, build, open the TUI on presets/7008C.ini
#   ./dev.sh test       install, build, run every test suite (fast, slow, slurm, install)
#   ./dev.sh run ARGS   install, build, run `acbb ARGS` (e.g. run presets/7008C.ini --json)
set -eu
cd "$(dirname "$0")"

PACKAGES="build-essential meson ninja-build pkg-config libgsl-dev libinih-dev libncurses-dev libcjson-dev
          gnuplot-nox jq tmux python3 python3-jsonschema libxml2-utils locales"

install_deps() {
    missing=""
    for p in $PACKAGES; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
            || missing="$missing $p"
    done
    [ -z "$missing" ] && return 0
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    # shellcheck disable=SC2086
    $sudo apt-get install -y -qq $missing >/dev/null
}

# Quiet when all goes well, the whole compiler output when it does not
# (issue 28 item 11: a compile error used to exit 1 with nothing printed).
build() {
    log=$(mktemp)
    if [ ! -f build/build.ninja ]; then
        echo "dev.sh: configuring and building acbb (the first build takes about a minute)..." >&2
        meson setup build -Dwerror=true >"$log" 2>&1 || { cat "$log" >&2; rm -f "$log"; exit 1; }
    fi
    meson compile -C build >"$log" 2>&1 || {
        cat "$log" >&2
        echo "dev.sh: the build failed (output above)" >&2
        rm -f "$log"
        exit 1
    }
    rm -f "$log"
}

install_deps
build
case "${1:-tui}" in
    tui) shift 2>/dev/null || true; exec ./build/acbb tui "$@" ;;
    test)
        # Every suite: the fast default (under a minute), the TUI's, the
        # seed's studies and reports, the slow
        # fidelity matrix, the Slurm/GNU parallel sweep (they skip what
        # this machine lacks) and the library's install suite (DESTDIR,
        # pkg-config example, Python). Fuzzing needs clang: see README.
        rc=0
        meson test -C build --print-errorlogs || rc=1
        # The tmux TUI tests mostly wait on a terminal: four at once.
        meson test -C build --suite tui --num-processes 4 --logbase tuilog --print-errorlogs || rc=1
        meson test -C build --suite studies --logbase studylog --print-errorlogs || rc=1
        meson test -C build --suite slow --logbase slowlog --print-errorlogs || rc=1
        meson test -C build --suite slurm --logbase slurmlog --print-errorlogs || rc=1
        # meson counts a TAP test whose checks say "# SKIP" as OK: say how
        # many of the Slurm suite's checks really ran (issue 21 item 13).
        log=build/meson-logs/slurmlog.txt
        if [ -f "$log" ]; then
            # grep -c exits 1 on a count of 0: not a failure here (set -e)
            total=$(grep -c '^ok [0-9]* \|^not ok [0-9]* ' "$log" || true)
            skipped=$(grep -c '^ok [0-9]* .*# SKIP' "$log" || true)
            echo "Slurm suite: $((total - skipped)) of $total checks ran, $skipped skipped:"
            grep '^ok [0-9]* .*# SKIP' "$log" | sed 's/^ok [0-9]* - /  skipped: /' | sort -u || true
        fi
        meson test -C build --suite install --logbase installlog --print-errorlogs || rc=1
        exit $rc ;;
    run) shift; exec ./build/acbb "$@" ;;
    *) echo "usage: ./dev.sh [tui [PRESET] | test | run ARGS...]" >&2; exit 2 ;;
esac
