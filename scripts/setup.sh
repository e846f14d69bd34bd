#!/usr/bin/env bash
# OpenTOP set-up for a Debian 12 or 13 machine, run as root from the source tree.
#   scripts/setup.sh gui   install what is missing, build, open the GUI on a simulated bus
#   scripts/setup.sh test  install what is missing, build, run the whole test suite
#   scripts/setup.sh build install what is missing and build (for scripts such as the package check)
# All are idempotent: packages already present are not reinstalled, and an up-to-date build
# does nothing. OPENTOP_GUI_QUIT_AFTER=SECONDS makes the GUI quit by itself (for checks).
set -euo pipefail
{ # read to the closing brace before anything runs: editing this file mid-run is harmless

mode="${1:-}"
case "$mode" in
gui | test | build) ;;
*)
    echo "usage: $0 gui|test|build" >&2
    exit 2
    ;;
esac

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${OPENTOP_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"

packages=(
    # compiler and build
    build-essential cmake ninja-build pkg-config ccache
    # CPack's Debian package generator runs file(1) on every binary
    file
    # Qt 6: libqt6opengl6-dev is only *recommended* by qt6-base-dev, but Qt6Charts' CMake files
    # need it; with --no-install-recommends it has to be named.
    qt6-base-dev libqt6opengl6-dev qt6-serialport-dev qt6-charts-dev
    qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libmodbus-dev libgtest-dev libgmock-dev
    # the end-of-line results database: QtSql's SQLite and PostgreSQL drivers; the PostgreSQL
    # server programs the tests start a throw-away cluster with (they never use the package's
    # "main" cluster), and poppler's pdftotext, which reads the certificate PDF back in the tests
    libqt6sql6-sqlite libqt6sql6-psql postgresql poppler-utils
    # independent Modbus peers the tests cross-check against
    mbpoll socat python3-pymodbus
    # the GUI without a display: a virtual X server, its auth, a screenshot tool and fonts
    xvfb xauth imagemagick fonts-dejavu-core
    # the program in Chinese, Korean and Japanese: CJK glyphs (no text as boxes) and Qt's own
    # translations (standard dialog buttons)
    fonts-noto-cjk qt6-translations-l10n
)

# Installed, or provided by an installed package (Debian 13's qt6-base-dev provides
# libqt6opengl6-dev, which is no real package there: asking dpkg for it says "not installed").
# grep without -q reads all its input, so that pipefail sees no SIGPIPE.
installed() {
    dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep "install ok installed" >/dev/null ||
        dpkg-query -W -f='${Status}\t${Provides}\n' 2>/dev/null | grep "^install ok installed" |
        cut -f2 | tr ',' '\n' | sed 's/(.*//; s/:.*//; s/ //g' | grep -x -- "$1" >/dev/null
}
missing=()
for p in "${packages[@]}"; do
    if ! installed "$p"; then
        missing+=("$p")
    fi
done
if ((${#missing[@]})); then
    echo "== installing: ${missing[*]}"
    if [ "$(id -u)" -ne 0 ]; then
        echo "error: packages are missing and this is not root; run as root or install: ${missing[*]}" >&2
        exit 1
    fi
    apt-get update -q
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOPENTOP_WERROR=ON
fi
echo "== building in $build"
cmake --build "$build" -j "$jobs"

if [ "$mode" = build ]; then
    exit 0
fi
if [ "$mode" = test ]; then
    echo "== running the test suite"
    cd "$build"
    exec ctest --output-on-failure --timeout 300 -j "$jobs"
fi

sim_bus="${OPENTOP_SIM_BUS:-dbu200@1,dbu400@150,dcpid@7}"
gui_args=(--sim "$sim_bus")
if [ -n "${OPENTOP_GUI_QUIT_AFTER:-}" ]; then
    gui_args+=(--quit-after "$OPENTOP_GUI_QUIT_AFTER")
fi
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    exec "$build/app/opentop" "${gui_args[@]}"
fi
# No display (e.g. an ssh session): run the real program under Xvfb and save a screenshot.
shot="$build/opentop-screenshot.png"
echo "== no display found: starting OpenTOP under Xvfb; screenshot in $shot (Ctrl-C to stop)"
exec xvfb-run -a -s "-screen 0 1600x1000x24" bash -c '
    app_bin=$1 shot=$2; shift 2
    "$app_bin" "$@" & app=$!
    sleep 4; import -window root "$shot" && echo "screenshot saved: $shot"
    wait $app' bash "$build/app/opentop" "$shot" "${gui_args[@]}"
}
