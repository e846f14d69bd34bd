#!/usr/bin/env bash
# Builds OpenTOP with a sanitizer in its own build directory and runs tests under it; any report
# stops the test (halt_on_error) and fails the run.
#   scripts/sanitize.sh address   AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer,
#                                 the engine's suites (transport, model, sim, report,
#                                 translations), in build-asan/; OPENTOP_SANITIZE_ALL=1: the
#                                 whole suite with the command line's, the window's, the
#                                 end-to-end, soak and fault-matrix tests (their programs built
#                                 with the sanitizers too)
#   scripts/sanitize.sh thread    ThreadSanitizer: the transport, model (monitor, worker thread,
#                                 queued calls, cancellation, shutdown) tests, in build-tsan/
# Environment: OPENTOP_SANITIZE_BUILD_DIR overrides the build directory; OPENTOP_CTEST_ARGS adds
# ctest arguments (e.g. "-R ModbusClient"). Suppressions for reports inside third-party code
# (Qt, fontconfig, ...) are in tests/sanitizers/, each with its reason.
set -euo pipefail
{ # read to the closing brace before anything runs

kind="${1:-}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case "$kind" in
address) build="${OPENTOP_SANITIZE_BUILD_DIR:-$root/build-asan}" ;;
thread) build="${OPENTOP_SANITIZE_BUILD_DIR:-$root/build-tsan}" ;;
*)
    echo "usage: $0 address|thread" >&2
    exit 2
    ;;
esac
jobs="$(nproc 2>/dev/null || echo 2)"
supp="$root/tests/sanitizers"

start=$SECONDS
# -O1 -g1 as the sanitizers' manuals advise: stacks keep their lines, and the build takes half
# the time of -O2 -g (CI's budget on 2 cores).
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOPENTOP_WERROR=ON \
    -DOPENTOP_SANITIZE="$kind" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS="-Wno-error=maybe-uninitialized" >/dev/null
# (GCC 12's maybe-uninitialized at -O1 reports std::optional values that are always set; the
# normal -O2 build keeps the warning an error.)
echo "== building with -fsanitize=$kind in $build"
# CI's share (2 cores, an hour for everything): the engine's suites; the command line's
# (test_cli), the window's (test_ui) and the end-to-end ones under ASan with
# OPENTOP_SANITIZE_ALL=1 (check-fresh-machine.sh sanitize).
unit_suites="test_transport test_model test_sim test_report test_translations"
if [ "$kind" = address ] && [ "${OPENTOP_SANITIZE_ALL:-0}" = 1 ]; then
    cmake --build "$build" -j "$jobs"
elif [ "$kind" = address ]; then
    # shellcheck disable=SC2086
    cmake --build "$build" -j "$jobs" --target $unit_suites
else
    cmake --build "$build" -j "$jobs" --target test_transport test_model
fi
built=$SECONDS
echo "== sanitizer build: $((built - start)) s"

export QT_QPA_PLATFORM=offscreen
cd "$build"
status=0
if [ "$kind" = address ]; then
    export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
    export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
    export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
    if [ "${OPENTOP_SANITIZE_ALL:-0}" = 1 ]; then
        echo "== running the whole test suite under ASan+UBSan"
        labels='.'
    else
        echo "== running the unit suites under ASan+UBSan"
        labels="^(${unit_suites// /|})\$"
    fi
    # shellcheck disable=SC2086
    ctest --output-on-failure --timeout 600 -j "$jobs" -L "$labels" ${OPENTOP_CTEST_ARGS:-} || status=$?
else
    export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp"
    # With TZ unset, glibc's tzset() (Qt calls it for every local time) frees and duplicates its
    # copy of the zone name on each call, under a glibc lock TSan cannot see. Where libc has no
    # symbols (a fresh root) the report cannot be matched to tsan.supp's tzset_internal line, so
    # name the system zone explicitly: the same zone, and tzset() then changes nothing.
    export TZ="${TZ:-:/etc/localtime}"
    echo "== running the transport and model tests under TSan"
    # shellcheck disable=SC2086
    ctest --output-on-failure --timeout 600 -j "$jobs" -L '^test_(transport|model)$' ${OPENTOP_CTEST_ARGS:-} || status=$?
fi
echo "== sanitizer tests: $((SECONDS - built)) s (whole run $((SECONDS - start)) s)"
exit "$status"
}
