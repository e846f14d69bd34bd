#!/bin/sh
# check-manpage.sh PROGRAM MANPAGE [cli]
# Fails when an option (--name) that "PROGRAM --help" prints is not in the man page MANPAGE
# (roff source). With "cli" (opentop-cli), also every command of the help's command list must
# have an entry (a line ".B command ..." or ".BI command ...") and every option of
# "PROGRAM help COMMAND" must be in the page.
set -eu
program=$1
page=$2
mode=${3:-}

# The page as plain text: \- is -, font changes go.
text=$(sed -e 's/\\-/-/g' -e 's/\\f[BIRP]//g' "$page")
help=$("$program" --help)
options=$(printf '%s\n' "$help" | grep -o -e '--[a-z][a-z0-9-]*' || true)
missing=
if [ "$mode" = cli ]; then
    commands=$(printf '%s\n' "$help" | sed -n '/^Commands:/,/^$/p' |
        sed -n 's/^  \([a-z][a-z-]*\).*/\1/p')
    [ -n "$commands" ] || { echo "no commands found in $program --help" >&2; exit 1; }
    for command in $commands; do
        if ! printf '%s\n' "$text" | grep -Eq "^\\.B[IR]? \"?$command( |\"|\$)"; then
            missing="$missing command:$command"
        fi
        options="$options
$("$program" help "$command" | grep -o -e '--[a-z][a-z0-9-]*' || true)"
    done
fi
[ -n "$options" ] || { echo "no options found in $program --help" >&2; exit 1; }
checked=0
for option in $(printf '%s\n' "$options" | sort -u); do
    checked=$((checked + 1))
    if ! printf '%s\n' "$text" | grep -Eq -e "$option([^a-z0-9-]|\$)"; then
        missing="$missing $option"
    fi
done
if [ -n "$missing" ]; then
    echo "$page lacks what $program --help shows:$missing" >&2
    exit 1
fi
echo "$page: all $checked options${commands:+ and the commands $(echo $commands)} documented"
