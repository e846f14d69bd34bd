#!/usr/bin/env bash
# The GUI's CPU use and memory while it monitors simulated drives with the bus overview and the
# trends of every drive open side by side, measured from /proc while it runs.
#
#   scripts/measure-gui.sh [BUILD_DIR]
#   environment: DRIVES=16 POLL_MS=100 DURATION=130 WARMUP=60 SIM=inprocess|pty RUN=1
#   e.g. SIM=pty scripts/measure-gui.sh build                       (16 drives at 10 Hz)
#        SIM=pty DRIVES=64 POLL_MS=500 scripts/measure-gui.sh build (64 drives at 2 Hz)
#
# The measurement starts once every drive is monitored (a real line is scanned first) and
# a warm-up has passed (by default the trends' one-minute window, so that they show as much
# as they ever do), and ends shortly before the GUI quits after DURATION seconds. Prints
# the samples per second the monitor reached per drive, the average CPU use of the whole
# process over the measured time (CPU time over wall time: on a busy machine, repeat it), and
# its resident memory.
set -euo pipefail
build=${1:-build}
bin="$build/app/opentop"
drives=${DRIVES:-16}
poll=${POLL_MS:-100}
duration=${DURATION:-130}
warmup=${WARMUP:-60}
[[ -x "$bin" ]] || { echo "measure-gui: $bin not found; build first" >&2; exit 2; }
(( duration > warmup + 5 )) || { echo "measure-gui: DURATION must exceed $((warmup + 5)) s" >&2; exit 2; }

work=$(mktemp -d)
trap 'exec 3>&- 2>/dev/null; kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
# A private settings directory: the measurement neither reads nor changes the user's settings.
export XDG_CONFIG_HOME="$work/config"
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}

# SIM=inprocess (default): the drives are simulated inside the GUI process, so the figures
# include the simulation. SIM=pty: opentop-sim serves them on a pseudo-terminal and the GUI
# talks RTU to it through libmodbus, as to a USB adapter; the figures are the GUI's alone.
# With SIM=pty and RUN=1 (default) the motors turn and change speed now and then, so the
# values on screen change as in a commissioning session, not a bus of idle drives.
connection=(--sim "dbu200@1-$drives")
console=false
if [[ ${SIM:-inprocess} == pty ]]; then
    mkfifo "$work/console"
    "$build/app/opentop-sim" --devices "dbu200@1-$drives" --pty "$work/pty" --quiet \
        <"$work/console" >"$work/sim" 2>&1 &
    exec 3>"$work/console"
    for _ in $(seq 50); do grep -q ready "$work/sim" && break; sleep 0.1; done
    connection=(--port "$work/pty" --baud 115200)
    [[ ${RUN:-1} == 1 ]] && console=true
fi
# Every drive turning at a speed of its own, alternating between two so that it ramps.
speeds() {
    $console || return 0
    for ((id = 1; id <= drives; ++id)); do
        echo "vr $id $(( 300 + (id * 97 + $1 * 700) % 2400 ))" >&3
    done
}
# The motors turn (X0 on) or stop; they are stopped before the GUI quits, as it would otherwise
# ask what to do with running drives.
motors() {
    $console || return 0
    for ((id = 1; id <= drives; ++id)); do echo "input $id $1" >&3; done
}
motors 1
speeds 0

"$bin" "${connection[@]}" --monitor-all --poll-ms "$poll" --quit-after "$duration" \
    --stats-every 1 >"$work/out" 2>"$work/err" &
pid=$!
ticks=$(getconf CLK_TCK)
cpu() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
rss() { awk '/^VmRSS/ {print $2}' "/proc/$pid/status"; }
started=$(date +%s)
margin=2
$console && margin=$((10 + drives / 8)) # for the motors to stop and the GUI to see it
end=$(( started + duration - margin ))

# Until the drives are watched and sampled (on a real line after a scan, which on a busy
# machine may miss a drive whose answer came late: then the figures say how many).
watched() { awk '/^monitor: / && $4 > 0 {n = $2} END {print n + 0}' "$work/out" 2>/dev/null; }
until (( $(watched) >= drives )); do
    kill -0 "$pid" 2>/dev/null && (( $(date +%s) < end )) || break
    (( $(watched) > 0 && $(date +%s) - started > 30 )) && break
    sleep 0.5
done
monitoring=$(( $(date +%s) - started ))
sleep "$warmup"
t0=$(date +%s.%N); c0=$(cpu)
max=0; sum=0; n=0; turn=0
while (( $(date +%s) < end )) && kill -0 "$pid" 2>/dev/null; do
    r=$(rss); sum=$((sum + r)); n=$((n + 1)); (( r > max )) && max=$r
    (( n % 5 == 0 )) && speeds $(( ++turn % 2 ))
    sleep 1
done
t1=$(date +%s.%N); c1=$(cpu)
motors 0
for _ in $(seq $((margin + 30))); do kill -0 "$pid" 2>/dev/null && sleep 1; done
kill -0 "$pid" 2>/dev/null && { echo "measure-gui: opentop did not quit" >&2; exit 1; }
wait "$pid" || { echo "measure-gui: opentop failed:" >&2; cat "$work/err" >&2; exit 1; }
(( n > 0 )) || { echo "measure-gui: nothing measured ($monitoring s to start monitoring); make DURATION longer" >&2; tail -5 "$work/err" >&2; grep "^monitor:" "$work/out" | tail -2 >&2; exit 1; }

grep -v '^drive \|^monitor: ' "$work/out" || true
awk '/^drive / {n++; s += $(NF-1); if (min == "" || $(NF-1) < min) min = $(NF-1)}
     END {if (n) printf "per drive: %.2f samples/s on average, %.2f at least\n", s / n, min}' "$work/out"
echo "$c0 $c1 $t0 $t1 $ticks" | awk '{printf "CPU: %.1f %% of one core (average over %.0f s after %d s to start monitoring and a %d s warm-up)\n", \
    ($2 - $1) / $5 / ($4 - $3) * 100, $4 - $3, '"$monitoring"', '"$warmup"'}'
(( $(watched) == drives )) || echo "measure-gui: only $(watched) of $drives drives were monitored"
echo "memory: resident $((sum / n / 1024)) MiB on average, $((max / 1024)) MiB at most"
