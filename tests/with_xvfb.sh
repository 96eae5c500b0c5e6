#!/bin/sh
# Runs a command under a fresh Xvfb server of its own and exits with the command's own status.
#
#   tests/with_xvfb.sh [-s WxHxD] command [args...]
#
# The viewer's window tests use this instead of xvfb-run, which exits 5 whenever removing its own
# temporary folder fails and so hides the exit code the tests check. Xvfb picks a free display itself
# (-displayfd), listens on no TCP port, and is stopped however the command ends. Exit 125 means Xvfb
# could not start; the reason is printed.
set -u

screen=1920x1200x24
if [ "${1:-}" = "-s" ]; then
    screen=$2
    shift 2
fi
if [ $# -eq 0 ]; then
    echo "usage: with_xvfb.sh [-s WxHxD] command [args...]" >&2
    exit 2
fi
command -v Xvfb >/dev/null || { echo "with_xvfb: Xvfb not found (apt-get install xvfb)" >&2; exit 125; }

dir=$(mktemp -d "${TMPDIR:-/tmp}/with_xvfb.XXXXXX") || exit 125
Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp 3>"$dir/display" 2>"$dir/log" &
server=$!
stop() {
    kill "$server" 2>/dev/null
    wait "$server" 2>/dev/null
    rm -rf "$dir"
}

# Xvfb writes the display number and a newline once it accepts clients.
tries=0
until grep -q '^[0-9][0-9]*$' "$dir/display" 2>/dev/null; do
    if ! kill -0 "$server" 2>/dev/null || [ "$tries" -ge 400 ]; then
        echo "with_xvfb: Xvfb did not start:" >&2
        cat "$dir/log" >&2
        stop
        exit 125
    fi
    tries=$((tries + 1))
    sleep 0.05
done

DISPLAY=:$(cat "$dir/display") "$@"
status=$?
stop
exit "$status"
