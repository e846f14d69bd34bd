#!/usr/bin/env bash
# Proves the README's set-up commands and the Debian package on brand-new minimal Debian roots,
# the way a new user's machine starts: nothing installed by hand.
#
#   scripts/check-fresh-machine.sh [--suite bookworm|trixie] CHECK...
#                                            Debian 12 (bookworm, the default) or 13 (trixie);
#                                            the roots come from the machine's apt sources with
#                                            their suite names changed to the one asked for
#
#   scripts/check-fresh-machine.sh test      README test command (bash scripts/setup.sh test)
#   scripts/check-fresh-machine.sh gui       README GUI command; the screenshot of the real window
#                                            must be written and not blank
#   scripts/check-fresh-machine.sh package   build the .deb, lintian + appstream + desktop checks,
#                                            then install it in a second fresh root, run it, remove it
#   scripts/check-fresh-machine.sh asan      the engine's suites (transport, model, sim,
#                                            report) built with ASan+UBSan
#                                            (scripts/sanitize.sh address)
#   scripts/check-fresh-machine.sh tsan      the transport and model tests with TSan
#                                            (scripts/sanitize.sh thread)
#   scripts/check-fresh-machine.sh sanitize  both, with the command line's, the window's and the
#                                            end-to-end suites under ASan too
#                                            (OPENTOP_SANITIZE_ALL=1)
#   scripts/check-fresh-machine.sh fuzz      every libFuzzer harness for OPENTOP_FUZZ_SECONDS (60)
#                                            from its seed corpus (scripts/fuzz.sh)
#   scripts/check-fresh-machine.sh windows   the Windows programs cross-built in the root and
#                                            proven under Wine against its Linux programs
#                                            (scripts/check-windows.sh; skipped in one line
#                                            without ../shared/toolchains)
#   scripts/check-fresh-machine.sh test gui package sanitize fuzz   all of them in one root
#                                            (about 90 min on 2 cores: before a release; CI runs
#                                            test gui package asan, see .ci/run)
#
# Needs root and mmdebstrap (installed from Debian's packages when missing). The roots come from
# the machine's own apt sources; the checked tree is a clean clone of HEAD (uncommitted changes
# are not included) with ../shared beside it. Results (logs, screenshots, the .deb, lintian's
# report) go to build-fresh/ in this tree.
#
# Environment:
#   OPENTOP_FRESH_CACHE=0     don't reuse downloaded .debs and compiler outputs between runs
#                             (default: kept in /var/cache/opentop-fresh; they only save time, the
#                             set of installed packages is the same)
#   OPENTOP_FRESH_KEEP=1      keep the roots afterwards (in /var/tmp/opentop-fresh.*)
set -euo pipefail
{ # read to the closing brace before anything runs: editing this file mid-run is harmless

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
suite=bookworm
if [ "${1:-}" = --suite ]; then
    suite="${2:-}"
    shift 2 || true
fi
case "$suite" in
bookworm) debian="Debian 12" ;;
trixie) debian="Debian 13" ;;
*)
    echo "usage: $0 [--suite bookworm|trixie] test|gui|package|asan|tsan|sanitize|fuzz|windows [...]" >&2
    exit 2
    ;;
esac
forms=("$@")
((${#forms[@]})) || forms=(test)
for f in "${forms[@]}"; do
    case "$f" in
    test | gui | package | asan | tsan | sanitize | fuzz | windows) ;;
    *)
        echo "usage: $0 [--suite bookworm|trixie] test|gui|package|asan|tsan|sanitize|fuzz|windows [...]" >&2
        exit 2
        ;;
    esac
done
want() {
    local f
    for f in "${forms[@]}"; do [ "$f" = "$1" ] && return 0; done
    return 1
}

if [ "$(id -u)" -ne 0 ]; then
    echo "error: a fresh root needs root (chroot, mounts); run as root" >&2
    exit 3
fi
if ! command -v mmdebstrap >/dev/null; then
    echo "== installing mmdebstrap"
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends mmdebstrap >/dev/null
fi

out="$repo/build-fresh"
mkdir -p "$out"
work="$(mktemp -d /var/tmp/opentop-fresh.XXXXXX)"
cache="/var/cache/opentop-fresh"
[ "$suite" = bookworm ] || cache="$cache/$suite" # one suite's .debs are not another's
use_cache="${OPENTOP_FRESH_CACHE:-1}"
mounted=()

# --- phase timing ---------------------------------------------------------------------------
phase_names=()
phase_secs=()
phase_start=0
phase_name=""
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
    echo "== time per phase"
    local i total=0
    for i in "${!phase_names[@]}"; do
        printf '   %-78s %5d s\n' "${phase_names[$i]}" "${phase_secs[$i]}"
        total=$((total + phase_secs[i]))
    done
    printf '   %-78s %5d s\n' "total" "$total"
}

# --- roots and mounts -------------------------------------------------------------------------
cleanup() {
    local status=$?
    local i
    if [ "$status" -ne 0 ] && [ -n "$phase_name" ]; then
        phase_names+=("$phase_name (FAILED)")
        phase_secs+=("$((SECONDS - phase_start))")
        report_phases
        echo "== FAILED in: $phase_name"
    fi
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
        umount "${mounted[$i]}" 2>/dev/null || umount -l "${mounted[$i]}" 2>/dev/null || true
    done
    if grep -q " $work/" /proc/mounts; then
        echo "warning: something is still mounted under $work; not removing it" >&2
    elif [ "${OPENTOP_FRESH_KEEP:-0}" = 1 ]; then
        echo "roots kept in $work"
    else
        rm -rf --one-file-system "$work"
    fi
    exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP

bind() { # bind SOURCE TARGET
    mkdir -p "$2"
    mount --bind "$1" "$2"
    mounted+=("$2")
}

base_tar="$work/base.tar"
make_base() {
    begin "fresh minimal $debian root (mmdebstrap --variant=minbase)"
    local sources=() file
    for file in /etc/apt/sources.list.d/debian.sources /etc/apt/sources.list; do
        [ -s "$file" ] || continue
        # The machine's mirrors, for the suite asked for (bookworm-updates -> trixie-updates, ...)
        sed -E "s/\bbookworm\b/$suite/g" "$file" >"$work/$(basename "$file")"
        sources+=("$work/$(basename "$file")")
    done
    local hooks=()
    if [ "$use_cache" = 1 ]; then
        mkdir -p "$cache/base-archives"
        hooks=(--skip=essential/unlink
            --setup-hook="mkdir -p \"\$1\"/var/cache/apt/archives/"
            --setup-hook="sync-in $cache/base-archives /var/cache/apt/archives/"
            --customize-hook="sync-out /var/cache/apt/archives $cache/base-archives")
    fi
    mmdebstrap --quiet --variant=minbase --include=ca-certificates,git "${hooks[@]}" \
        "$suite" "$base_tar" "${sources[@]}"
    end
}

# new_root NAME: a root unpacked from the base, with /proc, /sys, /dev, /dev/pts bound in; its
# path in $root (not printed: the mounts must be recorded in this shell, not in a subshell)
new_root() {
    root="$work/$1"
    mkdir -p "$root"
    tar -C "$root" -xf "$base_tar"
    # As in any Debian chroot, packages do not start services here (PostgreSQL's "main"
    # cluster, which the set-up's postgresql package makes): they would outlive the check and
    # hold its mounts. The tests start their own throw-away PostgreSQL server.
    printf '#!/bin/sh\nexit 101\n' >"$root/usr/sbin/policy-rc.d"
    chmod 755 "$root/usr/sbin/policy-rc.d"
    bind /proc "$root/proc"
    bind /sys "$root/sys"
    bind /dev "$root/dev"
    bind /dev/pts "$root/dev/pts"
    [ -d /dev/shm ] && bind /dev/shm "$root/dev/shm"
    if [ "$use_cache" = 1 ]; then
        mkdir -p "$cache/apt-archives/partial" "$cache/ccache"
        bind "$cache/apt-archives" "$root/var/cache/apt/archives"
        bind "$cache/ccache" "$root/root/.cache/ccache"
    fi
}

# in_root ROOT COMMAND: run COMMAND with bash in ROOT, with nothing of this machine's environment
in_root() {
    chroot "$1" env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 TERM=dumb \
        CI="${CI:-}" OPENTOP_GUI_QUIT_AFTER="${OPENTOP_GUI_QUIT_AFTER:-}" bash -c "$2"
}

# not_blank ROOT PNG: the screenshot exists and shows more than one flat colour
not_blank() {
    local stats
    if [ ! -s "$1$2" ]; then
        echo "FAIL: no screenshot at $2" >&2
        return 1
    fi
    stats="$(in_root "$1" "convert '$2' -format '%k %[fx:standard_deviation]' info:")"
    echo "   screenshot $2: $stats (distinct colours, standard deviation)"
    read -r colours deviation <<<"$stats"
    if [ "$colours" -lt 64 ] || awk -v d="$deviation" 'BEGIN { exit !(d < 0.03) }'; then
        echo "FAIL: the screenshot $2 is blank or nearly so" >&2
        return 1
    fi
}

# --- the checks -------------------------------------------------------------------------------
commit="$(git -C "$repo" rev-parse --short HEAD)"
echo "== checking commit $commit of $repo on fresh $debian roots: ${forms[*]}"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no)" ]; then
    echo "   (uncommitted changes in $repo are not part of the check)"
fi

make_base

new_root root-a
root_a="$root"
git clone -q --no-hardlinks "$repo" "$root_a/src/main"
if [ -d "$repo/../shared" ]; then
    cp -a "$repo/../shared" "$root_a/src/shared"
fi

if want test; then
    begin "README test command: bash scripts/setup.sh test"
    in_root "$root_a" 'cd /src/main && bash scripts/setup.sh test' 2>&1 | tee "$out/test.log"
    end
fi

if want gui; then
    begin "README GUI command: bash scripts/setup.sh gui (no display: Xvfb, screenshot)"
    OPENTOP_GUI_QUIT_AFTER=10 in_root "$root_a" 'cd /src/main && bash scripts/setup.sh gui' 2>&1 |
        tee "$out/gui.log"
    not_blank "$root_a" /src/main/build/opentop-screenshot.png
    cp "$root_a/src/main/build/opentop-screenshot.png" "$out/gui-screenshot.png"
    end
fi

if want package; then
    begin "build the Debian package (cmake --build build --target package)"
    in_root "$root_a" 'cd /src/main && bash scripts/setup.sh build >/dev/null &&
        cmake --build build --target package' 2>&1 | tail -n 5
    deb="$(cd "$root_a/src/main/build" && ls opentop_*_amd64.deb | head -n 1)"
    [ -n "$deb" ] || {
        echo "FAIL: no opentop_*_amd64.deb was made" >&2
        exit 1
    }
    cp "$root_a/src/main/build/$deb" "$out/"
    echo "   $deb: $(du -k "$out/$deb" | cut -f1) KiB, Installed-Size $(dpkg-deb -f "$out/$deb" Installed-Size) KiB"
    end

    begin "lintian, appstreamcli validate, desktop-file-validate"
    in_root "$root_a" 'DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        lintian appstream desktop-file-utils >/dev/null'
    in_root "$root_a" "cd /src/main/build && lintian --info --display-info --suppress-tags-from-file /dev/null '$deb'" \
        >"$out/lintian.txt" 2>&1 || true
    cat "$out/lintian.txt"
    if grep -q '^E: ' "$out/lintian.txt"; then
        echo "FAIL: lintian reports errors" >&2
        exit 1
    fi
    in_root "$root_a" "set -e; rm -rf /tmp/deb && dpkg-deb -x '/src/main/build/$deb' /tmp/deb
        appstreamcli validate --no-net /tmp/deb/usr/share/metainfo/*.metainfo.xml
        desktop-file-validate /tmp/deb/usr/share/applications/*.desktop && echo 'desktop entry: valid'"
    end

    begin "install the package on a second fresh root, run it, remove it"
    new_root root-b
    root_b="$root"
    cp "$out/$deb" "$root_b/tmp/"
    in_root "$root_b" "set -e
        apt-get update -q >/dev/null
        # tools of the check itself, not of OpenTOP: a virtual display and a screenshot tool
        DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
            xvfb xauth imagemagick >/dev/null
        dpkg-query -W -f '\${Package}\n' | sort >/tmp/before
        DEBIAN_FRONTEND=noninteractive apt-get install -y -q /tmp/$deb >/tmp/install.log
        dpkg-query -W -f '\${Package}\n' | sort >/tmp/after
        comm -13 /tmp/before /tmp/after >/tmp/pulled
        echo \"   the package pulled in \$(wc -l </tmp/pulled) packages\"
        if grep -E -- '-dev(:|\$)' /tmp/pulled; then echo 'FAIL: -dev packages pulled in' >&2; exit 1; fi
        dpkg -L opentop >/tmp/files
        version=\$(dpkg-query -W -f '\${Version}' opentop)
        for p in opentop opentop-cli opentop-sim; do
            v=\$(\$p --version 2>&1)
            echo \"   \$p --version: \$v\"
            case \"\$v\" in *\"\${version%%-*}\"*) ;; *) echo \"FAIL: \$p --version\" >&2; exit 1;; esac
        done
        opentop-sim --help >/dev/null
        opentop-cli --sim dbu200@1,dcpid@7 scan | tee /tmp/scan
        grep -q '2 drives found' /tmp/scan || { echo 'FAIL: the scan did not find both drives' >&2; exit 1; }
        test -s /usr/share/man/man1/opentop-cli.1.gz
        # a user outside the dialout group is told the exact fix
        useradd -m checker
        mknod -m 660 /srv/ttyCHECK c 4 64 && chgrp dialout /srv/ttyCHECK
        su checker -c 'opentop-cli --port /srv/ttyCHECK scan' >/tmp/denied 2>&1 || true
        sed 's/^/   checker: /' /tmp/denied
        grep -q 'usermod -aG dialout' /tmp/denied || { echo 'FAIL: no dialout advice' >&2; exit 1; }
        rm -f /srv/ttyCHECK
        xvfb-run -a -s '-screen 0 1366x768x24' bash -c '
            opentop --sim dbu200@1,dcpid@7 --quit-after 8 & app=\$!
            sleep 5; import -window root /tmp/package-gui.png; wait \$app'
    " 2>&1 | tee "$out/package.log"
    not_blank "$root_b" /tmp/package-gui.png
    cp "$root_b/tmp/package-gui.png" "$out/package-screenshot.png"
    in_root "$root_b" "set -e
        DEBIAN_FRONTEND=noninteractive apt-get purge -y -q opentop >/dev/null
        left=0
        while read -r f; do
            if [ -e \"\$f\" ] && [ ! -d \"\$f\" ]; then echo \"left behind: \$f\"; left=1; fi
        done </tmp/files
        for d in /usr/share/doc/opentop /usr/share/opentop /etc/opentop; do
            if [ -e \"\$d\" ]; then echo \"left behind: \$d\"; left=1; fi
        done
        [ \$left = 0 ] && echo '   removed: nothing of the package is left'
        exit \$left" 2>&1 | tee -a "$out/package.log"
    end
fi

if want asan || want sanitize; then
    # the packages come from the README's command (setup.sh build is a no-op after "test")
    all=0
    want sanitize && all=1
    begin "sanitizers: bash scripts/sanitize.sh address (ASan+UBSan; whole suite: $all)"
    in_root "$root_a" "cd /src/main && bash scripts/setup.sh build >/dev/null &&
        OPENTOP_SANITIZE_ALL=$all bash scripts/sanitize.sh address" 2>&1 |
        tee "$out/sanitize-address.log"
    end
fi
if want tsan || want sanitize; then
    begin "sanitizers: bash scripts/sanitize.sh thread (transport, monitor and model under TSan)"
    in_root "$root_a" 'cd /src/main && bash scripts/sanitize.sh thread' 2>&1 |
        tee "$out/sanitize-thread.log"
    end
fi

if want fuzz; then
    begin "fuzzing: bash scripts/fuzz.sh ${OPENTOP_FUZZ_SECONDS:-60} (every harness, libFuzzer)"
    in_root "$root_a" "cd /src/main && bash scripts/setup.sh build >/dev/null &&
        bash scripts/fuzz.sh ${OPENTOP_FUZZ_SECONDS:-60}" 2>&1 | tee "$out/fuzz.log"
    end
fi

if want windows; then
    # The Linux programs of the README's build serve the bus the Windows ones are checked on.
    begin "Windows: bash scripts/check-windows.sh (cross build, Wine: TCP, COM port, GUI, installer)"
    in_root "$root_a" 'cd /src/main && bash scripts/setup.sh build >/dev/null &&
        OPENTOP_GUI_QUIT_AFTER=45 bash scripts/check-windows.sh' 2>&1 | tee "$out/windows.log"
    cp "$root_a/src/main/build-win/opentop-wine.png" "$out/" 2>/dev/null || true
    end
fi

report_phases | tee "$out/phases.txt"
exit 0
}
