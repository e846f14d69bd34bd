#!/bin/bash
# Screenshots of the real program in every language (issue 13): the drive workspace, the monitor
# and the alarms page with an alarm raised, at 1366x768 under Xvfb, driven with xdotool as a
# person would. Writes docs/screenshots/lang-<lang>-{workspace,monitor,alarms}.png.
# Usage: scripts/screenshots-languages.sh [build dir] [languages...]
{ # read to the closing brace before anything runs
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
shift || true
languages=("${@:-zh_TW zh_CN ko ja en}")
read -r -a languages <<< "${languages[*]}"
out="$root/docs/screenshots"
for tool in Xvfb xdotool import; do
    command -v "$tool" > /dev/null || { echo "error: $tool is missing (apt-get install xvfb xdotool imagemagick)" >&2; exit 1; }
done
work="$(mktemp -d)"
display=":$((90 + RANDOM % 9))"
Xvfb "$display" -screen 0 1366x768x24 -nolisten tcp > /dev/null 2>&1 &
xvfb=$!
sim_pid=""
app_pid=""
cleanup() {
    [ -n "$app_pid" ] && kill "$app_pid" 2> /dev/null || true
    [ -n "$sim_pid" ] && kill "$sim_pid" 2> /dev/null || true
    kill "$xvfb" 2> /dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
export DISPLAY="$display"
sleep 1

shot() { # shot NAME: the whole screen, as the user sees it
    sleep "${2:-1.5}"
    import -window root "$out/$1"
    echo "   $out/$1"
}

for lang in "${languages[@]}"; do
    echo "== $lang"
    # A fresh user: no remembered connection, window geometry or language choice.
    export HOME="$work/home-$lang" XDG_CONFIG_HOME="$work/home-$lang/.config"
    mkdir -p "$XDG_CONFIG_HOME"
    mkfifo "$work/console-$lang"
    "$build/app/opentop-sim" --devices dbu200@1,dcpid@7 --pty "$work/pty-$lang" --quiet \
        < "$work/console-$lang" > "$work/sim-$lang.log" 2>&1 &
    sim_pid=$!
    exec 7> "$work/console-$lang"
    for _ in $(seq 50); do grep -q ready "$work/sim-$lang.log" && break; sleep 0.1; done
    "$build/app/opentop" --lang "$lang" --port "$work/pty-$lang" --timeout 40 --retries 0 \
        > "$work/gui-$lang.log" 2>&1 &
    app_pid=$!
    window=""
    for _ in $(seq 100); do
        window="$(xdotool search --onlyvisible --pid "$app_pid" 2> /dev/null | head -1 || true)"
        [ -n "$window" ] && break
        sleep 0.1
    done
    [ -n "$window" ] || { echo "error: no window" >&2; exit 1; }
    xdotool windowmove "$window" 0 0 windowsize "$window" 1366 768
    sleep 1
    xdotool windowactivate --sync "$window" 2> /dev/null || xdotool windowfocus "$window"
    xdotool key F5 # scan the bus
    sleep 14
    xdotool key Return # close the scan's summary, if it shows one
    # Drive 1 is selected and its monitor in front.
    shot "lang-$lang-monitor.png" 3
    # The core parameters: the third page (Drive ▸ Next page, Ctrl+PgDown).
    xdotool key ctrl+Next ctrl+Next
    shot "lang-$lang-workspace.png" 2
    # An overload alarm on drive 1: the red banner names it; its Show button (right-aligned)
    # opens the drive's alarms page, where the newest record's cause and remedy are shown.
    echo "alarm 1 7" >&7
    sleep 3
    xdotool mousemove 1232 96 click 1
    sleep 2
    xdotool mousemove 800 283 click 1
    shot "lang-$lang-alarms.png" 2
    kill "$app_pid"; wait "$app_pid" 2> /dev/null || true; app_pid=""
    echo quit >&7
    exec 7>&-
    sleep 0.5
    kill "$sim_pid" 2> /dev/null || true
    wait "$sim_pid" 2> /dev/null || true; sim_pid=""
done
}
