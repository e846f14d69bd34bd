#!/bin/sh
# check-eacces.sh OPENTOP_CLI
# A serial port the user may not open: the error must give the exact fix
# ("sudo usermod -aG dialout $USER", then log out and in again). As root (who may open
# anything) the check runs as "nobody" through setpriv; without setpriv it is skipped (77).
set -eu
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
chmod 755 "$dir"
: >"$dir/ttyDENIED"
chmod 000 "$dir/ttyDENIED"
run() { "$cli" --port "$dir/ttyDENIED" scan --from 1 --to 1; }
if [ "$(id -u)" = 0 ]; then
    command -v setpriv >/dev/null || { echo "setpriv missing: skipped"; exit 77; }
    run() {
        setpriv --reuid=65534 --regid=65534 --clear-groups \
            "$cli" --port "$dir/ttyDENIED" scan --from 1 --to 1
    }
    # nobody must be able to run the program where it was built.
    setpriv --reuid=65534 --regid=65534 --clear-groups "$cli" --version >/dev/null 2>&1 ||
        { echo "nobody cannot run $cli: skipped"; exit 77; }
fi
status=0
output=$(run 2>&1) || status=$?
printf '%s\n' "$output"
[ "$status" = 1 ] || { echo "exit status $status, expected 1" >&2; exit 1; }
printf '%s\n' "$output" | grep -Fq 'sudo usermod -aG dialout $USER' ||
    { echo "no usermod command in the message" >&2; exit 1; }
printf '%s\n' "$output" | grep -Fq 'log out and in again' ||
    { echo "no \"log out and in again\" in the message" >&2; exit 1; }
