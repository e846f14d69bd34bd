#!/bin/bash
# Screenshots of the real program as a laptop shows it (issue 24 item 7): a maximised window on a
# 1366x768 desktop is about 1366x700, with a dock open. The monitor beside the bus overview and
# the test run of a DBU in I/O priority beside the traffic log, driven with xdotool as a person
# would, under Xvfb. Writes docs/screenshots/laptop-{monitor,test-run}.png.
# Usage: scripts/screenshots-laptop.sh [build dir]
{ # read to the closing brace before anything runs
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
out="$root/docs/screenshots"
for tool in Xvfb xdotool import; do
    command -v "$tool" > /dev/null || { echo "error: $tool is missing (apt-get install xvfb xdotool imagemagick)" >&2; exit 1; }
done
work="$(mktemp -d)"
display=":$((80 + RANDOM % 9))"
Xvfb "$display" -screen 0 1366x700x24 -nolisten tcp > /dev/null 2>&1 &
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
export DISPLAY="$display" HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config"
mkdir -p "$XDG_CONFIG_HOME"
sleep 1

shot() { # shot NAME [SECONDS]: the whole screen, as the user sees it
    sleep "${2:-1.5}"
    import -window root "$out/$1"
    echo "   $out/$1"
}

"$build/app/opentop-sim" --devices dbu200@1,dbu400@150,dcpid@7 --pty "$work/pty" --quiet \
    > "$work/sim.log" 2>&1 < /dev/null &
sim_pid=$!
for _ in $(seq 50); do grep -q ready "$work/sim.log" && break; sleep 0.1; done
"$build/app/opentop" --port "$work/pty" --timeout 40 --retries 0 > "$work/gui.log" 2>&1 &
app_pid=$!
window=""
for _ in $(seq 100); do
    window="$(xdotool search --onlyvisible --pid "$app_pid" 2> /dev/null | head -1 || true)"
    [ -n "$window" ] && break
    sleep 0.1
done
[ -n "$window" ] || { echo "error: no window" >&2; exit 1; }
xdotool windowmove "$window" 0 0 windowsize "$window" 1366 700
sleep 1
xdotool windowactivate --sync "$window" 2> /dev/null || xdotool windowfocus "$window"
xdotool key F5 # scan the bus
sleep 30
xdotool key Return # close the scan's summary, if it shows one
xdotool key ctrl+shift+o # the bus overview dock
shot laptop-monitor.png 3
xdotool key ctrl+shift+o ctrl+t # the traffic log instead
for _ in $(seq 8); do xdotool key ctrl+Next; done # Drive ▸ Next page, to Test run
shot laptop-test-run.png 2
xdotool key ctrl+t
kill "$app_pid"; wait "$app_pid" 2> /dev/null || true; app_pid=""
exit 0
}
