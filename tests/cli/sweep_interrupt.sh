#!/bin/bash
# Issue 12's sweep acceptance, interrupted for real: a 50-point sweep at 320x240 is killed with
# SIGTERM once its progress shows 5 points done, then rerun into the same folder; the rerun keeps
# what the killed run wrote and renders only the rest. Prints the wall time of both runs (not
# asserted: the machine is shared). usage: sweep_interrupt.sh DIPTYCH SCENE WORK_DIR
set -u
diptych=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
args=(sweep "$scene" --slot visibility=shadow_map:bias=slope,units=0
      --vary resolution=256,512,1024,2048,4096 --vary factor=0.05:20:log10 --size 320x240
      --out s50)
start=$(date +%s)
"$diptych" "${args[@]}" > first.out 2> first.err &
pid=$!
for _ in $(seq 1 1200); do  # up to 10 minutes for 5 points
  grep -q "sweep: 5/50" first.err && break
  kill -0 "$pid" 2> /dev/null || break
  sleep 0.5
done
kill -TERM "$pid" 2> /dev/null
wait "$pid"
killed=$?
grep -q "sweep: 5/50" first.err || { echo "no progress line 5/50:"; cat first.err; exit 1; }
[ "$killed" -ne 0 ] || { echo "the first run finished before it could be interrupted"; exit 1; }
kept=$(/usr/bin/python3 -c "import json; print(len(json.load(open('s50/results.json'))['points']))")
[ "$kept" -ge 5 ] && [ "$kept" -lt 50 ] || { echo "results.json after the kill has $kept points"; exit 1; }
"$diptych" "${args[@]}" > second.out 2> second.err || { cat second.err; exit 1; }
end=$(date +%s)
grep -q "50 points, $kept resumed" second.err || { echo "rerun did not resume $kept:"; tail -3 second.err; exit 1; }
[ "$(grep -c "^sweep: .*/50 {" second.err)" -eq $((50 - kept)) ] ||
  { echo "rerun rendered other than the $((50 - kept)) missing points"; exit 1; }
/usr/bin/python3 -c "
import json; r = json.load(open('s50/results.json'))
assert [p['index'] for p in r['points']] == list(range(50))" || exit 1
echo "killed after $kept points (exit $killed), resumed the other $((50 - kept)); both runs" \
     "$((end - start)) s wall clock on this machine"
