#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz) with Debian's clang in build-fuzz/ and runs each
# for a while from its seed corpus and dictionary. Any crash, leak, timeout or sanitizer report
# fails the run; libFuzzer leaves the input as crash-*/leak-*/timeout-* in build-fuzz/findings/.
#   scripts/fuzz.sh [SECONDS] [HARNESS...]   default 60 s each, every harness
# Environment: OPENTOP_FUZZ_RUNS=N runs N inputs per harness instead of a time limit (the long
# run before resolving issue 11: OPENTOP_FUZZ_RUNS=10000000).
set -euo pipefail
{ # read to the closing brace before anything runs

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${OPENTOP_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${1:-60}"
shift || true
all=(FuzzBackupFile FuzzProfileLoader FuzzRtuReply FuzzCliValues FuzzTrafficLog FuzzRecipeFile
    FuzzSimTcpFraming FuzzUnitValuesCsv)
harnesses=("$@")
((${#harnesses[@]})) || harnesses=("${all[@]}")
jobs="$(nproc 2>/dev/null || echo 2)"

if ! command -v clang++ >/dev/null; then
    if [ "$(id -u)" -ne 0 ]; then
        echo "error: clang is missing; install it as root: apt-get install clang" >&2
        exit 1
    fi
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends clang >/dev/null
fi
# libFuzzer and the sanitizer runtimes are not in the clang package: Debian 12 ships them in
# libclang-rt-<major>-dev, which plain "apt-get install clang" does not bring.
runtime="$(clang++ -print-resource-dir)/lib/linux/libclang_rt.fuzzer-x86_64.a"
if [ ! -f "$runtime" ]; then
    major="$(clang++ -dumpversion | cut -d. -f1)"
    if [ "$(id -u)" -ne 0 ]; then
        echo "error: libFuzzer is missing ($runtime); install it as root:" \
            "apt-get install libclang-rt-$major-dev" >&2
        exit 1
    fi
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        "libclang-rt-$major-dev" >/dev/null
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
    CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DOPENTOP_FUZZ=ON -DOPENTOP_BUILD_TESTS=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
fi
cmake --build "$build" -j "$jobs" --target "${harnesses[@]}"

declare -A corpus=([FuzzBackupFile]=backup [FuzzProfileLoader]=profile [FuzzRtuReply]=rtu
    [FuzzCliValues]=cli [FuzzTrafficLog]=traffic [FuzzRecipeFile]=recipe [FuzzSimTcpFraming]=tcp
    [FuzzUnitValuesCsv]=unitcsv)
# dbu.json (95 KB) is longer than -max_len and would only be read cut; its reduced copy is in
# tests/fuzz/corpus/profile/ (made by tests/fuzz/reduce-profile.py)
declare -A seeds=([FuzzProfileLoader]="$root/model/profiles/dcpid.json")
# malloc_context_size=0: no allocation stack is recorded for every malloc, which made the
# harnesses 1.5–2 times faster; an error is still caught and its own stack printed. To see where
# a reported block was allocated, run the harness again on the saved input without it.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:malloc_context_size=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
export QT_QPA_PLATFORM=offscreen
findings="$build/findings"
mkdir -p "$findings"
limit=(-max_total_time="$seconds")
[ -n "${OPENTOP_FUZZ_RUNS:-}" ] && limit=(-runs="$OPENTOP_FUZZ_RUNS")
status=0
for h in "${harnesses[@]}"; do
    name="${corpus[$h]}"
    work="$build/corpus/$name" # grows as the fuzzer finds new paths; the seeds stay in git
    mkdir -p "$work"
    dirs=("$work")
    [ -d "$root/tests/fuzz/corpus/$name" ] && dirs+=("$root/tests/fuzz/corpus/$name")
    # a file among the corpus arguments would make libFuzzer run inputs instead of fuzzing
    [ -n "${seeds[$h]:-}" ] && cp -n "${seeds[$h]}" "$work/"
    echo "== $h: ${limit[*]}"
    if "$build/tests/fuzz/$h" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
        -dict="$root/tests/fuzz/dict/$name.dict" -artifact_prefix="$findings/$h-" \
        -print_final_stats=1 "${dirs[@]}" >"$findings/$h.log" 2>&1; then
        grep -E '^stat::number_of_executed_units|^Done' "$findings/$h.log" || true
    else
        status=1
        tail -n 40 "$findings/$h.log"
        echo "FAIL: $h; the input is in $findings/$h-*" >&2
    fi
done
exit "$status"
}
