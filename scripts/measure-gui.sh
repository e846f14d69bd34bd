#!/usr/bin/env bash
# The GUI's CPU use and memory while it monitors simulated drives (bus overview and trends of
# every drive open), measured from /proc while it runs.
#
#   scripts/measure-gui.sh [BUILD_DIR]   environment: DRIVES=16 POLL_MS=100 DURATION=60 SIM=pty
#
# Prints the samples per second the monitor reached per drive, the average CPU use of the
# whole process over the measured time (after a warm-up), and its resident memory.
set -euo pipefail
build=${1:-build}
bin="$build/app/opentop"
drives=${DRIVES:-16}
poll=${POLL_MS:-100}
duration=${DURATION:-60}
warmup=10
[[ -x "$bin" ]] || { echo "measure-gui: $bin not found; build first" >&2; exit 2; }
(( duration > warmup + 5 )) || { echo "measure-gui: DURATION must exceed $((warmup + 5)) s" >&2; exit 2; }

work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
# A private settings directory: the measurement neither reads nor changes the user's settings.
export XDG_CONFIG_HOME="$work/config"
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}

# SIM=inprocess (default): the drives are simulated inside the GUI process, so the figures
# include the simulation. SIM=pty: opentop-sim serves them on a pseudo-terminal and the GUI
# talks RTU to it through libmodbus, as to a USB adapter; the figures are the GUI's alone.
connection=(--sim "dbu200@1-$drives")
if [[ ${SIM:-inprocess} == pty ]]; then
    mkfifo "$work/console"
    sleep $((duration + 30)) >"$work/console" &
    "$build/app/opentop-sim" --devices "dbu200@1-$drives" --pty "$work/pty" --quiet \
        <"$work/console" >"$work/sim" 2>&1 &
    for _ in $(seq 50); do grep -q ready "$work/sim" && break; sleep 0.1; done
    connection=(--port "$work/pty" --baud 115200)
fi
"$bin" "${connection[@]}" --monitor-all --poll-ms "$poll" --quit-after "$duration" \
    >"$work/out" 2>"$work/err" &
pid=$!
ticks=$(getconf CLK_TCK)
cpu() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
rss() { awk '/^VmRSS/ {print $2}' "/proc/$pid/status"; }

sleep "$warmup"
t0=$(date +%s.%N); c0=$(cpu)
max=0; sum=0; n=0
end=$(( $(date +%s) + duration - warmup - 2 ))
while (( $(date +%s) < end )) && kill -0 "$pid" 2>/dev/null; do
    r=$(rss); sum=$((sum + r)); n=$((n + 1)); (( r > max )) && max=$r
    sleep 1
done
t1=$(date +%s.%N); c1=$(cpu)
wait "$pid" || { echo "measure-gui: opentop failed:" >&2; cat "$work/err" >&2; exit 1; }

grep -v '^drive ' "$work/out" || true
awk '/^drive / {n++; s += $(NF-1); if (min == "" || $(NF-1) < min) min = $(NF-1)}
     END {if (n) printf "per drive: %.2f samples/s on average, %.2f at least\n", s / n, min}' "$work/out"
echo "$c0 $c1 $t0 $t1 $ticks" | awk '{printf "CPU: %.1f %% of one core (average over %.0f s after a %d s warm-up)\n", \
    ($2 - $1) / $5 / ($4 - $3) * 100, $4 - $3, '"$warmup"'}'
echo "memory: resident $((sum / n / 1024)) MiB on average, $((max / 1024)) MiB at most"
