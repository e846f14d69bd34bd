#!/usr/bin/env bash
# CI phase "windows": cross-builds OpenTOP for Windows (scripts/build-windows.sh) and proves the
# result under Wine against the Linux programs, on a Modbus TCP bus and on a COM port:
#
#   scripts/check-windows.sh
#
#   1. packages     the Debian packages the cross build and the checks use, installed when missing
#                   (root); the MinGW Qt toolchain unpacked to /opt/qt6-mingw when it is not there
#   2. build        scripts/build-windows.sh: build, stage, installer, zip (incremental)
#   3. prefix       a fresh Wine prefix of its own: <build>/wine-prefix
#   4. tcp          Linux opentop-sim --tcp; opentop-cli.exe under Wine and the Linux opentop-cli
#                   each scan, back up, compare and restore: the same tables, the same backups
#                   (apart from "created" and "checksum"), no differences, nothing to write; a
#                   setting changed from Linux is written back by the Windows restore
#   5. com          Linux opentop-sim --pty; COM5 in the prefix is its pty: scan, backup and
#                   compare through libmodbus' Win32 serial code, equal to the Linux CLI on the
#                   same pty (the backups differ in "created", "checksum" and the port name)
#   6. gui          opentop.exe --tcp on Xvfb (1366x768) with Qt's freetype font engine (Wine's
#                   GDI draws no QLineEdit/QSpinBox text): it scans, monitors the drives and quits
#                   by itself; its screenshot (<build>/opentop-wine.png) must not be blank and
#                   must show the drives in the bus list and the numbers in the scan range boxes
#   7. installer    silent install, the installed opentop-cli.exe --version, silent uninstall:
#                   drive_c holds the same files as before and the Uninstall key is gone
#
# Where ../shared/toolchains or its Qt archive is missing, it says so in one line and exits 0.
# It ends with the time of each step; on a failure, with the reason in one line (exit 1).
#
# Environment:
#   LINUX_BIN_DIR=build/app          the Linux opentop-cli and opentop-sim (relative: to the repo)
#   OPENTOP_WIN_BUILD=<repo>/build-win   the Windows build folder (build-windows.sh reads it too)
#   OPENTOP_QT_MINGW=/opt/qt6-mingw  where the toolchain is (build-windows.sh reads it too)
#   OPENTOP_GUI_QUIT_AFTER=45        seconds after which the window quits by itself (--quit-after);
#                                    it must have scanned and be monitoring before
set -euo pipefail
{ # read to the closing brace before anything runs: editing this file mid-run is harmless

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
toolchains="$repo/../shared/toolchains"
archive="$toolchains/qt6.4.2-mingw-w64-x86_64.tar.zst"
if [ ! -d "$toolchains" ]; then
    echo "windows: skipped: no ../shared/toolchains beside the repository (the MinGW Qt toolchain)"
    exit 0
fi
if [ ! -f "$archive" ]; then
    echo "windows: skipped: no ../shared/toolchains/$(basename "$archive") (the MinGW Qt toolchain)"
    exit 0
fi
toolchains="$(cd "$toolchains" && pwd)"
archive="$toolchains/$(basename "$archive")"

qt="${OPENTOP_QT_MINGW:-/opt/qt6-mingw}"
build="${OPENTOP_WIN_BUILD:-$repo/build-win}"
linux_bin="${LINUX_BIN_DIR:-build/app}"
[[ "$linux_bin" = /* ]] || linux_bin="$repo/$linux_bin"
quit_after="${OPENTOP_GUI_QUIT_AFTER:-45}"
devices="dbu200@1,dbu400@150,dcpid@7"
read -r -a ids <<<"$(tr ',' '\n' <<<"$devices" | sed 's/.*@//' | tr '\n' ' ')"
work="$build/check-windows"
prefix="$build/wine-prefix"
pty_link="/tmp/opentop-check-windows.$$.pty"
cli_timeout=240 # seconds for one command-line run (a cold Wine and a full scan: about 30)

# --- phase timing (as scripts/check-fresh-machine.sh) -------------------------------------------
phase_names=()
phase_secs=()
phase_start=0
phase_name=""
failure=""
begin() {
    phase_name="$1"
    phase_start=$SECONDS
    echo
    echo "== [$(date +%H:%M:%S)] $1"
}
end() {
    local took=$((SECONDS - phase_start))
    phase_names+=("$phase_name")
    phase_secs+=("$took")
    echo "== $phase_name: ${took} s"
    phase_name=""
}
report_phases() {
    echo
    echo "== time per step"
    local i total=0
    for i in "${!phase_names[@]}"; do
        printf '   %-78s %5d s\n' "${phase_names[$i]}" "${phase_secs[$i]}"
        total=$((total + phase_secs[i]))
    done
    printf '   %-78s %5d s\n' "total" "$total"
}
fail() {
    failure="$*"
    exit 1
}

# --- processes of this check, ended by their ids ------------------------------------------------
sim_pid=""
xvfb_pid=""
gui_pid=""
stop() { # stop PID: TERM, then KILL if it is still there after 5 s
    local pid="$1" i
    [ -n "$pid" ] || return 0
    kill "$pid" 2>/dev/null || return 0
    for i in $(seq 50); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
}
cleanup() {
    local status=$?
    stop "$gui_pid"
    # Wine first: its server holds COM5's pty as its controlling terminal, and the simulator's
    # end would hang it up (wineserver then dumps its objects into a log)
    if [ -d "$prefix" ] && command -v wineserver >/dev/null; then
        WINEPREFIX="$prefix" wineserver -k 2>/dev/null || true
    fi
    stop "$sim_pid"
    stop "$xvfb_pid"
    rm -f "$pty_link"
    if [ "$status" -ne 0 ]; then
        if [ -n "$phase_name" ]; then
            phase_names+=("$phase_name (FAILED)")
            phase_secs+=("$((SECONDS - phase_start))")
        fi
        report_phases
        [ -n "$failure" ] || failure="a command failed (exit $status); see the lines above"
        echo "windows: FAILED${phase_name:+ in \"$phase_name\"}: $failure" >&2
    fi
    exit "$status"
}
trap cleanup EXIT
trap 'failure="interrupted"; exit 130' INT TERM HUP

# --- 1. packages and toolchain ------------------------------------------------------------------
begin "packages (Debian) and the MinGW Qt toolchain"
# The cross compilers (posix threads, as the toolchain was built with), the host Qt 6.4.2 whose
# moc/rcc/uic/lrelease the cross build runs, Wine (64-bit only: the installer is amd64 too),
# NSIS, and the check's own tools: a virtual display, screenshots and image statistics.
packages=(g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64
    mingw-w64-tools cmake ninja-build qt6-base-dev qt6-base-dev-tools qt6-tools-dev
    qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n wine wine64 nsis zip zstd xvfb
    imagemagick)
missing=()
for p in "${packages[@]}"; do
    [ "$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null)" = installed ] || missing+=("$p")
done
if ((${#missing[@]})); then
    [ "$(id -u)" -eq 0 ] || fail "packages missing and not root to install them: ${missing[*]}"
    echo "   installing: ${missing[*]}"
    mkdir -p "$build"
    apt-get update -q >"$build/check-windows-apt.log" 2>&1 ||
        fail "apt-get update failed (log: $build/check-windows-apt.log)"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}" \
        >>"$build/check-windows-apt.log" 2>&1 ||
        fail "apt-get install ${missing[*]} failed (log: $build/check-windows-apt.log)"
else
    echo "   all ${#packages[@]} packages installed"
fi
if [ -f "$qt/lib/cmake/Qt6/qt.toolchain.cmake" ]; then
    echo "   toolchain: $qt (already unpacked)"
else
    # The archive holds qt6-mingw/, and its CMake files name /opt/qt6-mingw.
    [ "$qt" = /opt/qt6-mingw ] ||
        fail "no toolchain at $qt (OPENTOP_QT_MINGW); the archive unpacks only to /opt/qt6-mingw"
    [ -w /opt ] || fail "no toolchain at /opt/qt6-mingw and /opt is not writable (not root?)"
    echo "   unpacking $(basename "$archive") to /opt"
    tar -C /opt -xf "$archive" || fail "could not unpack $archive"
    [ -f "$qt/lib/cmake/Qt6/qt.toolchain.cmake" ] || fail "$archive did not hold qt6-mingw/"
fi
for p in opentop-cli opentop-sim; do
    [ -x "$linux_bin/$p" ] || fail "no Linux $p in $linux_bin (LINUX_BIN_DIR): build it first"
done
end

# --- 2. the cross build -------------------------------------------------------------------------
begin "cross build: scripts/build-windows.sh (build, stage, installer, zip)"
mkdir -p "$build"
log="$build/check-windows-build.log"
OPENTOP_WIN_BUILD="$build" OPENTOP_QT_MINGW="$qt" bash "$repo/scripts/build-windows.sh" \
    >"$log" 2>&1 || {
    tail -n 30 "$log" >&2
    fail "scripts/build-windows.sh failed (log: $log)"
}
echo "   $(grep -cE '^\[[0-9]+/[0-9]+\] (Building|Linking)' "$log" || true) files compiled or linked"
sed -nE 's/^(build-windows: built|staged:|installer:|zip:)/   \1/p' "$log"
version="$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")"
stage="$build/stage/OpenTOP-$version-win64"
setup="$build/OpenTOP-$version-win64-setup.exe"
for f in "$stage/opentop.exe" "$stage/opentop-cli.exe" "$setup"; do
    [ -f "$f" ] || fail "the build made no $f"
done
end

# --- 3. a Wine prefix of this check's own -------------------------------------------------------
begin "fresh Wine prefix ($prefix)"
export WINEPREFIX="$prefix" WINEDEBUG=-all
# No Mono/Gecko prompts; no crash debugger: a crash ends the program with an error code (winedbg
# would wait, unseen, for someone to look).
export WINEDLLOVERRIDES="mscoree,mshtml=;winedbg.exe=d"
unset DISPLAY # only the window gets one (step 6)
if [ -d "$prefix" ]; then
    wineserver -k 2>/dev/null || true
    rm -rf "$prefix"
fi
rm -rf "$work"
mkdir -p "$work/linux-home"
wine wineboot -i >"$work/wineboot.log" 2>&1 || fail "wine wineboot -i failed (log: $work/wineboot.log)"
timeout 60 wineserver -w || true # the prefix written out before anything looks at it
[ -d "$prefix/drive_c/windows/system32" ] || fail "wineboot made no drive_c"
echo "   $(wine --version 2>/dev/null), prefix $(du -sh "$prefix" | cut -f1)"
end

cd "$work" # Windows and Linux programs alike write their files here (Wine: Z:\...)
# The Linux programs keep their settings (the scan memory) and late-reply journals in here too.
lin_env=(env HOME="$work/linux-home" XDG_CONFIG_HOME="$work/linux-home/config"
    XDG_DATA_HOME="$work/linux-home/data" XDG_CACHE_HOME="$work/linux-home/cache"
    XDG_STATE_HOME="$work/linux-home/state" OPENTOP_LATE_JOURNAL_DIR="$work/linux-home/late")

# run LABEL EXPECTED_EXIT COMMAND...: stdout to LABEL.out (without carriage returns), stderr to
# LABEL.err; fails unless it exits EXPECTED_EXIT
run() {
    local label="$1" expected="$2" rc=0
    shift 2
    timeout -k 5 "$cli_timeout" "$@" </dev/null >"$work/$label.raw" 2>"$work/$label.err" || rc=$?
    tr -d '\r' <"$work/$label.raw" >"$work/$label.out"
    rm -f "$work/$label.raw"
    if [ "$rc" -ne "$expected" ]; then
        tail -n 5 "$work/$label.out" "$work/$label.err" | sed 's/^/   | /' >&2
        fail "$label: exit $rc, expected $expected: $(grep -v '^$' "$work/$label.err" | tail -n 1)"
    fi
}
win() { run "win-$1" 0 wine "$stage/opentop-cli.exe" "${@:2}"; }
lin() { run "lin-$1" 0 "${lin_env[@]}" "$linux_bin/opentop-cli" "${@:2}"; }

# start_sim LABEL ARGS...: the Linux simulator, until it says "ready"
start_sim() {
    local label="$1" i
    shift
    "${lin_env[@]}" "$linux_bin/opentop-sim" --devices "$devices" --quiet "$@" \
        </dev/null >"$work/$label.out" 2>"$work/$label.err" &
    sim_pid=$!
    for i in $(seq 100); do
        grep -qx ready "$work/$label.out" && return 0
        kill -0 "$sim_pid" 2>/dev/null || break
        sleep 0.1
    done
    cat "$work/$label.err" >&2
    fail "opentop-sim $* did not start"
}

# scans_equal A B: the same table and total, apart from the time the scan took
scans_equal() {
    local a="$work/$1.out" b="$work/$2.out" n
    n="$(grep -cE '^ *[0-9]+ +[0-9A-F]{2}h ' "$a" || true)"
    [ "$n" -eq "${#ids[@]}" ] || fail "$1 found $n drives, not ${#ids[@]}: $(tail -n 1 "$a")"
    diff <(sed -E 's/ in [0-9.]+ s$//' "$a") <(sed -E 's/ in [0-9.]+ s$//' "$b") >"$work/$1.diff" || {
        sed 's/^/   | /' "$work/$1.diff" >&2
        fail "the scan tables of $1 and $2 differ"
    }
    echo "   scan: $n drives, the same table (Windows: $(sed -n 's/.* found in //p' "$a"), Linux: $(sed -n 's/.* found in //p' "$b"))"
}

# backups_equal WIN LIN FIELD...: the two backup files are the same apart from the given fields
# (which are listed as found); each program reads the other's file (format and checksum) and
# finds no differences, drive by drive
backups_equal() {
    local w="$1" l="$2" fields pattern id
    shift 2
    fields="$({ diff "$w" "$l" || true; } | sed -n 's/^< *"\([A-Za-z]*\)":.*/\1/p' | sort -u | tr '\n' ' ')"
    pattern="$(
        IFS='|'
        echo "$*"
    )"
    diff <(sed -E "s/^( *\"($pattern)\": ).*/\1…/" "$w") <(sed -E "s/^( *\"($pattern)\": ).*/\1…/" "$l") \
        >"$work/$w.diff" || {
        sed -n '1,20s/^/   | /p' "$work/$w.diff" >&2
        fail "$w and $l differ in more than ${*}"
    }
    echo "   backup: $(grep -c '"slave":' "$w") drives, $(grep -c '"address":' "$w") settings; the files differ in: ${fields:-nothing} (allowed: $*)"
    for id in "${ids[@]}"; do
        win "compare-files-$id" compare "$l:$id" "$w:$id"
        grep -q '^no differences' "$work/win-compare-files-$id.out" || fail "Windows: $l:$id and $w:$id differ"
        lin "compare-files-$id" compare "$w:$id" "$l:$id"
        grep -q '^no differences' "$work/lin-compare-files-$id.out" || fail "Linux: $w:$id and $l:$id differ"
    done
    echo "   each program reads the other's backup: no differences on any drive"
}

# compares_clean SIDE CONNECTION... : SIDE's compare of each drive with SIDE's backup file finds
# no difference
compares_clean() {
    local side="$1" file="$2" id
    shift 2
    for id in "${ids[@]}"; do
        "$side" "compare-$file-$id" "$@" compare "$id" "$file:$id"
        grep -q '^no differences' "$work/$side-compare-$file-$id.out" ||
            fail "$side: drive $id differs from $file:$id: $(head -n 5 "$work/$side-compare-$file-$id.out" | tr '\n' ' ')"
    done
}

# restored LABEL WRITTEN: every drive of the restore LABEL wrote WRITTEN (0: all unchanged) and
# none failed
restored() {
    local n
    n="$(grep -cE "^$2 written and verified, [0-9]+ unchanged, 0 failed, 0 not attempted$" "$work/$1.out" || true)"
    [ "$n" -eq "$3" ] || {
        sed 's/^/   | /' "$work/$1.out" >&2
        fail "$1: expected $3 drive(s) with \"$2 written and verified ... 0 failed\", found $n"
    }
}

# --- 4. Modbus TCP ------------------------------------------------------------------------------
begin "Modbus TCP: scan, backup, compare, restore (Windows under Wine vs Linux)"
# Port 0: the simulator takes a free port (the kernel's ephemeral range, above 32767) and says it.
start_sim sim-tcp --tcp 127.0.0.1:0
tcp="$(sed -n 's/^tcp: //p' "$work/sim-tcp.out")"
[ -n "$tcp" ] || fail "opentop-sim did not say its TCP port"
echo "   simulator: $devices on $tcp"
win scan --tcp "$tcp" scan
lin scan --tcp "$tcp" scan
scans_equal win-scan lin-scan
win backup --tcp "$tcp" backup "${ids[@]}" -o win-tcp.json
lin backup --tcp "$tcp" backup "${ids[@]}" -o lin-tcp.json
backups_equal win-tcp.json lin-tcp.json created checksum
compares_clean win win-tcp.json --tcp "$tcp"
compares_clean lin lin-tcp.json --tcp "$tcp"
echo "   compare with the drives: no differences (Windows and Linux, ${#ids[@]} drives each)"
win restore --tcp "$tcp" restore win-tcp.json --yes
restored win-restore 0 "${#ids[@]}"
lin restore --tcp "$tcp" restore lin-tcp.json --yes
restored lin-restore 0 "${#ids[@]}"
echo "   restore --yes: 0 written, all unchanged, 0 failed (Windows and Linux)"
# The write path: a setting changed from Linux is put back by the Windows restore.
lin set --tcp "$tcp" set 1 spno2.speed=1200 spno2.accel=1.5
win restore-write --tcp "$tcp" restore win-tcp.json --ids 1 --yes
restored win-restore-write 2 1
lin compare-after --tcp "$tcp" compare 1 lin-tcp.json:1
grep -q '^no differences' "$work/lin-compare-after.out" || fail "drive 1 differs from its backup after the Windows restore"
echo "   two settings changed from Linux: the Windows restore wrote and verified them back"
stop "$sim_pid"
sim_pid=""
end

# --- 5. COM port --------------------------------------------------------------------------------
begin "COM port: COM5 = the simulator's pty: scan, backup, compare (Windows vs Linux)"
start_sim sim-pty --pty "$pty_link"
ln -sfn "$pty_link" "$prefix/dosdevices/com5"
echo "   simulator: $devices on $(sed -n 's/^pty: //p' "$work/sim-pty.out") ($pty_link = COM5)"
# One program at a time: the pty has one client.
win com-scan --port COM5 --baud 19200 scan
lin com-scan --port "$pty_link" --baud 19200 scan
scans_equal win-com-scan lin-com-scan
win com-backup --port COM5 --baud 19200 backup "${ids[@]}" -o win-com.json
lin com-backup --port "$pty_link" --baud 19200 backup "${ids[@]}" -o lin-com.json
backups_equal win-com.json lin-com.json created checksum port
compares_clean win win-com.json --port COM5 --baud 19200
compares_clean lin lin-com.json --port "$pty_link" --baud 19200
echo "   compare with the drives: no differences (Windows on COM5 and Linux on the pty)"
timeout 60 wineserver -w || true # before the pty goes (see cleanup)
stop "$sim_pid"
sim_pid=""
rm -f "$prefix/dosdevices/com5"
end

# --- 6. the window ------------------------------------------------------------------------------
begin "GUI: opentop.exe --tcp under Xvfb 1366x768 (freetype fonts), screenshot"
start_sim sim-gui --tcp 127.0.0.1:0
tcp="$(sed -n 's/^tcp: //p' "$work/sim-gui.out")"
Xvfb -displayfd 3 -screen 0 1366x768x24 -nolisten tcp 3>"$work/xvfb.display" \
    >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 100); do
    [ -s "$work/xvfb.display" ] && break
    sleep 0.1
done
[ -s "$work/xvfb.display" ] || fail "Xvfb did not start: $(tail -n 1 "$work/xvfb.log")"
display=":$(head -n 1 "$work/xvfb.display")"
# --monitor-all scans 1-247 (nothing is known of this bus in the new prefix's settings) and then
# watches every drive; --stats-every says when. Wine's GDI font engine draws no text in line
# edits and spin boxes (docs/windows-progress.md): Qt's own freetype engine does.
DISPLAY="$display" wine "$stage/opentop.exe" -platform windows:fontengine=freetype \
    --tcp "$tcp" --monitor-all --stats-every 1 --quit-after "$quit_after" \
    </dev/null >"$work/gui.raw" 2>"$work/gui.err" &
gui_pid=$!
gui_start=$SECONDS
monitoring=""
while kill -0 "$gui_pid" 2>/dev/null && ((SECONDS - gui_start < quit_after)); do
    if grep -qE "^monitor: ${#ids[@]} drives, [1-9][0-9]* samples, 0 errors, 0 stale" "$work/gui.raw"; then
        monitoring=$((SECONDS - gui_start))
        break
    fi
    sleep 0.5
done
if [ -z "$monitoring" ]; then
    tail -n 3 "$work/gui.raw" "$work/gui.err" | sed 's/^/   | /' >&2
    kill -0 "$gui_pid" 2>/dev/null &&
        fail "the window was not monitoring ${#ids[@]} drives after a scan within ${quit_after} s"
    gui_rc=0
    wait "$gui_pid" || gui_rc=$?
    gui_pid=""
    fail "the window ended (exit $gui_rc) after $((SECONDS - gui_start)) s, before it monitored ${#ids[@]} drives"
fi
echo "   scanned and monitoring ${#ids[@]} drives after ${monitoring} s"
sleep 2 # a second redraw of the list and the trends
shot="$build/opentop-wine.png"
DISPLAY="$display" import -window root "$shot" || fail "import could not take the screenshot"
# Not blank: many colours and some contrast (as check-fresh-machine.sh's not_blank).
read -r colours deviation <<<"$(convert "$shot" -format '%k %[fx:standard_deviation]' info:)"
echo "   screenshot $shot: $colours colours, standard deviation $deviation"
if [ "$colours" -lt 64 ] || awk -v d="$deviation" 'BEGIN { exit !(d < 0.03) }'; then
    fail "the screenshot $shot is blank or nearly so"
fi
# dark GEOMETRY: pixels darker than 40 % grey in that part of the screenshot (text, mostly)
dark() {
    convert "$shot" -crop "$1" +repage -colorspace Gray -threshold 40% -negate \
        -format '%[fx:round(mean*w*h)]' info:
}
# Where the bus panel is: the top of its scan progress bar, full and blue after the scan, at
# x=100 (a bar above it, "Last time on ...", moves it down when the bus was seen before).
bar="$(convert "$shot" -crop 1x500+100+0 +repage -depth 8 txt:- |
    sed -n 's/^0,\([0-9]*\): *(\([0-9]*\),[0-9]*,\([0-9]*\).*/\1 \2 \3/p' |
    awk '!found && $2 < 120 && $3 > 180 { print $1; found = 1 }')" # all read: no SIGPIPE
[ -n "$bar" ] || fail "no full scan progress bar in the bus panel (see $shot)"
# The bus list's rows, 64 px below the bar (3 drives: number, model, state, ...): about 1100
# dark pixels with text.
rows="$(dark "480x90+0+$((bar + 64))")"
# The scan range's spin boxes, 28 px above the bar, "from 1 to 247", their text fields only:
# 9 and 32 dark pixels with freetype, 0 and 0 with Wine's GDI engine (no text drawn).
from="$(dark "28x18+114+$((bar - 28))")"
to="$(dark "28x18+179+$((bar - 28))")"
echo "   text: $rows dark pixels in the bus list's rows, $from and $to in the scan range boxes (progress bar at y=$bar)"
[ "$rows" -ge 300 ] || fail "no drive rows drawn in the bus list ($rows dark pixels; see $shot)"
if [ "$from" -lt 4 ] || [ "$to" -lt 15 ]; then
    fail "no text in the scan range spin boxes ($from, $to dark pixels; see $shot)"
fi
# It quits by itself (--quit-after); killed only if it does not.
quit_by=$((quit_after + 20))
while kill -0 "$gui_pid" 2>/dev/null && ((SECONDS - gui_start < quit_by)); do
    sleep 0.5
done
if kill -0 "$gui_pid" 2>/dev/null; then
    stop "$gui_pid"
    gui_pid=""
    fail "the window did not quit ${quit_by} s after it started (--quit-after $quit_after); killed"
fi
gui_rc=0
wait "$gui_pid" || gui_rc=$?
gui_pid=""
tr -d '\r' <"$work/gui.raw" >"$work/gui.out"
[ "$gui_rc" -eq 0 ] || fail "the window exited $gui_rc (log: $work/gui.err)"
grep -qE "^monitored ${#ids[@]} drives: [0-9]+ samples, 0 errors" "$work/gui.out" ||
    fail "the window's closing statistics are missing or show errors: $(tail -n 1 "$work/gui.out")"
echo "   quit by itself after $((SECONDS - gui_start)) s, exit 0: $(tail -n 1 "$work/gui.out")"
timeout 60 wineserver -w || true # Wine's desktop process lets go of the display first
stop "$xvfb_pid"
xvfb_pid=""
stop "$sim_pid"
sim_pid=""
end

# --- 7. the installer ---------------------------------------------------------------------------
begin "installer: silent install, installed opentop-cli --version, silent uninstall"
key='HKLM\Software\Microsoft\Windows\CurrentVersion\Uninstall\OpenTOP'
installed="$prefix/drive_c/Program Files/OpenTOP"
# NSIS's uninstaller runs from a copy of itself in %TEMP%\~nsuN.tmp, which Windows removes at the
# next reboot: not part of what was installed.
drive_c_files() {
    (cd "$prefix/drive_c" && find . -print | grep -Ev '/~nsu[^/]*\.tmp(/|$)' | LC_ALL=C sort)
}
timeout 60 wineserver -w || true # nothing of Wine's own still being written
drive_c_files >"$work/drive_c.before"
[ ! -e "$installed" ] || fail "$installed exists before the install"
run install 0 wine "$setup" /S
[ -f "$installed/opentop-cli.exe" ] || fail "the silent install put no opentop-cli.exe in $installed"
# Exactly the staged folder, and the uninstaller.
(cd "$stage" && find . -type f | LC_ALL=C sort) >"$work/stage.files"
(cd "$installed" && find . -type f ! -path ./uninstall.exe | LC_ALL=C sort) >"$work/installed.files"
diff "$work/stage.files" "$work/installed.files" >"$work/installed.diff" || {
    sed 's/^/   | /' "$work/installed.diff" >&2
    fail "the installed files are not the staged ones"
}
[ -f "$installed/uninstall.exe" ] || fail "no uninstall.exe installed"
menu="$prefix/drive_c/ProgramData/Microsoft/Windows/Start Menu/Programs/OpenTOP"
echo "   C:\\Program Files\\OpenTOP: $(find "$installed" -type f | wc -l) files ($(du -sh "$installed" | cut -f1)), the staged $(wc -l <"$work/stage.files") and uninstall.exe"
echo "   Start menu: $(find "$menu" -mindepth 1 -printf '%f, ' 2>/dev/null | sed 's/, $//')"
[ -f "$menu/OpenTOP.lnk" ] || fail "no Start menu entry OpenTOP.lnk"
run reg-installed 0 wine reg query "$key" /v DisplayVersion
grep -q "$version" "$work/reg-installed.out" || fail "the Uninstall key does not name version $version"
echo "   registry: $key, DisplayVersion $version"
run installed-version 0 wine 'C:\Program Files\OpenTOP\opentop-cli.exe' --version
grep -qx "opentop-cli $version" "$work/installed-version.out" ||
    fail "the installed opentop-cli.exe --version said: $(cat "$work/installed-version.out")"
echo "   installed opentop-cli.exe --version: $(cat "$work/installed-version.out")"
run uninstall 0 wine 'C:\Program Files\OpenTOP\uninstall.exe' /S
# The uninstaller goes on from its copy in %TEMP% after the first process has returned.
uninstall_start=$SECONDS
while [ -e "$installed" ] && ((SECONDS - uninstall_start < 60)); do
    sleep 0.5
done
[ ! -e "$installed" ] || fail "C:\\Program Files\\OpenTOP still exists 60 s after the silent uninstall"
timeout 60 wineserver -w || true
echo "   uninstalled: the folder was gone after $((SECONDS - uninstall_start)) s"
drive_c_files >"$work/drive_c.after"
diff "$work/drive_c.before" "$work/drive_c.after" >"$work/drive_c.diff" || {
    sed -n '1,20s/^/   | /p' "$work/drive_c.diff" >&2
    fail "drive_c holds other files after the uninstall than before the install"
}
echo "   drive_c: the same $(wc -l <"$work/drive_c.after") paths as before the install (%TEMP%\\~nsu*.tmp aside)"
run reg-removed 1 wine reg query "$key"
echo "   registry: the Uninstall key is gone"
end

report_phases
echo "windows: all checks passed (screenshot: $shot)"
exit 0
}
