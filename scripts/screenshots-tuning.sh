#!/bin/bash
# Screenshots of the Speed loop tuning page (issue 14) from the real program against opentop-sim
# (a simulated DC controller, dcpid@7, in its speed loop mode) at 1366x768 under Xvfb, driven
# with xdotool as a person would: a step test with the drive's gains, the relay autotune, its
# proposal accepted and stepped again. Writes docs/screenshots/tuning-autotune.png (result,
# proposal, predicted and measured step) and docs/screenshots/tuning-step.png (the two step
# runs overlaid, before and after).
# Usage: scripts/screenshots-tuning.sh [build dir]
{ # read to the closing brace before anything runs
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
out="$root/docs/screenshots"
for tool in Xvfb xdotool import; do
    command -v "$tool" > /dev/null || { echo "error: $tool is missing (apt-get install xvfb xdotool imagemagick)" >&2; exit 1; }
done
mkdir -p "$out"
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

shot() { # shot NAME [wait]: the whole screen, as the user sees it
    sleep "${2:-1.5}"
    import -window root "$out/$1"
    echo "   $out/$1"
}
click() { # click X Y
    xdotool mousemove "$1" "$2" click 1
    sleep 0.4
}
type_into() { # type_into X Y TEXT: replaces a field's text
    click "$1" "$2"
    xdotool key ctrl+a
    xdotool type "$3"
    sleep 0.3
}
confirm() { # answers the question before anything moves with its Run button
    sleep 1.5
    xdotool key shift+Tab space
}

# Where the page's controls are in the 1366x768 window (the page shown on drive 7).
from_field=(704 300)
to_field=(704 328)
run_step=(715 384)
tab_step=(605 268)
tab_autotune=(702 268)
autotune_button=(715 375)
accept_button=(640 557)
prediction_check=(882 598)

export HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config"
mkdir -p "$XDG_CONFIG_HOME"
mkfifo "$work/console"
"$build/app/opentop-sim" --devices dcpid@7 --pty "$work/pty" --quiet \
    < "$work/console" > "$work/sim.log" 2>&1 &
sim_pid=$!
exec 7> "$work/console"
for _ in $(seq 50); do grep -q ready "$work/sim.log" && break; sleep 0.1; done
echo "set 7 0x0080 2" >&7 # speed loop (commutation frequency)
"$build/app/opentop" --lang en --port "$work/pty" --timeout 40 --retries 0 \
    > "$work/gui.log" 2>&1 &
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
sleep 1
# The tuning page: before Alarms, the last page (Drive ▸ Previous page wraps round).
xdotool key ctrl+Prior ctrl+Prior
[ -n "${DEBUG:-}" ] && shot tuning-debug-1.png
# Run 1: the drive's own gains, 150 -> 300 1/s (the step the autotune's prediction shows).
type_into "${from_field[@]}" 150
type_into "${to_field[@]}" 300
click "${run_step[@]}"
[ -n "${DEBUG:-}" ] && shot tuning-debug-2.png 1
confirm
sleep 7
[ -n "${DEBUG:-}" ] && shot tuning-debug-3.png
# The relay autotune around 300 1/s, its proposal accepted, then stepped as predicted.
click "${tab_autotune[@]}"
[ -n "${DEBUG:-}" ] && shot tuning-debug-5.png 1
click "${autotune_button[@]}"
confirm
sleep 20
[ -n "${DEBUG:-}" ] && shot tuning-debug-4.png
click "${accept_button[@]}"
confirm
sleep 8
click "${tab_autotune[@]}"
shot tuning-autotune.png
# The step side: the two measured runs, before and after, without the prediction.
click "${tab_step[@]}"
click "${prediction_check[@]}"
shot tuning-step.png
kill "$app_pid"; wait "$app_pid" 2> /dev/null || true; app_pid=""
echo quit >&7
exec 7>&-
sleep 0.5
kill "$sim_pid" 2> /dev/null || true
wait "$sim_pid" 2> /dev/null || true; sim_pid=""
}
