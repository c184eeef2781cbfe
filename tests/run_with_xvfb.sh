#!/bin/bash
# Runs a command under a private Xvfb. The server picks a free display number itself
# (-displayfd), so concurrent runs cannot race for one number as `xvfb-run -a` can (it probes
# lock files, then starts the server: two runs may pick the same number and one fails).
set -u
out=$(mktemp)
# -noreset: by default the server resets when its last client disconnects, and a test that
# opens a second window right after closing the first can land inside that reset.
Xvfb -displayfd 1 -noreset -nolisten tcp -screen 0 1024x768x24 >"$out" 2>/dev/null &
server=$!
for _ in $(seq 100); do
  [ -s "$out" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.1
done
display=$(head -n1 "$out")
rm -f "$out"
if [ -z "$display" ]; then
  echo "run_with_xvfb: Xvfb did not start" >&2
  kill "$server" 2>/dev/null
  exit 1
fi
DISPLAY=":$display" "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status
